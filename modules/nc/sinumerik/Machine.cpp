// The run loop: a program counter over the parsed blocks of the program on top of the call stack,
// control flow by the jump targets the parser matched, subprogram calls through the resolver
// (R parameters global, DEF variables per call), and the runaway guard of options.maxBlocks.
#include "nc/sinumerik/Machine.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>

namespace camwb::nc::sinumerik {

namespace {

constexpr std::size_t kMaxCallDepth = 16;

const char* loopName(BlockKind kind)
{
    switch (kind) {
    case BlockKind::While:
        return "WHILE";
    case BlockKind::Repeat:
        return "REPEAT";
    case BlockKind::For:
        return "FOR";
    case BlockKind::Loop:
        return "LOOP";
    default:
        return "GOTOB";
    }
}

std::string stemUpper(const std::string& path) { return upper(std::filesystem::path(path).stem().string()); }

}  // namespace

void Machine::diag(Severity severity, const Program& p, Pos pos, const std::string& message)
{
    if (m_result.diagnostics.size() >= m_options.maxDiagnostics) {
        ++m_result.diagnosticsDropped;
        return;
    }
    const std::uint64_t key = std::hash<std::string>{}(message) ^
                              (static_cast<std::uint64_t>(pos.line) * 0x9E3779B97F4A7C15ull) ^
                              (static_cast<std::uint64_t>(pos.column) << 48) ^
                              (static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(&p)) << 7);
    if (!m_reported.insert(key).second)
        return;
    m_result.diagnostics.push_back({severity, p.path, pos.line, pos.column, message});
}

void Machine::addParseDiagnostics(const Program& p)
{
    for (const Diagnostic& d : p.diagnostics) {
        if (m_result.diagnostics.size() < m_options.maxDiagnostics)
            m_result.diagnostics.push_back(d);
        else
            ++m_result.diagnosticsDropped;
    }
    m_result.diagnosticsDropped += p.diagnosticsDropped;
}

void Machine::run(std::string_view mainText)
{
    const std::string path = m_options.fileName;
    m_programs.push_back(std::make_unique<Program>(parseProgram(path, std::string(mainText))));
    m_result.files.push_back(path);
    m_loopCounts.emplace_back();
    const Program& main = *m_programs.front();
    addParseDiagnostics(main);
    if (!path.empty())
        checkProcName(main, stemUpper(path));
    // 828D milling: T preselects, M6 changes. Turning (no M6 anywhere): T changes the tool.
    m_toolChangeOnM6 = main.hasM6;
    m_stack.push_back(Frame{});
    m_locals.assign(static_cast<std::size_t>(main.localSlots), 0.0);
    m_sink.begin();
    runLoop();
    m_sink.end();
}

void Machine::checkProcName(const Program& p, std::string_view expected)
{
    if (p.procName.empty() || expected.empty() || p.procName == expected)
        return;
    error(p, p.procPos,
          "PROC " + p.procName + " does not match the program name " + std::string(expected) +
              ": the control finds a subprogram by its file name, which the PROC must repeat");
}

void Machine::runLoop()
{
    while (!m_stack.empty() && !m_stopped) {
        Frame& frame = m_stack.back();
        const Program& p = *m_programs[static_cast<std::size_t>(frame.program)];
        if (frame.pc >= static_cast<int>(p.blocks.size())) {
            if (!returnFromCall())
                m_result.completed = true;
            continue;
        }
        if (cancelRequested(m_options, m_result.blocksExecuted)) {
            m_result.cancelled = true;
            m_stopped = true;
            break;
        }
        if (++m_result.blocksExecuted > m_options.maxBlocks) {
            reportRunaway();
            m_stopped = true;
            break;
        }
        const bool goOn = step();
        if (m_options.onBlock)
            reportModal();
        if (!goOn)
            break;
    }
}

void Machine::reportModal()
{
    BlockModal m;
    m.file = m_currentFile;
    m.line = m_currentLine;
    m.distance = m_modal.incremental ? BlockModal::Distance::Incremental : BlockModal::Distance::Absolute;
    m.distanceWord = m_modal.incremental ? "G91" : "G90";
    m.inch = m_modal.inch;
    m.unitsWord = m_modal.unitsCode == 70    ? "G70"
                  : m_modal.unitsCode == 700 ? "G700"
                  : m_modal.unitsCode == 710 ? "G710"
                                             : "G71";
    m.plane = m_modal.plane;
    m.planeWord = m_modal.plane == 18 ? "G18" : m_modal.plane == 19 ? "G19" : "G17";
    m.compensation = m_modal.comp;
    m.compensationWord = m_modal.comp == toolpath::CutterCompSide::Left    ? "G41"
                         : m_modal.comp == toolpath::CutterCompSide::Right ? "G42"
                                                                           : "G40";
    m.feedMode = m_modal.feedMode;
    m.feedModeWord = m_modal.feedMode == toolpath::FeedMode::InverseTime     ? "G93"
                     : m_modal.feedMode == toolpath::FeedMode::PerRevolution ? "G95"
                                                                             : "G94";
    const int offset = m_modal.workOffset;
    if (offset == 0)
        m.workOffset = "G500";
    else if (offset >= 1 && offset <= 4)
        m.workOffset = "G" + std::to_string(53 + offset);
    else if (offset >= 5)
        m.workOffset = "G" + std::to_string(500 + offset);
    m_options.onBlock(m);
}

void Machine::setSource(int line) { m_sink.setSource(toolpath::SourceRef{-1, -1, line, m_currentFile}); }

void Machine::jumpBack(int target)
{
    Frame& frame = m_stack.back();
    auto& counts = m_loopCounts[static_cast<std::size_t>(frame.program)];
    if (counts.empty())
        counts.assign(m_programs[static_cast<std::size_t>(frame.program)]->blocks.size(), 0);
    if (counts[static_cast<std::size_t>(target)] < 0xFFFFFFFFu)
        ++counts[static_cast<std::size_t>(target)];
    frame.pc = target;
}

void Machine::reportRunaway()
{
    // The loop that turned most often since it was last entered from above is the one that hangs.
    int bestProgram = m_stack.empty() ? 0 : m_stack.back().program;
    int bestBlock = -1;
    std::uint32_t best = 0;
    for (std::size_t prog = 0; prog < m_loopCounts.size(); ++prog) {
        const auto& counts = m_loopCounts[prog];
        for (std::size_t i = 0; i < counts.size(); ++i) {
            if (counts[i] > best) {
                best = counts[i];
                bestProgram = static_cast<int>(prog);
                bestBlock = static_cast<int>(i);
            }
        }
    }
    const Program& p = *m_programs[static_cast<std::size_t>(bestProgram)];
    const std::string limit = std::to_string(m_options.maxBlocks);
    if (bestBlock < 0) {
        error(p, {m_currentLine, 0}, "runaway program: more than " + limit + " blocks executed");
        return;
    }
    const Block& b = p.blocks[static_cast<std::size_t>(bestBlock)];
    // Back jumps land on the loop's head (WHILE, FOR) or just after it (REPEAT, LOOP).
    int head = bestBlock;
    BlockKind kind = b.kind;
    if (bestBlock > 0 && (b.kind != BlockKind::While && b.kind != BlockKind::For)) {
        const Block& before = p.blocks[static_cast<std::size_t>(bestBlock - 1)];
        if (before.kind == BlockKind::Repeat || before.kind == BlockKind::Loop) {
            head = bestBlock - 1;
            kind = before.kind;
        }
    }
    const Block& headBlock = p.blocks[static_cast<std::size_t>(head)];
    error(p, {headBlock.line, 0},
          "runaway program: more than " + limit + " blocks executed; the " + loopName(kind) + " loop of line " +
              std::to_string(headBlock.line) + " repeated " + std::to_string(best) +
              " times without ending (stopped here)");
}

bool Machine::step()
{
    const std::size_t frameIndex = m_stack.size() - 1;
    const int pc = m_stack[frameIndex].pc;
    const int programIndex = m_stack[frameIndex].program;
    const Program& p = *m_programs[static_cast<std::size_t>(programIndex)];
    const Block& b = p.blocks[static_cast<std::size_t>(pc)];
    m_currentFile = programIndex;
    m_currentLine = b.line;
    m_stack[frameIndex].pc = pc + 1;
    auto condition = [&](bool whenBroken) {
        if (b.bad || b.expr < 0)
            return whenBroken;
        m_evalFailed = false;
        const auto v = eval(p, b.expr);
        return v ? *v != 0 : whenBroken;
    };
    auto resetCount = [&] {
        auto& counts = m_loopCounts[static_cast<std::size_t>(programIndex)];
        if (!counts.empty())
            counts[static_cast<std::size_t>(pc)] = 0;
    };
    switch (b.kind) {
    case BlockKind::Normal:
        return executeNormal(p, b);
    case BlockKind::Empty:
    case BlockKind::Bad:
        emitComment(p, b);
        return true;
    case BlockKind::Proc:
        return true;
    case BlockKind::If:
        if (!condition(false))
            m_stack[frameIndex].pc = b.jump + 1;
        return true;
    case BlockKind::Else:
        m_stack[frameIndex].pc = b.jump + 1;
        return true;
    case BlockKind::EndIf:
        return true;
    case BlockKind::While:
        if (!condition(false)) {
            resetCount();
            m_stack[frameIndex].pc = b.jump + 1;
        }
        return true;
    case BlockKind::EndWhile:
        jumpBack(b.jump);
        return true;
    case BlockKind::Repeat:
    case BlockKind::Loop: {
        auto& counts = m_loopCounts[static_cast<std::size_t>(programIndex)];
        if (!counts.empty())
            counts[static_cast<std::size_t>(pc + 1)] = 0;
        return true;
    }
    case BlockKind::Until:
        if (!condition(true))
            jumpBack(b.jump + 1);
        return true;
    case BlockKind::EndLoop:
        jumpBack(b.jump + 1);
        return true;
    case BlockKind::For: {
        m_evalFailed = false;
        const auto from = eval(p, b.expr);
        const auto to = eval(p, b.expr2);
        resetCount();
        if (!from || !to) {
            m_stack[frameIndex].pc = b.jump + 1;
            return true;
        }
        double& var = b.forIsR ? m_r[static_cast<std::size_t>(b.forSlot)]
                               : m_locals[m_stack[frameIndex].localsBase + static_cast<std::size_t>(b.forSlot)];
        var = *from;
        if (var > *to)
            m_stack[frameIndex].pc = b.jump + 1;
        return true;
    }
    case BlockKind::EndFor: {
        const Block& head = p.blocks[static_cast<std::size_t>(b.jump)];
        double& var = head.forIsR ? m_r[static_cast<std::size_t>(head.forSlot)]
                                  : m_locals[m_stack[frameIndex].localsBase + static_cast<std::size_t>(head.forSlot)];
        var += 1;
        m_evalFailed = false;
        const auto to = eval(p, head.expr2);
        if (to && var <= *to)
            jumpBack(b.jump + 1);
        return true;
    }
    case BlockKind::Goto: {
        if (b.bad || b.text < 0)
            return true;  // reported when parsed
        if (b.expr >= 0 && !condition(false))
            return true;
        const std::string& label = p.texts[static_cast<std::size_t>(b.text)];
        bool anyTarget = false;
        const int target = jumpTarget(p, label, pc, b.gotoDir, anyTarget);
        if (target < 0) {
            // Undefined labels were reported with the program; the block after the jump goes on.
            if (b.gotoDir != GotoDir::BothNoAlarm && anyTarget)
                error(p, {b.line, 0}, "jump target " + label + " not found in the direction of the GOTO");
            return true;
        }
        if (target <= pc)
            jumpBack(target);
        else
            m_stack[frameIndex].pc = target;
        return true;
    }
    case BlockKind::MCall: {
        emitComment(p, b);
        if (b.bad)
            return true;  // reported when parsed
        const Word* word = b.callWord >= 0 ? &p.words[static_cast<std::size_t>(b.callWord)] : nullptr;
        if (!word || (word->kind != WordKind::Cycle && word->kind != WordKind::Call)) {
            m_modalCall.reset();
            return true;
        }
        m_evalFailed = false;
        ModalCall call;
        call.line = b.line;
        call.level = m_stack.size();
        call.args = evalArgs(p, b);
        if (m_evalFailed)
            return true;
        if (word->kind == WordKind::Cycle) {
            call.cycle = word->code;
        } else {
            call.cycle = -1;
            call.name = p.texts[static_cast<std::size_t>(word->code)];
        }
        m_modalCall = std::move(call);
        return true;
    }
    }
    return true;
}

// The block a GOTO jumps to: labels and block numbers are kept in block order, so the nearest
// one in the direction is found by binary search (a label repeated a million times stays cheap).
int Machine::jumpTarget(const Program& p, const std::string& label, int pc, GotoDir dir, bool& anyTarget) const
{
    std::vector<std::int32_t> none;
    const std::vector<std::int32_t>* labels = &none;
    if (auto it = p.labels.find(label); it != p.labels.end())
        labels = &it->second;
    using NumberIt = std::vector<std::pair<std::int64_t, std::int32_t>>::const_iterator;
    NumberIt numbersBegin = p.blockNumbers.end(), numbersEnd = p.blockNumbers.end();
    if (label.size() > 1 && label[0] == 'N') {
        std::int64_t n = 0;
        const auto r = std::from_chars(label.data() + 1, label.data() + label.size(), n);
        if (r.ec == std::errc() && r.ptr == label.data() + label.size()) {
            const auto range = std::equal_range(p.blockNumbers.begin(), p.blockNumbers.end(),
                                                std::pair<std::int64_t, std::int32_t>{n, 0},
                                                [](const auto& a, const auto& b) { return a.first < b.first; });
            numbersBegin = range.first;
            numbersEnd = range.second;
        }
    }
    anyTarget = !labels->empty() || numbersBegin != numbersEnd;
    auto indexOf = [](const std::pair<std::int64_t, std::int32_t>& e) { return e.second; };
    int forward = -1, backward = -1, first = -1;
    auto consider = [&](int candidate) {
        if (candidate > pc && (forward < 0 || candidate < forward))
            forward = candidate;
        if (candidate <= pc && candidate > backward)
            backward = candidate;
        if (first < 0 || candidate < first)
            first = candidate;
    };
    if (!labels->empty()) {
        const auto up = std::upper_bound(labels->begin(), labels->end(), pc);
        if (up != labels->end())
            consider(*up);
        if (up != labels->begin())
            consider(*(up - 1));
        consider(labels->front());
    }
    if (numbersBegin != numbersEnd) {
        const auto up = std::upper_bound(numbersBegin, numbersEnd, pc,
                                         [&](int value, const auto& e) { return value < indexOf(e); });
        if (up != numbersEnd)
            consider(indexOf(*up));
        if (up != numbersBegin)
            consider(indexOf(*(up - 1)));
        consider(indexOf(*numbersBegin));
    }
    if (dir != GotoDir::Backward && forward >= 0)
        return forward;
    if (dir != GotoDir::Forward && backward >= 0)
        return backward;
    if (dir == GotoDir::Both)
        return first;
    return -1;
}

std::vector<std::optional<double>> Machine::evalArgs(const Program& p, const Block& b)
{
    std::vector<std::optional<double>> args;
    args.reserve(static_cast<std::size_t>(b.argCount));
    for (std::int32_t i = 0; i < b.argCount; ++i) {
        const std::int32_t e = p.args[static_cast<std::size_t>(b.firstArg + i)];
        args.push_back(e >= 0 ? eval(p, e) : std::nullopt);
    }
    return args;
}

int Machine::loadProgram(const std::string& name, Pos callPos, const Program& caller)
{
    if (auto it = m_byName.find(name); it != m_byName.end()) {
        if (it->second < 0)
            error(caller, callPos, "undefined subprogram " + name);
        return it->second;
    }
    std::optional<ProgramSource> source;
    if (m_options.resolveProgram)
        source = m_options.resolveProgram(name);
    if (!source) {
        m_byName.emplace(name, -1);
        error(caller, callPos, "undefined subprogram " + name);
        return -1;
    }
    m_programs.push_back(std::make_unique<Program>(parseProgram(source->path, std::move(source->text))));
    m_loopCounts.emplace_back();
    m_result.files.push_back(source->path);
    const int index = static_cast<int>(m_programs.size() - 1);
    m_byName.emplace(name, index);
    const Program& loaded = *m_programs.back();
    addParseDiagnostics(loaded);
    checkProcName(loaded, name);
    return index;
}

bool Machine::callProgram(const std::string& name, const Block& block, const Program& caller, int repeats,
                          const std::vector<std::optional<double>>& args)
{
    const Pos pos{block.line,
                  block.callWord >= 0 ? caller.words[static_cast<std::size_t>(block.callWord)].pos.column : 0};
    if (m_stack.size() >= kMaxCallDepth) {
        error(caller, pos,
              "subprogram calls nested deeper than " + std::to_string(kMaxCallDepth) + " (recursive call of " + name +
                  "?): the call is left out");
        return true;
    }
    const int index = loadProgram(name, pos, caller);
    if (index < 0)
        return true;
    setSource(block.line);  // the calling block, so the callee's records link back to it
    const Program& callee = *m_programs[static_cast<std::size_t>(index)];
    if (args.size() > callee.procParams.size()) {
        error(caller, pos,
              name + " takes " + std::to_string(callee.procParams.size()) + " parameters, " +
                  std::to_string(args.size()) + " given");
        return true;
    }
    Frame frame;
    frame.program = index;
    frame.localsBase = m_locals.size();
    frame.repeatsLeft = std::max(0, repeats - 1);
    frame.callPc = m_stack.back().pc - 1;
    m_locals.resize(frame.localsBase + static_cast<std::size_t>(callee.localSlots), 0.0);
    for (std::size_t i = 0; i < args.size(); ++i) {
        const auto slot = static_cast<std::size_t>(callee.procParams[i]);
        double v = args[i].value_or(0.0);
        if (callee.slotType[slot] == 1)
            v = std::round(v);
        else if (callee.slotType[slot] == 2)
            v = v != 0;
        m_locals[frame.localsBase + slot] = v;
        if (frame.repeatsLeft > 0)
            frame.args.push_back(v);
    }
    m_stack.push_back(frame);
    return true;
}

bool Machine::returnFromCall()
{
    Frame& frame = m_stack.back();
    if (frame.repeatsLeft > 0) {
        // The next repetition is a new call with the same arguments.
        --frame.repeatsLeft;
        frame.pc = 0;
        std::fill(m_locals.begin() + static_cast<std::ptrdiff_t>(frame.localsBase), m_locals.end(), 0.0);
        const Program& callee = *m_programs[static_cast<std::size_t>(frame.program)];
        for (std::size_t i = 0; i < frame.args.size(); ++i)
            m_locals[frame.localsBase + static_cast<std::size_t>(callee.procParams[i])] = frame.args[i];
        return true;
    }
    m_locals.resize(frame.localsBase);
    m_stack.pop_back();
    if (m_stack.empty()) {
        m_result.completed = true;
        return false;
    }
    return true;
}

}  // namespace camwb::nc::sinumerik
