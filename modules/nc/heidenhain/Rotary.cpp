// Five-axis Klartext through the machine's kinematic chain (nc/FiveAxis.h): A/B/C words in L blocks,
// tool-tip control with M128 / FUNCTION TCPM (X Y Z the tip in the workpiece frame, the rotary axes
// turning the tool about it) or without it (X Y Z B C the machine's axes), and the moves made while
// the rotary axes are turned, which reach the sink as ToolAxisMove (tip, tool axis, machine angles).
#include "nc/heidenhain/Machine.h"

#include "nc/detail/PlaneAxes.h"

#include <cmath>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

bool isCircle(BlockKind k)
{
    return k == BlockKind::Circle || k == BlockKind::CircleRadius || k == BlockKind::CircleTangent ||
           k == BlockKind::CirclePolar;
}

std::string rotaryUnknownMessage(char axis, std::string_view need)
{
    const std::string name(1, axis);
    return name + " is unknown here: no absolute " + name + " has been programmed yet, and " + std::string(need) +
           " needs it; nothing moves";
}

}  // namespace

// The rotary words of a block: the angles the chain's joints take (or, under AXIS SPAT, the spatial
// angles), with the diagnostics of words the machine cannot read. False: the block is not run.
bool Machine::rotaryTarget(const Block& b, const BlockWords& w, RotaryTarget& target)
{
    target.angles = m_five.angles();
    if (!w.rotary)
        return true;
    const Program& p = program();
    bool ok = true;
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        const int k = static_cast<int>(word.key);
        const bool incremental = k >= static_cast<int>(Key::IA) && k <= static_cast<int>(Key::IW);
        const bool absolute = k >= static_cast<int>(Key::A) && k <= static_cast<int>(Key::W);
        if (!absolute && !incremental)
            continue;
        const auto value = w.axes[static_cast<std::size_t>(k)];
        const int axisIndex = incremental ? k - static_cast<int>(Key::IA) : k - static_cast<int>(Key::A);  // 0 A .. 5 W
        if (axisIndex >= 3) {
            warnOnce(kWarnParallelAxes, b, "parallel axes U, V, W are not traced: their values are ignored");
            continue;
        }
        if (!value)
            continue;  // reported by gather
        const char axis = "ABC"[axisIndex];
        int joint = -1;
        const RotaryAxisUse use = m_five.use(axis, &joint);
        if (use == RotaryAxisUse::NoMachine) {
            warnOnce(kWarnRotary, b,
                     "rotary axes A, B, C need a five-axis machine (--machine, or the NC inspector's Machine) to be "
                     "traced: their values are ignored");
            continue;
        }
        if (use == RotaryAxisUse::NoChain) {
            warnOnce(kWarnNoChain, b, m_five.useMessage(axis, use));
            continue;
        }
        if (use == RotaryAxisUse::Missing) {
            report(Severity::Error, word.line, word.column, m_five.useMessage(axis, use));
            ok = false;
            continue;
        }
        if (isCircle(b.kind)) {
            report(Severity::Error, word.line, word.column,
                   std::string(1, axis) + " in a circle block: circles are traced with the rotary axes standing still");
            ok = false;
            continue;
        }
        if (m_axisSpat) {
            // FUNCTION TCPM AXIS SPAT: A, B, C are spatial angles of the tool, modal like axes.
            double& angle = m_spatial[static_cast<std::size_t>(axisIndex)];
            angle = incremental ? angle + *value : *value;
            target.spatial = true;
            continue;
        }
        const auto angle = m_five.angleFor(joint, *value, incremental ? RotaryMode::Incremental : RotaryMode::Absolute);
        if (!angle) {
            report(Severity::Error, word.line, word.column, rotaryUnknownMessage(axis, "an incremental move"));
            ok = false;
            continue;
        }
        const auto j = static_cast<std::size_t>(joint);
        if (!target.angles.known[j] || std::abs(target.angles.deg[j] - *angle) > 1e-12)
            target.changed = true;
        target.angles.deg[j] = *angle;
        target.angles.known[j] = true;
    }
    if (ok && target.angles.turned() && !target.angles.complete()) {
        const kinematics::KinematicChain& chain = m_five.machine()->kinematics;
        const std::size_t missing = target.angles.known[0] ? 1 : 0;
        report(Severity::Error, b.line, b.column,
               rotaryUnknownMessage(chain.joints[missing].axis[0], "the tool axis with the other rotary axis turned"));
        ok = false;
    }
    // Only a turn that the trace can show is a move of its own: from an unknown angle to 0 the
    // tool is where a 3-axis program has it.
    target.changed = target.changed && (target.angles.turned() || m_five.fiveAxisMove());
    return ok;
}

// A five-axis move needs the whole tip (a ToolAxisMove carries no axis mask) and, for a head
// without tool-tip control, the tool's length.
bool Machine::fiveAxisReady(const Block& b, const RotaryTarget& target, AxisMask given, bool& traced)
{
    using Trace = FiveAxisState::BlockTrace;
    traced = true;
    const bool tipKnown = m_known.missing(kNoAxes, AxisMask{}, given) < 0;
    const Trace trace = m_five.blockTrace(target.angles, target.spatial, tipKnown, given.bits != 0);
    switch (trace) {
    case Trace::ThreeAxis:
        return true;
    case Trace::HomeUntraced:
        traced = false;
        return true;
    case Trace::TipUnknown:
        // After M140 MB MAX the tool is somewhere up its axis: the table may turn there, and the
        // trace shows the tool again once a block gives every axis.
        if (target.spatial)
            return needKnown(b, kNoAxes, AxisMask{}, given, "AXIS SPAT (the tool vector at the tip)");
        warnOnce(kWarnFiveAxisUnknown, b,
                 "a move with the rotary axes turned while X, Y or Z is unknown is not traced (the tool tip is "
                 "unknown); the trace goes on once a block gives every axis");
        traced = false;
        return true;
    case Trace::NeedsToolLength:
    case Trace::FiveAxis:
        break;
    }
    if (target.spatial && !m_five.tcpm()) {
        report(Severity::Error, b.line, b.column, "AXIS SPAT needs tool-tip control (FUNCTION TCPM): nothing moves");
        return false;
    }
    if (trace == Trace::NeedsToolLength) {
        report(Severity::Error, b.line, b.column,
               "the machine's head turns the tool about a pivot above its tip: without tool-tip control the "
               "tool length is needed (TOOL DEF L, or the tool table); nothing moves");
        return false;
    }
    return true;
}

bool Machine::orientSpatial(const Block& b, const Vec3& end)
{
    const Vec3 axis = spatialToolAxis(m_spatial[0], m_spatial[1], m_spatial[2]);
    if (const auto problem = m_five.orient(end, axis)) {
        report(Severity::Error, b.line, b.column, "the spatial angles of AXIS SPAT: " + *problem + "; nothing moves");
        return false;
    }
    return true;
}

void Machine::tcpmFunction(const Block& b)
{
    if (!m_five.active()) {
        if (!b.flag)
            report(Severity::Warning, b.line, b.column,
                   "FUNCTION TCPM: tool-tip control needs a five-axis machine (--machine, or the NC inspector's "
                   "Machine) to be traced; "
                   "positions are traced as three-axis moves");
        return;
    }
    if (b.flag) {
        m_axisSpat = false;
        setTcpm(false);
        return;
    }
    if (b.a & kTcpmRefCenter)
        warnOnce(kWarnTcpmRefCenter, b, "FUNCTION TCPM REFPNT ...-CENTER: X Y Z are traced as the tool tip");
    if ((b.a & kTcpmAxisSpat) && !m_axisSpat)
        m_spatial = {0, 0, 0};
    m_axisSpat = (b.a & kTcpmAxisSpat) != 0;
    setTcpm(true);
}

void Machine::setTcpm(bool on) { m_five.setTcpm(on, m_pos, m_known.complete()); }

void Machine::sendFiveAxis(const Element& e, bool rapid, double feed)
{
    if (m_comp != CutterCompSide::Off)
        warnOnce(kWarnCompTilted, program().blocks[m_pc],
                 "radius compensation RL/RR with the rotary axes turned is not traced: the programmed path is");
    if (e.type == Element::Type::Line) {
        m_sink.toolAxisMove(m_five.move(e.end, rapid ? 0 : feed));
        return;
    }
    const detail::PlaneAxes plane = detail::planeAxes(e.plane);
    Arc arc;
    arc.to = e.end;
    arc.center = detail::withInPlane(e.start, plane, e.center);
    arc.normal = plane.normal;
    arc.clockwise = e.clockwise;
    arc.turns = e.turns;
    arc.feedMmPerMin = feed;
    m_sink.arc(m_five.arcInWorkpiece(arc));
}

// The active tool's length for a head's kinematics: TOOL DEF L, else the tool table's, plus DL of
// the TOOL CALL; unknown when neither gives one.
void Machine::updateToolLength()
{
    std::optional<double> length;
    if (const auto it = m_toolLength.find(m_tool); it != m_toolLength.end())
        length = it->second;
    else if (m_options.toolTable)
        if (const ToolTableEntry* entry = m_options.toolTable->find(m_tool))
            length = entry->lengthMm;
    m_five.setToolLength(length ? std::optional<double>(*length + m_deltaLength) : std::nullopt);
}

}  // namespace camwb::nc::heidenhain
