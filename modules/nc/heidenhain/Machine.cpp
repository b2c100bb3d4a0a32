#include "nc/heidenhain/Machine.h"

#include "nc/heidenhain/Parser.h"

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

Machine::Machine(const InterpretOptions& options, MachineSink& sink, InterpretResult& result) :
    m_options(options),
    m_sink(sink),
    m_result(result),
    m_rep(result.diagnostics, options.maxDiagnostics, result.diagnosticsDropped)
{
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
        if (++m_result.blocksExecuted > m_options.maxBlocks) {
            const Block& b = blocks[m_pc];
            report(Severity::Error, b.line, 0,
                   "runaway program: more than " + std::to_string(m_options.maxBlocks) +
                       " blocks executed (a jump or repeat that never ends?)");
            m_result.completed = false;
            break;
        }
        m_jumped = false;
        execute(blocks[m_pc]);
        if (!m_jumped)
            ++m_pc;
    }
    m_sink.end();
    sortDiagnostics();
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
        m_knownX = m_knownY = false;
        m_tangent.reset();
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
        if (!b.flag)
            report(Severity::Warning, b.line, b.column,
                   "PLANE " + std::string(b.name) +
                       ": the tilted working plane is traced once the five-axis machine model exists; "
                       "positions are traced untilted");
        return;
    case BlockKind::Function:
        if (equalsIgnoreCase(b.name, "TCPM")) {
            if (!b.flag)
                report(Severity::Warning, b.line, b.column,
                       "FUNCTION TCPM: five-axis tool-tip motion is traced once the five-axis machine model exists; "
                       "positions are traced as three-axis moves");
        } else {
            report(Severity::Warning, b.line, b.column, "FUNCTION " + std::string(b.name) + " is not traced");
        }
        return;
    }
}

bool Machine::gather(const Block& b, BlockWords& w, bool quiet)
{
    const Program& p = program();
    bool ok = true;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        std::optional<double> v;
        if (word.expr >= 0) {
            v = eval(word.expr, quiet);
            if (!v) {
                ok = false;
                continue;
            }
        }
        const auto k = static_cast<int>(word.key);
        if (k <= static_cast<int>(Key::IW)) {
            if (std::abs(*v) > kMaxCoordinate && !quiet) {
                report(Severity::Error, word.line, word.column, "coordinate out of the control's range (+-99999.9999)");
                ok = false;
                continue;
            }
            w.axes[static_cast<std::size_t>(k)] = *v;
            const Key key = word.key;
            if (key != Key::X && key != Key::Y && key != Key::Z && key != Key::IX && key != Key::IY && key != Key::IZ)
                w.rotary = true;
            continue;
        }
        switch (word.key) {
        case Key::PR:
            w.pr = v;
            break;
        case Key::PA:
            w.pa = v;
            break;
        case Key::IPR:
            w.ipr = v;
            break;
        case Key::IPA:
            w.ipa = v;
            break;
        case Key::Radius:
            w.radius = v;
            break;
        case Key::Len:
            w.len = v;
            break;
        case Key::Angle:
            w.angle = v;
            break;
        case Key::Direction:
            w.direction = word.param;
            break;
        case Key::Comp:
            w.comp = word.param;
            break;
        case Key::Feed:
            w.feed = BlockWords::FeedWord::Value;
            w.feedValue = *v;
            if (*v < 0 && !quiet) {
                report(Severity::Error, word.line, word.column, "negative feed");
                ok = false;
            }
            break;
        case Key::FeedMax:
            w.feed = BlockWords::FeedWord::Max;
            break;
        case Key::FeedAuto:
            w.feed = BlockWords::FeedWord::Auto;
            break;
        case Key::FeedRev:
            w.feed = BlockWords::FeedWord::PerRev;
            w.feedValue = *v;
            break;
        case Key::FeedTooth:
            w.feed = BlockWords::FeedWord::PerTooth;
            w.feedValue = *v;
            break;
        case Key::M:
            if (w.mCount < static_cast<int>(w.m.size())) {
                if (w.mCount == 0)
                    w.mColumn = word.column;
                w.m[static_cast<std::size_t>(w.mCount++)] = word.param;
            } else if (!quiet) {
                report(Severity::Warning, word.line, word.column, "more than 8 M functions in one block: ignored");
            }
            break;
        case Key::Mb:
            if (word.param == 1)
                w.mbMax = true;
            else
                w.mb = v;
            break;
        default:
            break;
        }
    }
    return ok;
}

void Machine::applyFeed(const BlockWords& w)
{
    using F = BlockWords::FeedWord;
    if (w.feed == F::Value || w.feed == F::Auto) {
        if (m_feedMode != FeedMode::PerMinute) {
            m_feedMode = FeedMode::PerMinute;
            m_sink.feedMode(FeedModeChange{FeedMode::PerMinute});
        }
        m_feed = w.feed == F::Value ? w.feedValue * m_feedScale : m_autoFeed;
    } else if (w.feed == F::PerRev) {
        if (m_feedMode != FeedMode::PerRevolution) {
            m_feedMode = FeedMode::PerRevolution;
            m_sink.feedMode(FeedModeChange{FeedMode::PerRevolution});
        }
        m_feed = w.feedValue * m_scale;
    }
}

void Machine::applyComp(const BlockWords& w)
{
    if (w.comp < 0)
        return;
    const CutterCompSide side =
        w.comp == 0 ? CutterCompSide::Off : (w.comp == 1 ? CutterCompSide::Left : CutterCompSide::Right);
    if (side != m_comp) {
        m_comp = side;
        m_sink.cutterComp(CutterComp{side});
    }
}

void Machine::spindleOn(bool clockwise, const Block& b, int column)
{
    if (m_rpm <= 0)
        report(Severity::Warning, b.line, column, "spindle started with no speed (S) programmed");
    m_spindleOn = true;
    m_spindleCw = clockwise;
    m_sink.spindle(Spindle{m_rpm, clockwise, 0});
}

void Machine::spindleOff()
{
    if (!m_spindleOn)
        return;
    m_spindleOn = false;
    m_sink.spindle(Spindle{0, m_spindleCw, 0});
}

void Machine::coolant(CoolantMode mode)
{
    if (mode == m_coolant)
        return;
    m_coolant = mode;
    m_sink.coolant(Coolant{mode});
}

// M functions effective at the start of the block (before its motion).
void Machine::applyEarlyM(const Block& b, const BlockWords& w)
{
    for (int i = 0; i < w.mCount; ++i) {
        switch (w.m[static_cast<std::size_t>(i)]) {
        case 3:
            spindleOn(true, b, w.mColumn);
            break;
        case 4:
            spindleOn(false, b, w.mColumn);
            break;
        case 8:
            coolant(CoolantMode::Flood);
            break;
        case 13:
            spindleOn(true, b, w.mColumn);
            coolant(CoolantMode::Flood);
            break;
        case 14:
            spindleOn(false, b, w.mColumn);
            coolant(CoolantMode::Flood);
            break;
        case 128:
            warnOnce(kWarnTcpm, b,
                     "M128 (TCPM): five-axis tool-tip motion is traced once the five-axis machine model exists; "
                     "positions are traced as three-axis moves");
            break;
        case 91:
        case 92:
            warnOnce(kWarnM91, b, "M91/M92 (machine coordinates): traced as workpiece coordinates (no machine model)");
            break;
        default:
            break;
        }
    }
}

// M functions effective at the end of the block (after its motion).
void Machine::applyLateM(const Block& b, const BlockWords& w, bool moved)
{
    bool cycleCalled = false;
    for (int i = 0; i < w.mCount; ++i) {
        const int m = w.m[static_cast<std::size_t>(i)];
        switch (m) {
        case 0:
        case 1:
            m_sink.programStop(ProgramStop{m == 1});
            break;
        case 2:
        case 30:
            spindleOff();
            coolant(CoolantMode::Off);
            if (m_programDepth > 0) {
                warnOnce(kWarnCalledEnd, b, "M2/M30 in a called program: traced as its end");
                returnFromProgram();
            } else {
                endProgram(true);
            }
            return;
        case 5:
            spindleOff();
            break;
        case 9:
            coolant(CoolantMode::Off);
            break;
        case 99:
            m_modalCycleCall = false;
            runCycle(b, m_pos.xy());
            cycleCalled = true;
            break;
        case 89:
            m_modalCycleCall = true;
            runCycle(b, m_pos.xy());
            cycleCalled = true;
            break;
        case 140:
            if (w.mb) {
                m_pos.z += *w.mb * m_scale;
                m_sink.rapid(Rapid{m_pos});
            } else {
                warnOnce(kWarnM140, b,
                         "M140 MB MAX: the retract to the travel limit is not traced (no machine limits)");
            }
            break;
        default:
            break;
        }
    }
    if (moved && m_modalCycleCall && !cycleCalled)
        runCycle(b, m_pos.xy());
}

void Machine::toolDef(const Block& b)
{
    if (b.exprA < 0)
        return;
    const auto n = eval(b.exprA);
    BlockWords w;
    if (!n || !gather(b, w, false))
        return;
    if (*n < 0 || *n > 32767) {
        report(Severity::Error, b.line, b.column, "tool number out of range");
        return;
    }
    if (w.radius)
        m_toolRadius[static_cast<int>(*n)] = *w.radius * m_scale;
}

void Machine::toolCall(const Block& b)
{
    const Program& p = program();
    BlockWords w;
    gather(b, w, false);
    std::optional<double> speed;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key == Key::ToolAxis && word.param != 'Z')
            warnOnce(kWarnToolAxis, b,
                     "tool axis " + std::string(1, static_cast<char>(word.param)) +
                         ": circles and cycles are still traced in the XY plane");
        if (word.key == Key::Speed)
            speed = eval(word.expr);
        if (word.key == Key::SurfaceSpeed)
            warnOnce(kWarnSurfaceSpeed, b, "S(VC=...): the spindle speed needs the tool diameter and is not traced");
        if (word.key == Key::Feed)
            m_autoFeed = w.feedValue * m_feedScale;
    }
    if (b.a != -2) {
        ToolChange change;
        if (b.a == -1) {
            change.tool.number = 0;
            change.tool.name = std::string(b.name);
        } else {
            const auto n = eval(b.exprA);
            if (!n)
                return;
            if (*n < 0 || *n > 32767 || *n != std::floor(*n)) {
                report(Severity::Error, b.line, b.column, "tool number out of range");
                return;
            }
            change.tool.number = static_cast<int>(*n);
        }
        spindleOff();
        m_tool = change.tool.number;
        if (auto r = m_toolRadius.find(m_tool); r != m_toolRadius.end())
            change.tool.diameterMm = 2 * r->second;
        source(b);
        m_sink.toolChange(change);
    }
    if (speed) {
        if (*speed < 0 || *speed > 999999) {
            report(Severity::Error, b.line, b.column, "spindle speed out of range");
            return;
        }
        m_rpm = *speed;
        if (m_spindleOn) {
            source(b);
            m_sink.spindle(Spindle{m_rpm, m_spindleCw, 0});
        }
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
