// Control flow of the Klartext machine: the run loop with its block budget, program end and
// return, LBL / CALL LBL (repeats and subprograms), CALL PGM, FN assignments and jumps, and the
// block dispatch; diagnostics sorted by file and line when the run ends.
#include "nc/heidenhain/Machine.h"

#include "nc/heidenhain/Parser.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <cmath>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

std::string upperName(std::string_view s)
{
    std::string out(s);
    for (char& c : out)
        c = upper(c);
    return out;
}

}  // namespace

bool BlockWords::hasXyz() const
{
    for (int i : {0, 1, 2, 9, 10, 11}) {
        if (axes[static_cast<std::size_t>(i)])
            return true;
    }
    return pr || pa || ipr || ipa;
}

double CycleDefinition::get(int n, double fallback) const
{
    return has(n) ? q[static_cast<std::size_t>(n - 200)] : fallback;
}

Machine::Machine(const InterpretOptions& options, CutterCompensation& sink, InterpretResult& result) :
    m_options(options),
    m_sink(sink),
    m_compensation(sink),
    m_result(result),
    m_rep(result.diagnostics, options.maxDiagnostics, result.diagnosticsDropped),
    m_five(options.machine)
{
    if (options.start)
        m_pos = *options.start;
    m_known = knownAtStart(options);
}

void Machine::report(Severity s, int line, int column, std::string message)
{
    m_rep.report(s, program().path, line, column, std::move(message));
}

void Machine::warnOnce(int key, const Block& b, const std::string& message)
{
    if (m_warned.test(static_cast<std::size_t>(key)))
        return;
    m_warned.set(static_cast<std::size_t>(key));
    report(Severity::Warning, b.line, b.column, message);
}

void Machine::source(int line) { m_sink.setSource(SourceRef{-1, -1, line, program().fileIndex}); }
void Machine::source(const Block& b) { source(b.line); }

std::optional<double> Machine::eval(int expr, bool quiet)
{
    const bool wasQuiet = m_rep.quiet;
    m_rep.quiet = quiet || wasQuiet;
    auto v = evaluate(program(), expr, m_params, m_rep, program().path);
    m_rep.quiet = wasQuiet;
    return v;
}

void Machine::run(std::string_view text)
{
    auto main = std::make_unique<Program>();
    main->path = m_options.fileName.empty() ? std::string("<input>") : m_options.fileName;
    main->fileIndex = 0;
    m_result.files.push_back(m_options.fileName);
    m_programs.push_back(std::move(main));
    parseProgram(*m_programs[0], text, m_rep);
    m_scale = m_programs[0]->inch ? 25.4 : 1.0;
    m_feedScale = m_programs[0]->inch ? 2.54 : 1.0;  // inch programs: F in 1/10 inch/min

    m_sink.begin();
    while (!m_stop) {
        const std::vector<Block>& blocks = program().blocks;
        if (m_pc >= blocks.size()) {
            if (m_programDepth > 0) {
                returnFromProgram();
                continue;
            }
            endProgram(true);
            break;
        }
        if (cancelRequested(m_options, m_result.blocksExecuted)) {
            m_result.cancelled = true;
            m_result.completed = false;
            break;
        }
        if (++m_result.blocksExecuted > m_options.maxBlocks) {
            const Block& b = blocks[m_pc];
            report(Severity::Error, b.line, 0,
                   "runaway program: more than " + std::to_string(m_options.maxBlocks) +
                       " blocks executed (a jump or repeat that never ends?)");
            m_result.completed = false;
            break;
        }
        m_jumped = false;
        const Block& block = blocks[m_pc];
        execute(block);
        if (m_options.onBlock)
            reportModal(block);
        if (!m_jumped)
            ++m_pc;
    }
    m_sink.end();
    sortDiagnostics();
}

// The state after a block in Klartext's words: absolute or incremental per coordinate word, MM or
// INCH of BEGIN PGM, the working plane of the TOOL CALL's axis, R0/RL/RR, F or FU, a datum shift.
void Machine::reportModal(const Block& b)
{
    BlockModal m;
    m.file = program().fileIndex;
    m.line = b.line;
    bool absolute = false, incremental = false;
    const Program& p = program();
    for (int i = 0; i < b.wordCount; ++i) {
        const Key key = p.words[static_cast<std::size_t>(b.firstWord + i)].key;
        absolute = absolute || (key >= Key::X && key <= Key::W) || key == Key::PR || key == Key::PA;
        incremental = incremental || (key >= Key::IX && key <= Key::IW) || key == Key::IPR || key == Key::IPA;
    }
    using D = BlockModal::Distance;
    m.distance = absolute && incremental ? D::Mixed
                 : absolute              ? D::Absolute
                 : incremental           ? D::Incremental
                                         : D::PerWord;
    m.distanceWord = absolute && incremental ? "X and IX" : absolute ? "X Y Z" : incremental ? "IX IY IZ" : "X or IX";
    m.inch = m_scale != 1.0;
    m.unitsWord = m.inch ? "INCH" : "MM";
    m.plane = m_toolAxis == 'X' ? 19 : m_toolAxis == 'Y' ? 18 : 17;
    m.planeWord = m_toolAxis == 'X' ? "TOOL CALL X" : m_toolAxis == 'Y' ? "TOOL CALL Y" : "TOOL CALL Z";
    m.compensation = m_comp;
    m.compensationWord = m_comp == CutterCompSide::Left ? "RL" : m_comp == CutterCompSide::Right ? "RR" : "R0";
    m.feedMode = m_feedMode;
    m.feedModeWord = m_feedMode == FeedMode::PerRevolution ? "FU" : "F";
    if (!(m_shift == Vec3{})) {
        const base::NumberFormat f{4, true, false, true};
        m.workOffset = "datum shift X" + f.format(m_shift.x / m_scale) + " Y" + f.format(m_shift.y / m_scale) + " Z" +
                       f.format(m_shift.z / m_scale);
    }
    m_options.onBlock(m);
}

// Parse-time and run-time diagnostics in the order of the files and their lines, as an editor
// lists them (stable: the order of one line's diagnostics stays as found).
void Machine::sortDiagnostics()
{
    auto fileOrder = [this](const std::string& file) {
        for (std::size_t i = 0; i < m_programs.size(); ++i) {
            if (m_programs[i]->path == file)
                return static_cast<int>(i);
        }
        return static_cast<int>(m_programs.size());
    };
    std::stable_sort(m_result.diagnostics.begin(), m_result.diagnostics.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) {
                         const int fa = fileOrder(a.file), fb = fileOrder(b.file);
                         return fa != fb ? fa < fb : a.line < b.line;
                     });
}

void Machine::endProgram(bool completed)
{
    m_stop = true;
    m_result.completed = completed;
}

void Machine::returnFromProgram()
{
    while (!m_frames.empty() && !m_frames.back().isProgram)
        m_frames.pop_back();
    if (m_frames.empty()) {
        endProgram(true);
        return;
    }
    const Frame f = m_frames.back();
    m_frames.pop_back();
    m_prog = f.program;
    m_pc = f.returnPc;
    m_jumped = true;
    --m_programDepth;
}

void Machine::execute(const Block& b)
{
    source(b);
    if (!b.comment.empty() && b.kind != BlockKind::Invalid)
        m_sink.comment(Comment{std::string(b.comment)});
    switch (b.kind) {
    case BlockKind::Empty:
    case BlockKind::Comment:
    case BlockKind::BlkForm:
    case BlockKind::Skipped:
    case BlockKind::Invalid:
    case BlockKind::LineVector:
        return;
    case BlockKind::Elision:
        m_programmed = kNoAxes;
        m_tangents = {};
        return;
    case BlockKind::BeginPgm:
        if (m_pc != 0)
            report(Severity::Warning, b.line, b.column, "BEGIN PGM is not the first block");
        return;
    case BlockKind::EndPgm:
        if (m_programDepth > 0)
            return returnFromProgram();
        return endProgram(true);
    case BlockKind::ToolDef:
        return toolDef(b);
    case BlockKind::ToolCall:
        return toolCall(b);
    case BlockKind::Line:
    case BlockKind::LinePolar:
    case BlockKind::Circle:
    case BlockKind::CircleRadius:
    case BlockKind::CircleTangent:
    case BlockKind::CirclePolar:
    case BlockKind::Approach:
    case BlockKind::MOnly:
    case BlockKind::Stop:
        return motionBlock(b);
    case BlockKind::CircleCenter:
        return circleCenter(b);
    case BlockKind::Round:
    case BlockKind::Chamfer:
        return corner(b);
    case BlockKind::Label:
        return label(b);
    case BlockKind::CallLabel:
        return callLabel(b);
    case BlockKind::CallPgm:
        return callProgram(b);
    case BlockKind::FnAssign:
        return fnAssign(b);
    case BlockKind::FnJump:
        return fnJump(b);
    case BlockKind::FnError: {
        const auto v = b.exprA >= 0 ? eval(b.exprA) : std::optional<double>(0);
        const long long number = v && std::abs(*v) < 1e9 ? static_cast<long long>(*v) : 0;
        report(Severity::Error, b.line, b.column,
               "FN 14: ERROR = " + std::to_string(number) + ": the control stops here");
        return endProgram(false);
    }
    case BlockKind::CycleDef:
        return cycleDef(b);
    case BlockKind::CycleCall:
    case BlockKind::CycleCallPos:
        return cycleCall(b);
    case BlockKind::Plane:
        return planeFunction(b);
    case BlockKind::Function:
        if (equalsIgnoreCase(b.name, "TCPM")) {
            tcpmFunction(b);
        } else {
            report(Severity::Warning, b.line, b.column, "FUNCTION " + std::string(b.name) + " is not traced");
        }
        return;
    }
}

std::optional<std::size_t> Machine::findLabel(std::string_view ref, bool isName)
{
    const Program& p = program();
    const auto it = p.labels.find(labelKey(ref, isName));
    if (it == p.labels.end())
        return std::nullopt;
    return static_cast<std::size_t>(it->second);
}

void Machine::label(const Block& b)
{
    if (b.flag || labelKey(b.name, false) != "N0")
        return;
    // LBL 0: the end of a subprogram called with CALL LBL.
    if (m_frames.empty() || m_frames.back().isProgram || m_frames.back().program != m_prog)
        return;
    const Frame f = m_frames.back();
    m_frames.pop_back();
    m_pc = f.returnPc;
    m_jumped = true;
}

void Machine::callLabel(const Block& b)
{
    const auto target = findLabel(b.labelRef, b.labelRefIsName);
    if (!target) {
        report(Severity::Error, b.line, b.column, "undefined label " + std::string(b.labelRef));
        return;
    }
    std::int64_t rep = -1;
    if (b.wordCount > 0)
        rep = program().words[static_cast<std::size_t>(b.firstWord)].param;
    if (!m_frames.empty() && !m_frames.back().isProgram && m_frames.back().program == m_prog &&
        m_frames.back().callPc == m_pc) {
        // The repeated section came back to its CALL: once more, or carry on after it.
        Frame& f = m_frames.back();
        if (--f.remaining > 0) {
            m_pc = f.target + 1;
            m_jumped = true;
        } else {
            m_frames.pop_back();
        }
        return;
    }
    if (rep == 0)
        return;
    if (m_frames.size() >= kMaxLabelNesting) {
        report(Severity::Error, b.line, b.column,
               "CALL LBL nested deeper than " + std::to_string(kMaxLabelNesting) + " levels (recursive call?)");
        return;
    }
    m_frames.push_back(Frame{m_prog, m_pc, m_pc + 1, *target, rep < 0 ? 1 : rep, false});
    m_pc = *target + 1;
    m_jumped = true;
}

void Machine::callProgram(const Block& b)
{
    if (m_programDepth >= kMaxProgramNesting) {
        report(Severity::Error, b.line, b.column,
               "CALL PGM nested deeper than " + std::to_string(kMaxProgramNesting) + " levels (recursive call?)");
        return;
    }
    const std::string key = upperName(b.name);
    int index = -1;
    std::optional<ProgramSource> found;
    if (auto it = m_programByName.find(key); it != m_programByName.end()) {
        index = it->second;
    } else {
        if (m_options.resolveProgram) {
            found = m_options.resolveProgram(b.name);
            if (!found) {
                // TNC:\DIR\NAME.H: try the bare file name.
                const std::size_t cut = b.name.find_last_of("\\/:");
                if (cut != std::string_view::npos && cut + 1 < b.name.size())
                    found = m_options.resolveProgram(b.name.substr(cut + 1));
            }
        }
        if (!found) {
            report(Severity::Error, b.line, b.column, "undefined program " + std::string(b.name));
            return;
        }
        // The same file under another spelling (TNC:\DIR\SUB and SUB) is the same program.
        for (std::size_t i = 1; i < m_programs.size(); ++i) {
            if (m_programs[i]->path == found->path)
                index = static_cast<int>(i);
        }
    }
    if (index < 0 && m_programs.size() >= kMaxPrograms) {
        report(Severity::Error, b.line, b.column,
               "more than " + std::to_string(kMaxPrograms) + " different programs called: " + std::string(b.name) +
                   " is not loaded");
        return;
    }
    if (index < 0) {
        auto called = std::make_unique<Program>();
        called->text = std::move(found->text);
        called->path = found->path;
        called->fileIndex = static_cast<int>(m_result.files.size());
        m_result.files.push_back(found->path);
        parseProgram(*called, called->text, m_rep);
        index = static_cast<int>(m_programs.size());
        m_programs.push_back(std::move(called));
    }
    m_programByName.emplace(key, index);
    source(b.line);  // the calling block, so the callee's records link back to it
    m_frames.push_back(Frame{m_prog, m_pc, m_pc + 1, 0, 0, true});
    ++m_programDepth;
    m_prog = index;
    m_pc = 0;
    m_jumped = true;
}

void Machine::fnAssign(const Block& b)
{
    const auto v = eval(b.exprA);
    if (!v)
        return;
    m_params.at(static_cast<ExprOp>(b.a), b.b) = *v;
}

void Machine::fnJump(const Block& b)
{
    const auto a = eval(b.exprA);
    const auto c = a ? eval(b.exprB) : std::nullopt;
    if (!a || !c)
        return;
    const double tolerance = 1e-9 * std::max({1.0, std::abs(*a), std::abs(*c)});
    bool jump = false;
    switch (static_cast<Condition>(b.b)) {
    case Condition::Equal:
        jump = std::abs(*a - *c) <= tolerance;
        break;
    case Condition::NotEqual:
        jump = std::abs(*a - *c) > tolerance;
        break;
    case Condition::Greater:
        jump = *a > *c + tolerance;
        break;
    case Condition::Less:
        jump = *a < *c - tolerance;
        break;
    }
    if (!jump)
        return;
    const auto target = findLabel(b.labelRef, b.labelRefIsName);
    if (!target) {
        report(Severity::Error, b.line, b.column, "undefined label " + std::string(b.labelRef));
        return;
    }
    m_pc = *target + 1;
    m_jumped = true;
}

}  // namespace camwb::nc::heidenhain
