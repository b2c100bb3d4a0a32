// One ordinary block: its words are read in order (ExecuteWords.cpp; assignments take effect at
// once), then the block acts group by group in the control's order: units, distance mode, plane,
// work offset, feed mode, feed, tool, spindle, coolant, compensation, dwell, the motion, a modal
// or direct cycle call, stops, the end or return, and a subprogram call. The steps have the names
// of the ISO interpreter's (IsoMachine.h), which follows LinuxCNC's order of execution.
#include "nc/sinumerik/Machine.h"

#include "base/NumberFormat.h"

#include <cmath>

namespace camwb::nc::sinumerik {

namespace {

using namespace camwb::toolpath;

constexpr double kMaxValue = 99999.999;  // the control's input range for positions (mm or inch)

double& component(Vec3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }
double component(const Vec3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

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
    error(p, pos, "value " + base::formatGeneral(value, 10) + " outside the control's range (+-99999.999)");
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
    case AssignTarget::ToolData: {
        const auto tool = eval(p, w.expr2);
        const auto edge = tool ? eval(p, w.expr3) : std::nullopt;
        if (!tool || !edge)
            return;
        if (!(*tool >= 0 && *tool <= 32000 && *edge >= 1 && *edge <= 32000)) {
            error(p, w.pos, "$TC_DP: tool 0..32000 and cutting edge 1..32000 expected");
            return;
        }
        EdgeData& data = m_edges[{static_cast<int>(*tool), static_cast<int>(*edge)}];
        if (w.code == 6)
            data.radius = value;
        else if (w.code == 15)
            data.radiusWear = value;
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
    BlockWords w;
    w.arc.pos = {b.line, 0};
    w.line = b.line;
    w.callWord = b.callWord >= 0 ? &p.words[static_cast<std::size_t>(b.callWord)] : nullptr;
    if (!readWords(p, b, w))
        return false;  // SETAL: the program stops
    if (m_evalFailed)
        return true;  // reported; the block is left out

    // The control's order within a block (the modal groups first, as LinuxCNC orders them too).
    applyUnits(w);
    applyDistanceMode(w);
    applyPlane(w);
    applyWorkOffset(p, w);
    applyFeedMode(w);
    applyFeedRate(w);
    applyToolChange(w);
    applyToolOffset(p, w);
    applySpindle(p, w);
    applyCoolant(w);
    applyCompensation(w);
    applyDwell(p, w);
    applyTransformation(p, w);
    const bool moved = applyMotion(p, w);
    applyCalls(p, b, w, moved);
    return applyStop(p, b, w);
}

void Machine::applyUnits(const BlockWords& w)
{
    if (w.units)
        m_modal.unitsCode = w.units;
    if (w.units == 70 || w.units == 700) {
        m_modal.inch = true;
        m_modal.inchFeed = w.units == 700;
    } else if (w.units == 71 || w.units == 710) {
        m_modal.inch = false;
        m_modal.inchFeed = false;
    }
}

void Machine::applyDistanceMode(const BlockWords& w)
{
    if (w.absInc)
        m_modal.incremental = w.absInc == 91;
}

void Machine::applyPlane(const BlockWords& w)
{
    if (w.plane)
        m_modal.plane = w.plane;
}

void Machine::applyWorkOffset(const Program& p, const BlockWords& w)
{
    if (w.workOffset >= 0 && w.workOffset != m_modal.workOffset) {
        m_modal.workOffset = w.workOffset;
        setSource(w.line);
        m_sink.workOffset(WorkOffset{w.workOffset});
    }
}

void Machine::applyFeedMode(const BlockWords& w)
{
    if (w.feedMode == 93)
        setFeedMode(FeedMode::InverseTime, w.line);
    else if (w.feedMode == 94)
        setFeedMode(FeedMode::PerMinute, w.line);
    else if (w.feedMode == 95 || w.css == 1)
        setFeedMode(FeedMode::PerRevolution, w.line);  // G96 switches to revolutional feed with it
}

void Machine::applyFeedRate(const BlockWords& w)
{
    if (w.feed && !w.dwell)
        m_feed = feedToInternal(*w.feed);
}

// M6 changes to the selected tool; without any M6 in the program T changes at once.
void Machine::applyToolChange(const BlockWords& w)
{
    bool toolChange = false;
    if (w.tool) {
        m_tool = static_cast<int>(std::lround(*w.tool));
        if (!m_toolChangeOnM6)
            toolChange = true;
    }
    for (int i = 0; i < w.mCount; ++i)
        if (w.m[i] == 6)
            toolChange = true;
    if (!toolChange)
        return;
    m_activeTool = m_tool;
    m_edge = 1;  // the control's default cutting edge after a change ($MC_CUTTING_EDGE_DEFAULT)
    ToolChange tc;
    tc.tool.number = m_tool;
    tc.tool.name = m_toolName;
    const ToolTableEntry* entry = m_options.toolTable ? m_options.toolTable->find(m_tool) : nullptr;
    m_five.setToolLength(entry ? std::optional<double>(entry->lengthMm) : std::nullopt);
    setSource(w.line);
    m_sink.toolChange(tc);
}

// S, G96/G97 with LIMS, and M3/M4/M5: one Spindle record when any of them changed.
void Machine::applySpindle(const Program& p, const BlockWords& w)
{
    bool spindleChanged = false;
    if (w.css >= 0 && (w.css == 1) != m_modal.constantSurfaceSpeed) {
        m_modal.constantSurfaceSpeed = w.css == 1;
        spindleChanged = w.css == 1 || w.speed.has_value();
    }
    if (w.lims) {
        m_lims = *w.lims;
        spindleChanged = spindleChanged || m_modal.constantSurfaceSpeed;
    }
    if (w.speed && !(w.dwell && !w.feed)) {
        if (*w.speed < 0) {
            error(p, {w.line, 0}, "negative spindle speed");
        } else if (*w.speed != m_speed) {
            m_speed = *w.speed;
            spindleChanged = true;
        }
    }
    for (int i = 0; i < w.mCount; ++i) {
        const int m = w.m[i];
        if (m == 3 || m == 4) {
            if (m_spindleDir != m)
                spindleChanged = true;
            m_spindleDir = m;
            spindleChanged = spindleChanged || !m_spindleEmitted;
        } else if (m == 5) {
            if (m_spindleDir != 0 || !m_spindleEmitted)
                spindleChanged = true;
            m_spindleDir = 0;
        }
    }
    if (spindleChanged && (m_spindleDir != 0 || m_spindleEmitted)) {
        emitSpindle(w.line);
        m_spindleEmitted = true;
    }
}

void Machine::applyCoolant(const BlockWords& w)
{
    int coolant = -1;
    for (int i = 0; i < w.mCount; ++i) {
        if (w.m[i] == 7)
            coolant = static_cast<int>(CoolantMode::Mist);
        else if (w.m[i] == 8)
            coolant = static_cast<int>(CoolantMode::Flood);
        else if (w.m[i] == 9)
            coolant = static_cast<int>(CoolantMode::Off);
    }
    if (coolant >= 0) {
        setSource(w.line);
        m_sink.coolant(Coolant{static_cast<CoolantMode>(coolant)});
    }
}

// D<n>: the cutting edge whose offsets (the radius among them) apply from now on; D0: none.
void Machine::applyToolOffset(const Program& p, const BlockWords& w)
{
    if (!w.edge)
        return;
    if (*w.edge < 0 || *w.edge > 32000 || *w.edge != std::trunc(*w.edge)) {
        error(p, {w.line, 0}, "D (cutting edge) must be a whole number 0..32000");
        return;
    }
    m_edge = static_cast<int>(*w.edge);
}

void Machine::applyCompensation(const BlockWords& w)
{
    if (w.corners)
        m_compensation.setOutsideIntersection(w.corners == 451);
    if (w.comp < 0)
        return;
    const CutterCompSide side = w.comp == 41   ? CutterCompSide::Left
                                : w.comp == 42 ? CutterCompSide::Right
                                               : CutterCompSide::Off;
    if (side != m_modal.comp) {
        if (side != CutterCompSide::Off)
            setCompensationRadius();
        m_modal.comp = side;
        setSource(w.line);
        m_sink.cutterComp(CutterComp{side});
    }
}

// The radius of the active tool's cutting edge: $TC_DP6 (+ $TC_DP15 wear) where the program set
// it, else the tool table's; D0 compensates nothing.
void Machine::setCompensationRadius()
{
    const int tool = m_toolChangeOnM6 ? m_activeTool : m_tool;
    const std::string what = "T" + std::to_string(tool) + " D" + std::to_string(m_edge);
    if (m_edge == 0) {
        m_compensation.setRadius(0.0, what);
        return;
    }
    if (const auto it = m_edges.find({tool, m_edge}); it != m_edges.end() && it->second.radius) {
        m_compensation.setRadius(*it->second.radius + it->second.radiusWear, what);
        return;
    }
    m_compensation.setRadius(m_options.toolTable ? m_options.toolTable->radiusOf(tool) : std::nullopt, what);
}

void Machine::applyDwell(const Program& p, const BlockWords& w)
{
    if (!w.dwell)
        return;
    const int line = w.line;
    double seconds = 0;
    if (w.feed) {
        seconds = *w.feed;
    } else if (w.speed) {
        const double rpm = m_modal.constantSurfaceSpeed ? m_lims : m_speed;
        if (rpm <= 0)
            error(p, {line, 0}, "G4 S (revolutions) with no spindle speed");
        else
            seconds = *w.speed * 60.0 / rpm;
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

// The block's end point from its axis words (inch, diameter, absolute or incremental per word).
Vec3 Machine::blockTarget(const BlockWords& w) const
{
    Vec3 target = m_pos;
    for (int i = 0; i < 3; ++i) {
        if (!w.axis[i])
            continue;
        double mm = toMm(*w.axis[i]);
        if (i == 0 && m_modal.diameter)
            mm /= 2;
        const bool incremental =
            w.axisMode[i] == ValueMode::Incremental || (w.axisMode[i] == ValueMode::Modal && m_modal.incremental);
        component(target, i) = incremental ? component(m_pos, i) + mm : mm;
    }
    return target;
}

bool Machine::needKnown(const Program& p, const BlockWords& w, AxisMask before, AxisMask after, AxisMask given,
                        const char* need, Pos fallback)
{
    const int axis = m_known.missing(before, after, given);
    if (axis < 0)
        return true;
    const std::size_t i = static_cast<std::size_t>(axis);
    error(p, w.axis[i] ? w.axisPos[i] : fallback, unknownAxisMessage(axis, need));
    return false;
}

// An incremental word on an unknown axis, an arc or compensation from an unknown start are
// errors; `given`: the axes the block writes in absolute terms.
bool Machine::checkKnown(const Program& p, const BlockWords& w, AxisMask& given)
{
    AxisMask incremental = kNoAxes;
    given = kNoAxes;
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (!w.axis[k])
            continue;
        const bool inc =
            w.axisMode[k] == ValueMode::Incremental || (w.axisMode[k] == ValueMode::Modal && m_modal.incremental);
        (inc ? incremental : given).bits |= axisBit(i).bits;
    }
    const Pos at{w.line, 0};
    if (!needKnown(p, w, incremental, kNoAxes, kNoAxes, "an incremental move", at))
        return false;
    if (m_modal.motion >= 2)
        return needKnown(p, w, planeMask(m_modal.plane), AxisMask{}, given, "the arc", w.arc.pos);
    return m_modal.comp == CutterCompSide::Off ||
           needKnown(p, w, kXyAxes, AxisMask{}, given, "cutter compensation", at);
}

// Machine axes moved to a place the trace cannot put in the work offset's frame: unknown from
// here, all three with the rotary axes turned (a machine axis then moves the tip along a turned
// direction). True: they were turned.
bool Machine::loseMachineAxes(int line, AxisMask axes)
{
    const bool turned = m_five.active() && m_five.fiveAxisMove();
    setSource(line);
    m_known.lose(turned ? AxisMask{AxisMask::kAll} : axes, m_sink);
    if (turned)
        m_five.moveUntraced();
    return turned;
}

// G53 / G153 / SUPA X.. Y.. Z..: machine coordinates, whose place in the work offset's frame the
// trace does not know (the offsets are the control's). The axes the block gives are unknown after
// it, and with the rotary axes turned all three are (a machine axis then moves the tip along a
// turned direction), until a block gives them again; nothing is drawn meanwhile.
bool Machine::moveInMachineCoordinates(const Program& p, const BlockWords& w)
{
    AxisMask moved{0};
    for (int i = 0; i < 3; ++i)
        if (w.axis[static_cast<std::size_t>(i)])
            moved.bits |= axisBit(i).bits;
    const bool turned = loseMachineAxes(w.line, moved);
    if (!m_warnedMachineCoordinates) {
        m_warnedMachineCoordinates = true;
        warning(p, {w.line, 0},
                std::string("G53/G153/SUPA: a move in machine coordinates is not traced (the work offset is the "
                            "control's); ") +
                    (turned ? "X, Y and Z are" : "the axes it gives are") + " unknown until a block gives them");
    }
    return false;
}

// G74 X1=0 Z1=0 (reference point) and G75 FP=n X1=0 ... (fixed point n, e.g. the tool change
// position): the machine axes named go to places in machine coordinates the trace cannot place in
// the work offset's frame, so those axes are unknown after the block until a block gives them, as
// after SUPA. A machine axis word without G74/G75 moves an axis the trace has no frame for.
bool Machine::approachFixedPoint(const Program& p, const BlockWords& w)
{
    if (!w.approach) {
        error(p, w.machineAxisPos, "machine axes (X1=, Y1=, Z1=) are read with G74 or G75 only");
        return false;
    }
    if (w.machineAxes.none()) {
        error(p, {w.line, 0}, "G" + std::to_string(w.approach) + " names no machine axis (X1=0, Y1=0, Z1=0)");
        return false;
    }
    loseMachineAxes(w.line, w.machineAxes);
    if (!m_warnedApproach) {
        m_warnedApproach = true;
        warning(p, {w.line, 0},
                std::string(w.approach == 74 ? "G74 (reference point approach)" : "G75 (fixed point approach)") +
                    " is not traced (the point is the machine's); the axes it moves are unknown until a block "
                    "gives them");
    }
    return false;
}

bool Machine::applyMotion(const Program& p, const BlockWords& w)
{
    const int line = w.line;
    if (w.approach || !w.machineAxes.none())
        return approachFixedPoint(p, w);
    if (w.motion >= 0 && !w.dwell)
        m_modal.motion = w.motion;
    const bool anyLinearAxis = w.axis[0] || w.axis[1] || w.axis[2];
    RotaryMove rotary;
    if (!rotaryTarget(p, w, rotary))
        return false;
    const ArcWords& arcWords = w.arc;
    const bool arcWordsGiven = arcWords.centre[0] || arcWords.centre[1] || arcWords.centre[2] || arcWords.cr ||
                               arcWords.ar || arcWords.turn > 0;
    if (w.dwell || !(anyLinearAxis || rotary.moves || (arcWordsGiven && m_modal.motion >= 2))) {
        if (arcWordsGiven && !w.dwell)
            warning(p, {line, 0}, "arc words without G2/G3: ignored");
        return false;
    }
    if (w.g53 && anyLinearAxis)
        return moveInMachineCoordinates(p, w);
    AxisMask given;
    bool traced = true;
    if (!checkKnown(p, w, given) || !fiveAxisReady(p, w, rotary, given, traced))
        return false;
    const Vec3 target = blockTarget(w);
    if (!turnTo(p, w, rotary, target))
        return false;
    if (m_five.inPlane() && !anyLinearAxis)
        return false;  // in a swivelled plane the rotary axes alone turn; the tip stays in the plane
    const int m = m_modal.motion;
    if (m < 2)
        m_known.give(given);
    if (!traced) {
        m_pos = target;  // the axes the block gave; the others stay unknown
        m_five.moveUntraced();
        return false;
    }
    if (m < 2 && m_five.active() && m_five.fiveAxisMove())
        return moveFiveAxis(p, w, target);
    if (m == 0) {
        const bool mcallPositioning = m_modalCall && m_modalCall->cycle > 0 && !w.callWord &&
                                      m_modalCall->level == m_stack.size() && target.z == m_pos.z &&
                                      m_modal.plane == 17;
        if (!mcallPositioning) {
            setSource(line);
            m_sink.rapid(Rapid{target, m_known.mask()});
        }
        m_pos = target;
        return true;
    }
    if (m == 1) {
        if (m_feed <= 0)
            error(p, {line, 0}, "G1 without a feed (F)");
        setSource(line);
        m_sink.linear(Linear{target, m_feed, m_known.mask()});
        m_pos = target;
        return true;
    }
    if (m_feed <= 0)
        error(p, arcWords.pos, "G" + std::to_string(m) + " without a feed (F)");
    return arc(p, target, m == 2, arcWords, line);
}

// A modal call (MCALL) after a move, then a cycle called in the block itself.
void Machine::applyCalls(const Program& p, const Block& b, const BlockWords& w, bool moved)
{
    if (moved && m_modalCall && !w.callWord && m_modalCall->level == m_stack.size()) {
        const ModalCall call = *m_modalCall;
        if (call.cycle > 0)
            runCycle(p, call.cycle, call.args, {w.line, 0}, w.line);
        else
            callProgram(call.name, b, p, 1, call.args);
    }
    if (w.callWord && w.callWord->kind == WordKind::Cycle) {
        m_evalFailed = false;
        const auto args = evalArgs(p, b);
        if (!m_evalFailed)
            runCycle(p, w.callWord->code, args, w.callWord->pos, w.line);
    }
}

// M0/M1, the end of the program or a return (M2, M30, M17, RET), and a subprogram call.
bool Machine::applyStop(const Program& p, const Block& b, const BlockWords& w)
{
    bool stop = false, optionalStop = false, end = w.ret;
    for (int i = 0; i < w.mCount; ++i) {
        const int m = w.m[i];
        stop = stop || m == 0;
        optionalStop = optionalStop || m == 1;
        end = end || m == 2 || m == 30 || m == 17;
    }
    if (stop || optionalStop) {
        setSource(w.line);
        m_sink.programStop(ProgramStop{!stop});
    }
    if (end) {
        if (m_stack.size() == 1) {
            m_result.completed = true;
            m_stack.clear();
            return false;
        }
        return returnFromCall();
    }
    const Word* callWord = w.callWord;
    if (!callWord || callWord->kind != WordKind::Call)
        return true;
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

}  // namespace camwb::nc::sinumerik
