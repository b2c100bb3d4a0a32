// Words and machine functions of Klartext blocks: evaluating a block's words, feeds (F, FMAX,
// F AUTO, FU), radius compensation (R0/RL/RR), M functions in the control's order (spindle and
// coolant at the block start; stops, program end, M99/M89 cycle calls at its end), TOOL DEF and
// TOOL CALL.
#include "nc/heidenhain/Machine.h"

#include <cmath>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

bool Machine::gather(const Block& b, BlockWords& w, bool quiet)
{
    const Program& p = program();
    bool ok = true;
    bool m128 = false;
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
            if (m128) {
                // M128 F: the feed of the compensating moves, not the block's (iTNC 530, M128).
                if (!quiet)
                    warnOnce(kWarnTcpmFeed, b, "M128 F (the feed of compensating moves) is not traced");
                break;
            }
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
        case Key::Length:
            w.length = v;
            break;
        case Key::DeltaLength:
            w.deltaLength = v;
            break;
        case Key::M:
            m128 = m128 || word.param == 128;
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

void Machine::applyFeedRate(const BlockWords& w)
{
    using F = BlockWords::FeedWord;
    if (w.feed == F::Value || w.feed == F::Auto) {
        // With M136 in force a plain F is per revolution (iTNC 530 User's Manual, M136), in the
        // unit of a plain F (0.1 inch in inch programs, as the iTNC post writes it).
        setFeedMode(m_m136 ? FeedMode::PerRevolution : FeedMode::PerMinute);
        m_feed = w.feed == F::Auto ? m_autoFeed : w.feedValue * m_feedScale;
    } else if (w.feed == F::PerRev) {
        setFeedMode(FeedMode::PerRevolution);
        m_feed = w.feedValue * m_scale;
    }
}

void Machine::setFeedMode(FeedMode mode)
{
    if (m_feedMode == mode)
        return;
    m_feedMode = mode;
    m_sink.feedMode(FeedModeChange{mode});
}

void Machine::applyCompensation(const BlockWords& w)
{
    if (w.comp < 0)
        return;
    const CutterCompSide side =
        w.comp == 0 ? CutterCompSide::Off : (w.comp == 1 ? CutterCompSide::Left : CutterCompSide::Right);
    if (side != m_comp) {
        if (side != CutterCompSide::Off)
            setCompensationRadius();
        m_comp = side;
        m_sink.cutterComp(CutterComp{side});
    }
}

// R of the tool's TOOL DEF, else of the tool table, plus DR of the TOOL CALL (the TNC's
// compensation value R + DR(TOOL CALL); the table's DR column is not in LinuxCNC's format).
void Machine::setCompensationRadius()
{
    const std::string what = "tool " + std::to_string(m_tool);
    std::optional<double> radius;
    if (const auto it = m_toolRadius.find(m_tool); it != m_toolRadius.end())
        radius = it->second;
    else if (m_options.toolTable)
        radius = m_options.toolTable->radiusOf(m_tool);
    m_compensation.setRadius(radius ? std::optional<double>(*radius + m_deltaRadius) : std::nullopt, what);
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
void Machine::applySpindleAndCoolant(const Block& b, const BlockWords& w)
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
        case 136:
        case 137:
            // M136: F in mm per spindle revolution until M137 (iTNC 530 User's Manual, M136).
            m_m136 = w.m[static_cast<std::size_t>(i)] == 136;
            setFeedMode(m_m136 ? FeedMode::PerRevolution : FeedMode::PerMinute);
            break;
        case 126:
        case 127:
            m_five.setShortestPath(w.m[static_cast<std::size_t>(i)] == 126);
            break;
        case 128:
            if (m_five.active()) {
                m_axisSpat = false;
                setTcpm(true);
            } else {
                warnOnce(kWarnTcpm, b,
                         "M128 (TCPM): tool-tip control needs a five-axis machine (--machine, or the NC inspector's "
                         "Machine) to be traced; "
                         "positions are traced as three-axis moves");
            }
            break;
        default:
            break;
        }
    }
}

// M functions effective at the end of the block (after its motion).
void Machine::applyStop(const Block& b, const BlockWords& w, bool moved)
{
    bool cycleCalled = false;
    for (int i = 0; i < w.mCount; ++i) {
        const int m = w.m[static_cast<std::size_t>(i)];
        switch (m) {
        case 0:
            // Program stop, spindle stop, coolant off (the control's M0).
            m_sink.programStop(ProgramStop{false});
            spindleOff();
            coolant(CoolantMode::Off);
            break;
        case 1:
            m_sink.programStop(ProgramStop{true});
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
        case 129:
            // M129 takes effect at the end of its block (iTNC 530 User's Manual, M128).
            if (m_five.active()) {
                m_axisSpat = false;
                setTcpm(false);
            }
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
            retract(b, w.mbMax ? std::nullopt : w.mb, "M140 MB");
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
    if (*n < 0 || *n > 32767 || *n != std::floor(*n)) {  // as TOOL CALL: a TOOL DEF 2.5 is no tool
        report(Severity::Error, b.line, b.column, "tool number out of range");
        return;
    }
    if (w.radius)
        m_toolRadius[static_cast<int>(*n)] = *w.radius * m_scale;
    if (w.length)
        m_toolLength[static_cast<int>(*n)] = *w.length * m_scale;
}

void Machine::toolCall(const Block& b)
{
    const Program& p = program();
    BlockWords w;
    gather(b, w, false);
    std::optional<double> speed;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key == Key::ToolAxis)
            m_toolAxis = static_cast<char>(word.param);
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
    m_deltaRadius = 0;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key == Key::DeltaRadius && word.expr >= 0)
            if (const auto dr = eval(word.expr))
                m_deltaRadius = *dr * m_scale;
    }
    m_deltaLength = w.deltaLength ? *w.deltaLength * m_scale : 0;
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
    updateToolLength();
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

}  // namespace camwb::nc::heidenhain
