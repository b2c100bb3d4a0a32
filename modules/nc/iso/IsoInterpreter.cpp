// Entry of the plain ISO (LinuxCNC / Fanuc style RS274NGC) interpreter and its line loop.
//
// Choices, following LinuxCNC 2.9 where it has one:
// - Block delete ('/') is read as with the switch off: the block runs, as rs274 does by default.
// - Canned cycles are Cycle records with top = retract = R: LinuxCNC counts G83/G73 pecks from R.
//   clearance is the Z before the first hole, returnToClearance means G98.
// - M6 stops a running spindle; M2/M30 stop spindle and coolant, cancel compensation and reset
//   G54 and G94, as LinuxCNC's program end does.
// - Other controls' programs read with warnings, not errors: G70/G71 as inch/mm, G0/G1 kept
//   through G80 (Fanuc), O program numbers, "..." elisions, unknown G/M codes, A/B/C/U/V/W and
//   M128 (five-axis: traced once the machine model exists).
// - G53 and G28/G30 (after G28's intermediate point) go to machine coordinates the trace cannot
//   place: the axes they move become unknown (an UnknownAxes record), with a warning. G10/G92 and
//   G96 are accepted with a warning and do not move the trace.
// - Cutter compensation as LinuxCNC 2.9's interpreter makes it (interp_convert.cc,
//   convert_straight_comp1/2 and convert_arc_comp1/2, checked against rs274 in tests/external):
//   the radius of G41/G42 D<tool> from the tool table (without D: the tool in the spindle), of
//   G41.1/G42.1 D<diameter>; the entry move ends r beside its end point square to itself, an
//   entry arc is LinuxCNC's own; outside corners get an arc about the corner (a rapid goes
//   straight), inside corners are trimmed to the offsets' intersection; turns under 0.05 rad
//   (TOLERANCE_CONCAVE_CORNER) are tangent; at a reversal next to an arc the tool runs outside of,
//   the tool stays on the arc's side ("h" and "m" shapes); after G40 the next move goes straight
//   from the compensated point. An entry no longer than r, a move in Z alone as the entry and a
//   gouge are errors, as rs274 refuses them; a tool missing from the table is a warning and the
//   programmed path (rs274 stops).
#include "nc/detail/Dialects.h"
#include "nc/iso/IsoProgram.h"

#include <cstring>

namespace camwb::nc::iso {

Program::Program(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink,
                 InterpretResult& result) :
    m_texts{text},
    m_options(options),
    m_sink(m_compensation),
    m_result(result),
    m_reporter(result.diagnostics, result.diagnosticsDropped,
               options.fileName.empty() ? std::string("<input>") : options.fileName, options.maxDiagnostics),
    m_compensation(sink, CompensationRules::linuxCnc(), result, options.maxDiagnostics),
    m_scanner(m_parameters, m_reporter),
    m_machine(m_compensation, options.toolTable, m_reporter, m_parameters, options.arcRadiusToleranceMm)
{
    m_machine.startAt(options.start, knownAtStart(options));
}

bool Program::readLine(std::string_view& line)
{
    const std::string_view text = m_texts[static_cast<std::size_t>(m_next.file)];
    if (m_next.offset >= text.size())
        return false;
    const char* start = text.data() + m_next.offset;
    const std::size_t left = text.size() - m_next.offset;
    const void* newline = std::memchr(start, '\n', left);
    const std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - start) : left;
    line = std::string_view(start, length);
    if (m_next.file != m_current.file)  // into or back from a subroutine file
        m_reporter.setFile(m_result.files[static_cast<std::size_t>(m_next.file)]);
    m_current = m_next;
    m_lineNumber = m_next.line;
    m_next.offset += length + (newline ? 1 : 0);
    ++m_next.line;
    return true;
}

bool Program::countBlock()
{
    if (cancelRequested(m_options, m_result.blocksExecuted)) {
        m_result.cancelled = true;
        m_fatal = true;
        return false;
    }
    if (++m_result.blocksExecuted <= m_options.maxBlocks)
        return true;
    m_reporter.error(m_lineNumber, 0,
                     "runaway program: more than " + std::to_string(m_options.maxBlocks) +
                         " blocks executed (an endless loop or recursion?)");
    m_fatal = true;
    return false;
}

void Program::applyAssignments()
{
    for (int i = 0; i < m_block.assignmentCount; ++i) {
        const Assignment& a = m_block.assignments[static_cast<std::size_t>(i)];
        if (a.index >= 0)
            m_parameters.setNumbered(a.index, a.value);
        else
            m_parameters.setNamed(a.name, a.value);
    }
}

void Program::run()
{
    m_sink.begin();
    std::string_view line;
    bool first = true;
    bool percentOpened = false;
    while (!m_fatal && !m_programEnd && readLine(line)) {
        // '%' lines delimit the program: the first opens it, the next one ends it.
        std::size_t i = 0;
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
            ++i;
        if (i == line.size())
            continue;
        if (line[i] == '%' && m_current.file != 0)
            continue;  // a subroutine file's own delimiters
        if (line[i] == '%') {
            if (!first || percentOpened) {
                m_programEnd = true;
                break;
            }
            percentOpened = true;
            first = false;
            continue;
        }
        first = false;
        if (line[i] == '.' && line.find_first_not_of(". \t\r", i) == std::string_view::npos) {
            // Listings in documents cut programs with "...": nothing to run, but nothing there either.
            m_reporter.warning(m_lineNumber, static_cast<int>(i) + 1, "elided lines ('...') skipped");
            continue;
        }
        if (!countBlock())
            break;
        m_scanner.scan(line, m_lineNumber, m_block);
        if (m_block.error)
            continue;
        if (m_block.oKeyword != OKeyword::None) {
            if (oWord() == Flow::Stop)
                break;
            continue;
        }
        applyAssignments();
        if (m_machine.execute(m_block, m_lineNumber, m_current.file) == BlockOutcome::ProgramEnd)
            m_programEnd = true;
        if (m_options.onBlock)
            m_machine.reportModal(m_options.onBlock);
    }
    if (!m_fatal && !m_programEnd)
        m_reporter.warning(m_lineNumber, 0, "the program ends without M2, M30 or a closing '%'");
    if (!m_fatal && !m_calls.empty() && !m_programEnd)
        m_reporter.error(m_lineNumber, 0, "the program ends inside a subroutine call");
    m_result.completed = !m_fatal;
    m_sink.end();
}

}  // namespace camwb::nc::iso

namespace camwb::nc::detail {

InterpretResult interpretIso(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    result.files.push_back(options.fileName.empty() ? std::string("<input>") : options.fileName);
    iso::Program program(text, options, sink, result);
    program.run();
    return result;
}

}  // namespace camwb::nc::detail
