// One ordinary block: its words are read in order (assignments take effect at once), then the
// block acts in the control's order: modal G codes, tool, spindle, coolant, compensation, dwell,
// the motion, a modal or direct cycle call, stops, the end or return, and a subprogram call.
#include "nc/sinumerik/Machine.h"

#include <cmath>
#include <cstdio>

namespace camwb::nc::sinumerik {

namespace {

using namespace camwb::toolpath;

constexpr double kMaxValue = 99999.999;  // the control's input range for positions (mm or inch)

double& component(Vec3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

}  // namespace

void Machine::emitComment(const Program& p, const Block& block)
{
    if (block.comment < 0)
        return;
    setSource(block.line);
    m_sink.comment(Comment{p.texts[static_cast<std::size_t>(block.comment)]});
}

double Machine::feedToInternal(double f) const
{
    if (m_modal.feedMode == FeedMode::InverseTime)
        return f;
    return m_modal.inchFeed ? f * 25.4 : f;
}

bool Machine::checkRange(const Program& p, Pos pos, double value)
{
    if (std::isfinite(value) && std::abs(value) <= kMaxValue)
        return true;
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    error(p, pos, std::string("value ") + text + " outside the control's range (+-99999.999)");
    return false;
}

void Machine::setFeedMode(FeedMode mode, int line)
{
    if (m_modal.feedMode == mode)
        return;
    m_modal.feedMode = mode;
    setSource(line);
    m_sink.feedMode(FeedModeChange{mode});
}

void Machine::emitSpindle(int line)
{
    Spindle s;
    s.clockwise = m_spindleDir != 4;
    if (m_spindleDir != 0) {
        if (m_modal.constantSurfaceSpeed) {
            s.surfaceSpeedMPerMin = m_speed;
            s.rpm = m_lims;
        } else {
            s.rpm = m_speed;
        }
    }
    setSource(line);
    m_sink.spindle(s);
}

void Machine::assign(const Program& p, const Word& w, double value)
{
    switch (w.target) {
    case AssignTarget::R:
        m_r[static_cast<std::size_t>(w.code)] = value;
        return;
    case AssignTarget::RIndirect: {
        const auto i = eval(p, w.expr2);
        if (!i)
            return;
        if (!(*i >= 0 && *i < 1000)) {
            error(p, w.pos, "R parameter number out of range (R0..R999)");
            return;
        }
        m_r[static_cast<std::size_t>(*i)] = value;
        return;
    }
    case AssignTarget::Local: {
        std::size_t slot = static_cast<std::size_t>(w.code);
        if (w.expr2 >= 0) {
            const auto i = eval(p, w.expr2);
            if (!i)
                return;
            if (!(*i >= 0 && *i < w.arraySize)) {
                error(p, w.pos, "array index out of range");
                return;
            }
            slot += static_cast<std::size_t>(*i);
        }
        const std::uint8_t type = p.slotType[slot];
        m_locals[m_stack.back().localsBase + slot] = type == 1 ? std::round(value) : type == 2 ? (value != 0) : value;
        return;
    }
    }
}

bool Machine::executeNormal(const Program& p, const Block& b)
{
    m_evalFailed = false;
    emitComment(p, b);
    const Word* words = p.words.data() + b.firstWord;

    int motion = -1, plane = 0, units = 0, absInc = 0, workOffset = -1, comp = -1, feedMode = -1, css = -1;
    bool dwell = false, g53 = false;
    std::array<std::optional<double>, 6> axis{};
    std::array<ValueMode, 6> axisMode{};
    ArcWords arcWords;
    arcWords.pos = {b.line, 0};
    std::optional<double> feed, speed, lims, tool;
    int mCodes[8];
    int mCount = 0;
    bool ret = false;
    const Word* callWord = b.callWord >= 0 ? &p.words[static_cast<std::size_t>(b.callWord)] : nullptr;

    for (std::int32_t i = 0; i < b.wordCount; ++i) {
        const Word& w = words[i];
        switch (w.kind) {
        case WordKind::G: {
            const int g = w.code;
            if (g <= 3) {
                motion = g;
                arcWords.pos = w.pos;
            } else if (g == 4)
                dwell = true;
            else if (g >= 17 && g <= 19)
                plane = g;
            else if (g == 90 || g == 91)
                absInc = g;
            else if (g == 70 || g == 71 || g == 700 || g == 710)
                units = g;
            else if (g >= 54 && g <= 57)
                workOffset = g - 53;
            else if (g == 500)
                workOffset = 0;
            else if (g >= 505 && g <= 599)
                workOffset = g - 500;
            else if (g >= 40 && g <= 42)
                comp = g;
            else if (g == 93 || g == 94 || g == 95)
                feedMode = g;
            else if (g == 96 || g == 97 || g == 961 || g == 971)
                css = g == 96 || g == 961 ? 1 : 0;
            else if (g == 53 || g == 153)
                g53 = true;
            else if (g == 9 || g == 60 || g == 64 || (g >= 641 && g <= 645) || g == 601 || g == 602 || g == 603 ||
                     g == 25 || g == 26 || g == 110 || g == 111 || g == 112 || g == 140 || g == 141 || g == 142 ||
                     g == 143 || g == 340 || g == 341 || g == 450 || g == 451 || g == 62 || g == 621)
                ;  // path control, limits, approach: nothing the trace shows
            else
                warning(p, w.pos, "G" + std::to_string(g) + " is not interpreted: ignored");
            break;
        }
        case WordKind::M:
            if (mCount < 8)
                mCodes[mCount++] = w.code;
            break;
        case WordKind::Axis: {
            const auto v = wordValue(p, w);
            if (v && checkRange(p, w.pos, *v)) {
                axis[w.index] = v;
                axisMode[w.index] = w.mode;
            } else {
                m_evalFailed = true;
            }
            break;
        }
        case WordKind::Centre: {
            const auto v = wordValue(p, w);
            if (v && checkRange(p, w.pos, *v)) {
                arcWords.centre[w.index] = v;
                arcWords.centreMode[w.index] = w.mode;
            } else {
                m_evalFailed = true;
            }
            break;
        }
        case WordKind::F:
            feed = wordValue(p, w);
            break;
        case WordKind::S:
            speed = wordValue(p, w);
            break;
        case WordKind::T:
            tool = wordValue(p, w);
            break;
        case WordKind::TName:
            m_toolName = p.texts[static_cast<std::size_t>(w.code)];
            tool = 0;
            break;
        case WordKind::D:
            (void)wordValue(p, w);
            break;
        case WordKind::Cr:
            arcWords.cr = wordValue(p, w);
            break;
        case WordKind::Ar:
            arcWords.ar = wordValue(p, w);
            break;
        case WordKind::Turn: {
            const auto v = wordValue(p, w);
            if (v && (*v < 0 || *v > 999 || *v != std::trunc(*v))) {
                error(p, w.pos, "TURN must be a whole number 0..999");
                m_evalFailed = true;
            } else if (v) {
                arcWords.turn = static_cast<int>(*v);
            }
            break;
        }
        case WordKind::Lims:
            lims = wordValue(p, w);
            break;
        case WordKind::Assign: {
            const auto v = wordValue(p, w);
            if (v)
                assign(p, w, *v);
            break;
        }
        case WordKind::Keyword:
            switch (static_cast<Keyword>(w.code)) {
            case Keyword::DiamOn:
                m_modal.diameter = true;
                break;
            case Keyword::DiamOf:
                m_modal.diameter = false;
                break;
            case Keyword::TraOri:
                warning(p, w.pos,
                        "TRAORI (five-axis transformation) is recognised; its motion is traced once the "
                        "five-axis machine model exists: positions are traced as programmed");
                break;
            case Keyword::Cycle800:
                warning(p, w.pos,
                        "CYCLE800 (swivel plane) is recognised; five-axis motion is traced once the "
                        "five-axis machine model exists: positions are traced in the unswivelled frame");
                break;
            case Keyword::Frame:
                warning(p, w.pos,
                        "programmable frame " + p.texts[static_cast<std::size_t>(b.text)] +
                            " is not applied: positions are traced in the programmed frame");
                setSource(b.line);
                m_sink.passThrough(PassThrough{p.texts[static_cast<std::size_t>(b.text)]});
                break;
            case Keyword::Ret:
                ret = true;
                break;
            case Keyword::SetAl: {
                m_evalFailed = false;
                const auto args = evalArgs(p, b);
                const int alarm = !args.empty() && args[0] ? static_cast<int>(*args[0]) : 0;
                error(p, w.pos, "the program sets alarm " + std::to_string(alarm) + " (SETAL): stopped");
                m_stopped = true;
                return false;
            }
            default:
                break;
            }
            break;
        case WordKind::Msg:
            if (w.code >= 0) {
                setSource(b.line);
                m_sink.comment(Comment{p.texts[static_cast<std::size_t>(w.code)]});
            }
            break;
        default:
            break;
        }
    }
    if (m_evalFailed)
        return true;  // reported; the block is left out

    const int line = b.line;
    if (units == 70 || units == 700) {
        m_modal.inch = true;
        m_modal.inchFeed = units == 700;
    } else if (units == 71 || units == 710) {
        m_modal.inch = false;
        m_modal.inchFeed = false;
    }
    if (absInc)
        m_modal.incremental = absInc == 91;
    if (plane)
        m_modal.plane = plane;
    if (workOffset >= 0 && workOffset != m_modal.workOffset) {
        m_modal.workOffset = workOffset;
        setSource(line);
        m_sink.workOffset(WorkOffset{workOffset});
    }
    if (g53)
        warning(p, {line, 0},
                "G53/G153 (machine coordinates for this block) is not traced: positions stay in the "
                "work offset's frame");
    if (feedMode == 93)
        setFeedMode(FeedMode::InverseTime, line);
    else if (feedMode == 94)
        setFeedMode(FeedMode::PerMinute, line);
    else if (feedMode == 95 || css == 1)
        setFeedMode(FeedMode::PerRevolution, line);  // G96 switches to revolutional feed with it
    if (feed && !dwell)
        m_feed = feedToInternal(*feed);

    // Tool: M6 changes to the selected tool; without any M6 in the program T changes at once.
    bool toolChange = false;
    if (tool) {
        m_tool = static_cast<int>(std::lround(*tool));
        if (!m_toolChangeOnM6)
            toolChange = true;
    }
    for (int i = 0; i < mCount; ++i)
        if (mCodes[i] == 6)
            toolChange = true;
    if (toolChange) {
        ToolChange tc;
        tc.tool.number = m_tool;
        tc.tool.name = m_toolName;
        setSource(line);
        m_sink.toolChange(tc);
    }

    bool spindleChanged = false;
    if (css >= 0 && (css == 1) != m_modal.constantSurfaceSpeed) {
        m_modal.constantSurfaceSpeed = css == 1;
        spindleChanged = css == 1 || speed.has_value();
    }
    if (lims) {
        m_lims = *lims;
        spindleChanged = spindleChanged || m_modal.constantSurfaceSpeed;
    }
    if (speed && !(dwell && !feed)) {
        if (*speed < 0) {
            error(p, {line, 0}, "negative spindle speed");
        } else if (*speed != m_speed) {
            m_speed = *speed;
            spindleChanged = true;
        }
    }
    int coolant = -1;
    bool stop = false, optionalStop = false, end = false;
    for (int i = 0; i < mCount; ++i) {
        switch (mCodes[i]) {
        case 3:
        case 4:
            if (m_spindleDir != mCodes[i])
                spindleChanged = true;
            m_spindleDir = mCodes[i];
            spindleChanged = spindleChanged || !m_spindleEmitted;
            break;
        case 5:
            if (m_spindleDir != 0 || !m_spindleEmitted)
                spindleChanged = true;
            m_spindleDir = 0;
            break;
        case 7:
            coolant = static_cast<int>(CoolantMode::Mist);
            break;
        case 8:
            coolant = static_cast<int>(CoolantMode::Flood);
            break;
        case 9:
            coolant = static_cast<int>(CoolantMode::Off);
            break;
        case 0:
            stop = true;
            break;
        case 1:
            optionalStop = true;
            break;
        case 2:
        case 30:
        case 17:
            end = true;
            break;
        default:
            break;
        }
    }
    if (spindleChanged && (m_spindleDir != 0 || m_spindleEmitted)) {
        emitSpindle(line);
        m_spindleEmitted = true;
    }
    if (coolant >= 0) {
        setSource(line);
        m_sink.coolant(Coolant{static_cast<CoolantMode>(coolant)});
    }
    if (comp >= 0) {
        const CutterCompSide side = comp == 41   ? CutterCompSide::Left
                                    : comp == 42 ? CutterCompSide::Right
                                                 : CutterCompSide::Off;
        if (side != m_modal.comp) {
            m_modal.comp = side;
            setSource(line);
            m_sink.cutterComp(CutterComp{side});
        }
    }
    if (dwell) {
        double seconds = 0;
        if (feed) {
            seconds = *feed;
        } else if (speed) {
            const double rpm = m_modal.constantSurfaceSpeed ? m_lims : m_speed;
            if (rpm <= 0)
                error(p, {line, 0}, "G4 S (revolutions) with no spindle speed");
            else
                seconds = *speed * 60.0 / rpm;
        } else {
            error(p, {line, 0}, "G4 needs F (seconds) or S (revolutions)");
        }
        if (seconds < 0)
            error(p, {line, 0}, "negative dwell time");
        else if (seconds > 0) {
            setSource(line);
            m_sink.dwell(Dwell{seconds});
        }
    }

    // Motion.
    if (motion >= 0 && !dwell)
        m_modal.motion = motion;
    bool moved = false;
    bool anyLinearAxis = axis[0] || axis[1] || axis[2];
    if (axis[3] || axis[4] || axis[5])
        warning(p, {line, 0}, "rotary axes A B C are not traced until the five-axis machine model exists");
    const bool arcWordsGiven = arcWords.centre[0] || arcWords.centre[1] || arcWords.centre[2] || arcWords.cr ||
                               arcWords.ar || arcWords.turn > 0;
    if (!dwell && (anyLinearAxis || (arcWordsGiven && m_modal.motion >= 2))) {
        Vec3 target = m_pos;
        for (int i = 0; i < 3; ++i) {
            if (!axis[i])
                continue;
            double mm = toMm(*axis[i]);
            if (i == 0 && m_modal.diameter)
                mm /= 2;
            const bool incremental =
                axisMode[i] == ValueMode::Incremental || (axisMode[i] == ValueMode::Modal && m_modal.incremental);
            component(target, i) = incremental ? component(m_pos, i) + mm : mm;
        }
        const int m = m_modal.motion;
        const bool mcallPositioning = m_modalCall && m_modalCall->cycle > 0 && !callWord && m == 0 &&
                                      m_modalCall->level == m_stack.size() && target.z == m_pos.z &&
                                      m_modal.plane == 17;
        if (m == 0) {
            if (!mcallPositioning) {
                setSource(line);
                m_sink.rapid(Rapid{target});
            }
            m_pos = target;
            moved = true;
        } else if (m == 1) {
            if (m_feed <= 0)
                error(p, {line, 0}, "G1 without a feed (F)");
            setSource(line);
            m_sink.linear(Linear{target, m_feed});
            m_pos = target;
            moved = true;
        } else {
            if (m_feed <= 0)
                error(p, arcWords.pos, "G" + std::to_string(m) + " without a feed (F)");
            moved = arc(p, target, m == 2, arcWords, line);
        }
    } else if (arcWordsGiven && !dwell) {
        warning(p, {line, 0}, "arc words without G2/G3: ignored");
    }

    if (moved && m_modalCall && !callWord && m_modalCall->level == m_stack.size()) {
        if (m_modalCall->cycle > 0) {
            const ModalCall call = *m_modalCall;
            runCycle(p, call.cycle, call.args, {line, 0}, line);
        } else {
            const ModalCall call = *m_modalCall;
            callProgram(call.name, b, p, 1, call.args);
        }
    }
    if (callWord && callWord->kind == WordKind::Cycle) {
        m_evalFailed = false;
        const auto args = evalArgs(p, b);
        if (!m_evalFailed)
            runCycle(p, callWord->code, args, callWord->pos, line);
    }
    if (stop || optionalStop) {
        setSource(line);
        m_sink.programStop(ProgramStop{!stop});
    }
    if (end || ret) {
        if (m_stack.size() == 1) {
            m_result.completed = true;
            m_stack.clear();
            return false;
        }
        return returnFromCall();
    }
    if (callWord && callWord->kind == WordKind::Call) {
        m_evalFailed = false;
        const auto args = evalArgs(p, b);
        if (m_evalFailed)
            return true;
        int repeats = 1;
        if (b.expr2 >= 0) {
            const auto count = eval(p, b.expr2);
            if (count && *count >= 1 && *count <= 9999)
                repeats = static_cast<int>(*count);
            else
                error(p, callWord->pos, "P (repetitions) must be 1..9999");
        }
        return callProgram(p.texts[static_cast<std::size_t>(callWord->code)], b, p, repeats, args);
    }
    return true;
}

}  // namespace camwb::nc::sinumerik
