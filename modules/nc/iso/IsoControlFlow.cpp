// O-word control flow (LinuxCNC "O Codes"): sub/endsub/call/return, while/endwhile, do/while,
// if/elseif/else/endif, repeat/endrepeat, break/continue. Blocks match by label, as LinuxCNC
// requires (a loop and its end share the O number), so skipping forward only looks for the
// label and keyword of each line, without reading the rest.
#include "nc/iso/IsoProgram.h"

namespace camwb::nc::iso {

namespace {

constexpr std::size_t kMaxCallDepth = 100;
constexpr std::size_t kMaxControlDepth = 1000;
constexpr std::size_t kMaxFiles = 100;  // subroutine files one program may load
constexpr double kArgumentLimit = 1e9;  // repeat counts

}  // namespace

void Program::oError(std::string message) { m_reporter.error(m_lineNumber, m_block.oColumn, std::move(message)); }

Program::ControlFrame* Program::innermost(const std::string& label, std::initializer_list<OKeyword> kinds)
{
    const std::size_t floor = m_calls.empty() ? 0 : static_cast<std::size_t>(m_calls.back().controlDepth);
    for (std::size_t i = m_control.size(); i > floor; --i) {
        ControlFrame& f = m_control[i - 1];
        if (f.label != label)
            continue;
        for (OKeyword k : kinds) {
            if (f.kind == k) {
                m_control.resize(i);  // frames opened inside it are left with it
                return &m_control.back();
            }
        }
    }
    return nullptr;
}

bool Program::skipTo(const std::string& label, std::initializer_list<OKeyword> keywords, bool pastIt, OKeyword* found)
{
    const int from = m_lineNumber;
    std::string_view line;
    for (;;) {
        const Position before = m_next;
        if (!readLine(line))
            break;
        if (!countBlock())
            return false;
        OKeyword keyword = OKeyword::None;
        if (!LineScanner::peekOWord(line, m_labelScratch, keyword) || m_labelScratch != label)
            continue;
        for (OKeyword k : keywords) {
            if (keyword == k) {
                if (found)
                    *found = keyword;
                if (!pastIt)
                    m_next = before;
                return true;
            }
        }
    }
    m_lineNumber = from;
    oError("no matching end for o" + label + " before the end of the program");
    m_fatal = true;
    return false;
}

void Program::scanSubroutines(int file)
{
    const std::string_view text = m_texts[static_cast<std::size_t>(file)];
    Position p{0, 1, file};
    std::string found;
    while (p.offset < text.size()) {
        const std::size_t end = text.find('\n', p.offset);
        const std::size_t stop = end == std::string_view::npos ? text.size() : end;
        OKeyword keyword = OKeyword::None;
        if (LineScanner::peekOWord(text.substr(p.offset, stop - p.offset), found, keyword) && keyword == OKeyword::Sub)
            m_subroutines.emplace(found, Position{stop + 1, p.line + 1, file});
        p = Position{stop + 1, p.line + 1, file};
    }
}

// LinuxCNC looks for o<name> in <name>.ngc on its subroutine path; here the resolver of the
// options (by default the program's folder) finds the file.
bool Program::loadSubroutineFile(const std::string& label)
{
    if (!m_options.resolveProgram || m_triedFiles.count(label) || m_texts.size() >= kMaxFiles ||
        label.find_first_not_of("0123456789") == std::string::npos)
        return false;
    m_triedFiles.emplace(label, true);
    std::optional<ProgramSource> source = m_options.resolveProgram(label);
    if (!source)
        return false;
    m_loaded.push_back(std::move(source->text));
    m_texts.push_back(m_loaded.back());
    m_result.files.push_back(source->path);
    scanSubroutines(static_cast<int>(m_texts.size()) - 1);
    return true;
}

bool Program::findSubroutine(const std::string& label, Position& body)
{
    auto it = m_subroutines.find(label);
    if (it == m_subroutines.end() && !m_scannedSubroutines) {
        // Called before its definition was read: look through the whole program once.
        m_scannedSubroutines = true;
        scanSubroutines(0);
        it = m_subroutines.find(label);
    }
    if (it == m_subroutines.end() && loadSubroutineFile(label))
        it = m_subroutines.find(label);
    if (it == m_subroutines.end())
        return false;
    body = it->second;
    return true;
}

void Program::returnFromCall()
{
    const CallFrame frame = m_calls.back();
    m_calls.pop_back();
    m_control.resize(static_cast<std::size_t>(frame.controlDepth));
    m_parameters.popFrame();
    m_next = frame.returnTo;
}

int Program::oCondition(const char* what)
{
    if (m_block.oArguments.size() != 1) {
        oError("o" + m_block.oLabel + " " + what + " needs one [condition]");
        return -1;
    }
    return m_block.oArguments[0] != 0 ? 1 : 0;
}

Program::Flow Program::skipped(bool found) { return found ? Flow::Next : Flow::Stop; }

Program::Flow Program::oWord()
{
    if (m_control.size() >= kMaxControlDepth) {
        oError("control blocks nested too deeply");
        m_fatal = true;
        return Flow::Stop;
    }
    switch (m_block.oKeyword) {
    case OKeyword::Sub:
        m_subroutines.insert_or_assign(m_block.oLabel, m_next);
        return skipped(skipTo(m_block.oLabel, {OKeyword::EndSub}, true));
    case OKeyword::EndSub:
    case OKeyword::Return:
        return oReturn();
    case OKeyword::Call:
        return oCall();
    case OKeyword::Do:
        m_control.push_back(ControlFrame{OKeyword::Do, m_block.oLabel, m_next, 0, false});
        return Flow::Next;
    case OKeyword::While:
        return oWhile();
    case OKeyword::EndWhile:
        return oEndWhile();
    case OKeyword::Repeat:
        return oRepeat();
    case OKeyword::EndRepeat:
        return oEndRepeat();
    case OKeyword::If:
        return oIf();
    case OKeyword::ElseIf:
    case OKeyword::Else:
        return oElse();
    case OKeyword::EndIf:
        if (!innermost(m_block.oLabel, {OKeyword::If}))
            oError("o" + m_block.oLabel + " endif without if");
        else
            m_control.pop_back();
        return Flow::Next;
    case OKeyword::Break:
    case OKeyword::Continue:
        return oBreakOrContinue();
    case OKeyword::None:
        break;
    }
    return Flow::Next;
}

Program::Flow Program::oReturn()
{
    if (m_calls.empty()) {
        oError("o" + m_block.oLabel + (m_block.oKeyword == OKeyword::Return ? " return" : " endsub") +
               " outside a subroutine call");
        return Flow::Next;
    }
    if (!m_block.oArguments.empty())
        m_parameters.setNamed("_value", m_block.oArguments[0]);
    returnFromCall();
    return Flow::Next;
}

Program::Flow Program::oCall()
{
    const std::string& label = m_block.oLabel;
    const auto& args = m_block.oArguments;
    Position body;
    if (!findSubroutine(label, body)) {
        oError("subroutine o" + label + " is not defined");
        return Flow::Next;
    }
    if (m_calls.size() >= kMaxCallDepth) {
        oError("subroutine calls nested more than 100 deep (endless recursion?)");
        m_fatal = true;
        return Flow::Stop;
    }
    m_machine.announce(m_lineNumber, m_current.file);
    m_calls.push_back(CallFrame{m_next, static_cast<int>(m_control.size())});
    m_parameters.pushFrame(args.data(), static_cast<int>(std::min<std::size_t>(args.size(), kCallArguments)));
    m_next = body;
    return Flow::Next;
}

// `while` opens a loop, or closes a do ... while.
Program::Flow Program::oWhile()
{
    const std::string& label = m_block.oLabel;
    const int c = oCondition("while");
    if (c < 0)
        return Flow::Next;
    if (!m_control.empty() && m_control.back().kind == OKeyword::Do && m_control.back().label == label) {
        if (c)
            m_next = m_control.back().start;  // do ... while: back to the body
        else
            m_control.pop_back();
        return Flow::Next;
    }
    // Coming back from endwhile, this line is the innermost loop's own start.
    const bool again = !m_control.empty() && m_control.back().kind == OKeyword::While &&
                       m_control.back().label == label && m_control.back().start.line == m_current.line &&
                       m_control.back().start.file == m_current.file;
    if (c) {
        if (!again)
            m_control.push_back(ControlFrame{OKeyword::While, label, m_current, 0, false});
        return Flow::Next;
    }
    if (again)
        m_control.pop_back();
    return skipped(skipTo(label, {OKeyword::EndWhile}, true));
}

Program::Flow Program::oEndWhile()
{
    ControlFrame* f = innermost(m_block.oLabel, {OKeyword::While});
    if (!f) {
        oError("o" + m_block.oLabel + " endwhile without while");
        return Flow::Next;
    }
    m_next = f->start;
    return Flow::Next;
}

Program::Flow Program::oRepeat()
{
    const std::string& label = m_block.oLabel;
    const auto& args = m_block.oArguments;
    if (args.size() != 1 || !(args[0] < kArgumentLimit)) {
        oError("o" + label + " repeat needs one [count]");
        return Flow::Next;
    }
    const long long count = args[0] > 0 ? static_cast<long long>(args[0]) : 0;
    if (count <= 0)
        return skipped(skipTo(label, {OKeyword::EndRepeat}, true));
    m_control.push_back(ControlFrame{OKeyword::Repeat, label, m_next, count, false});
    return Flow::Next;
}

Program::Flow Program::oEndRepeat()
{
    ControlFrame* f = innermost(m_block.oLabel, {OKeyword::Repeat});
    if (!f) {
        oError("o" + m_block.oLabel + " endrepeat without repeat");
        return Flow::Next;
    }
    if (--f->remaining > 0)
        m_next = f->start;
    else
        m_control.pop_back();
    return Flow::Next;
}

Program::Flow Program::oIf()
{
    const std::string& label = m_block.oLabel;
    const int c = oCondition("if");
    if (c < 0)
        return Flow::Next;
    m_control.push_back(ControlFrame{OKeyword::If, label, m_next, 0, c == 1});
    if (c)
        return Flow::Next;
    return skipped(skipTo(label, {OKeyword::ElseIf, OKeyword::Else, OKeyword::EndIf}, false));
}

// elseif and else: skip to endif after a branch was taken, else test (elseif) or take (else).
Program::Flow Program::oElse()
{
    const std::string& label = m_block.oLabel;
    ControlFrame* f = innermost(label, {OKeyword::If});
    if (!f) {
        oError("o" + label + (m_block.oKeyword == OKeyword::Else ? " else" : " elseif") + " without if");
        return Flow::Next;
    }
    if (f->taken) {
        m_control.pop_back();
        return skipped(skipTo(label, {OKeyword::EndIf}, true));
    }
    if (m_block.oKeyword == OKeyword::Else) {
        f->taken = true;
        return Flow::Next;
    }
    const int c = oCondition("elseif");
    if (c < 0)
        return Flow::Next;
    if (c) {
        f->taken = true;
        return Flow::Next;
    }
    return skipped(skipTo(label, {OKeyword::ElseIf, OKeyword::Else, OKeyword::EndIf}, false));
}

Program::Flow Program::oBreakOrContinue()
{
    const std::string& label = m_block.oLabel;
    ControlFrame* f = innermost(label, {OKeyword::While, OKeyword::Do, OKeyword::Repeat});
    if (!f) {
        oError("o" + label + (m_block.oKeyword == OKeyword::Break ? " break" : " continue") + " outside a loop");
        return Flow::Next;
    }
    const OKeyword kind = f->kind;
    if (m_block.oKeyword == OKeyword::Continue) {
        if (kind == OKeyword::While) {
            m_next = f->start;
            return Flow::Next;
        }
        if (kind == OKeyword::Repeat) {
            if (--f->remaining > 0) {
                m_next = f->start;
                return Flow::Next;
            }
            m_control.pop_back();
            return skipped(skipTo(label, {OKeyword::EndRepeat}, true));
        }
        return skipped(skipTo(label, {OKeyword::While}, false));  // do: test the condition
    }
    m_control.pop_back();
    const OKeyword end = kind == OKeyword::While    ? OKeyword::EndWhile
                         : kind == OKeyword::Repeat ? OKeyword::EndRepeat
                                                    : OKeyword::While;
    return skipped(skipTo(label, {end}, true));
}

}  // namespace camwb::nc::iso
