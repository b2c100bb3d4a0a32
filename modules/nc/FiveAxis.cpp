#include "nc/FiveAxis.h"

#include "base/NumberFormat.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace camwb::nc {

using kinematics::MachinePose;
using kinematics::ToolPose;
using toolpath::Vec3;

namespace {

constexpr double kTurnedDeg = 1e-9;

// The difference `d` in degrees as the shorter way round, in (-180, 180].
double shorterWay(double d)
{
    d = std::fmod(d, 360.0);
    if (d > 180)
        d -= 360;
    else if (d <= -180)
        d += 360;
    return d;
}

// How far from `from` to the angle `to` in the positive sense, in [0, 360).
double positiveWay(double from, double to)
{
    double d = std::fmod(to - from, 360.0);
    return d < 0 ? d + 360 : d;
}

}  // namespace

bool JointAngles::turned() const
{
    for (int i = 0; i < 2; ++i) {
        if (known[static_cast<std::size_t>(i)] && std::abs(deg[static_cast<std::size_t>(i)]) > kTurnedDeg)
            return true;
    }
    return false;
}

FiveAxisState::BlockTrace FiveAxisState::blockTrace(const JointAngles& target, bool orientation, bool tipKnown,
                                                    bool linearGiven) const
{
    if ((m_inPlane && !orientation) || !active() || !(target.turned() || fiveAxisMove() || orientation))
        return BlockTrace::ThreeAxis;
    if (!tipKnown)
        return target.atHome() && !linearGiven ? BlockTrace::HomeUntraced : BlockTrace::TipUnknown;
    if (needsToolLength() && !toolLengthKnown())
        return BlockTrace::NeedsToolLength;
    return BlockTrace::FiveAxis;
}

bool JointAngles::atHome() const
{
    for (std::size_t i = 0; i < 2; ++i) {
        if (known[i] && std::abs(std::remainder(deg[i], 360.0)) > kTurnedDeg)
            return false;
    }
    return true;
}

FiveAxisState::FiveAxisState(const kinematics::Machine* machine) : m_machine(machine)
{
    if (machine && machine->kinematics.fiveAxis())
        m_chain = &machine->kinematics;
}

FiveAxisState::~FiveAxisState() = default;

RotaryAxisUse FiveAxisState::use(char axis, int* joint) const
{
    if (!m_machine)
        return RotaryAxisUse::NoMachine;
    const std::string name(1, axis);
    if (!m_machine->axis(name))
        return RotaryAxisUse::Missing;
    if (m_chain) {
        for (std::size_t i = 0; i < m_chain->joints.size(); ++i) {
            if (m_chain->joints[i].axis == name) {
                if (joint)
                    *joint = static_cast<int>(i);
                return RotaryAxisUse::Traced;
            }
        }
    }
    return RotaryAxisUse::NoChain;
}

std::string FiveAxisState::useMessage(char axis, RotaryAxisUse use) const
{
    const std::string name(1, axis);
    const std::string machine = m_machine ? (m_machine->name.empty() ? m_machine->id : m_machine->name) : "";
    switch (use) {
    case RotaryAxisUse::NoMachine:
        return "rotary axis " + name +
               " without a machine (--machine, or the NC inspector's Machine) to read it through: its value is ignored";
    case RotaryAxisUse::Missing:
        return "the " + machine + " has no " + name + " axis";
    case RotaryAxisUse::NoChain:
        return "the machine file of the " + machine + " gives no five-axis kinematic chain for " + name +
               ": its value is ignored";
    case RotaryAxisUse::Traced:
        break;
    }
    return {};
}

std::optional<double> FiveAxisState::angleFor(int joint, double value, RotaryMode mode) const
{
    const auto j = static_cast<std::size_t>(joint);
    const bool known = m_angles.known[j];
    const double from = m_angles.deg[j];
    const kinematics::Axis* axis = m_machine ? m_machine->axis(m_chain->joints[j].axis) : nullptr;
    const bool endless = axis && axis->endless;
    switch (mode) {
    case RotaryMode::Absolute:
        // M126 turns an axis whose display is reduced to 0..360 the shorter way (iTNC 530 User's
        // Manual, "Shorter-path traverse of rotary axes: M126"): C355 -> C5 is +10, traced as 365.
        if (m_shortestPath && endless && known)
            return from + shorterWay(value - from);
        return value;
    case RotaryMode::Incremental:
        return known ? std::optional<double>(from + value) : std::nullopt;
    case RotaryMode::Shortest:
        return known ? from + shorterWay(value - from) : value;
    case RotaryMode::Positive:
        return known ? from + positiveWay(from, value) : value;
    case RotaryMode::Negative:
        return known ? from - positiveWay(value, from) : value;
    }
    return value;
}

bool FiveAxisState::needsToolLength() const
{
    if (!m_chain || m_tcpm)
        return false;
    for (const kinematics::RotaryJoint& j : m_chain->joints) {
        if (!j.onTable)
            return true;
    }
    return false;
}

MachinePose FiveAxisState::pose(const Vec3& linear) const
{
    MachinePose p;
    p.linear = linear;
    p.rotaryDeg = m_angles.deg;
    return p;
}

void FiveAxisState::setTcpm(bool on, Vec3& programmed, bool linearKnown)
{
    if (on == m_tcpm)
        return;
    if (m_chain && m_angles.complete() && m_angles.turned() && linearKnown) {
        // The tool stays; what the program calls its position changes frame.
        const Vec3 tip = toolPose(programmed).tip;
        m_tcpm = on;
        programmed = programmedFor(tip);
    }
    m_tcpm = on;
}

Vec3 FiveAxisState::programmedFor(const Vec3& tip) const
{
    if (m_tcpm)
        return tip;
    return kinematics::linearAxesFor(*m_chain, tip, m_angles.deg, m_toolLength.value_or(0)) - m_chain->workpieceZero;
}

ToolPose FiveAxisState::toolPose(const Vec3& programmed) const
{
    const double length = m_toolLength.value_or(0);
    if (m_tcpm) {
        // The tip is programmed; the angles give the axis wherever the linear axes are.
        ToolPose t = kinematics::forwardKinematics(*m_chain, pose(m_chain->workpieceZero), length);
        t.tip = programmed;
        return t;
    }
    return kinematics::forwardKinematics(*m_chain, pose(programmed + m_chain->workpieceZero), length);
}

std::variant<FiveAxisState::TravelEnd, std::string> FiveAxisState::travelEnd(const Vec3& tip,
                                                                             const Vec3& direction) const
{
    std::array<double, 2> deg{0, 0};
    bool head = false;
    for (std::size_t i = 0; i < 2; ++i) {
        deg[i] = m_angles.known[i] ? m_angles.deg[i] : 0;
        head = head || !m_chain->joints[i].onTable;
    }
    if (head && !m_toolLength && (std::abs(deg[0]) > kTurnedDeg || std::abs(deg[1]) > kTurnedDeg))
        return std::string("the tool length is unknown (TOOL DEF L, or the tool table), and the turned head's axes "
                           "depend on it");
    const double length = m_toolLength.value_or(0);
    // The machine's axes move linearly with the tip: from `from`, `step` per millimetre.
    const Vec3 from = kinematics::linearAxesFor(*m_chain, tip, deg, length);
    const Vec3 step = kinematics::linearAxesFor(*m_chain, tip + direction, deg, length) - from;
    const auto component = [](const Vec3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; };
    std::optional<TravelEnd> end;
    for (int i = 0; i < 3; ++i) {
        const std::string name(1, "XYZ"[i]);
        const kinematics::Axis* axis = m_machine->axis(name);
        const double rate = component(step, i);
        if (!axis || axis->rotary || axis->endless || axis->max <= axis->min || std::abs(rate) < 1e-9)
            continue;  // no travel given, or the axis does not move
        const double at = component(from, i);
        const double limit = rate > 0 ? axis->max : axis->min;
        const double distance = (limit - at) / rate;
        if (distance < -1e-6)
            return name + " stands at " + base::formatFixed(at, 3) + ", past the end of its travel at " +
                   base::formatFixed(limit, 3) + " (the machine file's workpieceZero places the workpiece)";
        if (!end || distance < end->distanceMm)
            end = TravelEnd{std::max(0.0, distance), name};
    }
    if (!end)
        return std::string("no linear axis with a travel limit moves along the tool axis");
    return *end;
}

toolpath::RotaryAxes FiveAxisState::machineAxes() const
{
    toolpath::RotaryAxes r;
    if (!m_chain)
        return r;
    for (std::size_t i = 0; i < m_chain->joints.size() && i < 2; ++i)
        if (m_angles.known[i])
            r.set(m_chain->joints[i].axis, m_angles.deg[i]);
    return r;
}

toolpath::ToolAxisMove FiveAxisState::move(const Vec3& programmed, double feedMmPerMin)
{
    const ToolPose t = toolPose(programmed);
    toolpath::ToolAxisMove m;
    m.tip = t.tip;
    m.axis = t.axis.normalized();
    m.feedMmPerMin = feedMmPerMin;
    m.machine = machineAxes();
    m.jointInterpolated = !m_tcpm;
    m_lastSentTurned = m_angles.turned();
    return m;
}

toolpath::Arc FiveAxisState::arcInWorkpiece(const toolpath::Arc& programmed)
{
    m_lastSentTurned = m_angles.turned();
    if (m_tcpm || !m_chain)
        return programmed;
    toolpath::Arc a = programmed;
    const Vec3 centre = toolPose(programmed.center).tip;
    a.to = toolPose(programmed.to).tip;
    a.center = centre;
    a.normal = (toolPose(programmed.center + programmed.normal).tip - centre).normalized();
    return a;
}

kinematics::PoseSolver& FiveAxisState::solver() const
{
    const double length = m_toolLength.value_or(0);
    if (!m_solver || m_solverToolLength != length) {
        m_solver = std::make_unique<kinematics::PoseSolver>(*m_machine, length);
        m_solverToolLength = length;
    }
    return *m_solver;
}

void FiveAxisState::setInPlane(bool tilted)
{
    m_inPlane = tilted;
    // The plane's moves were 3-axis records: the first move after it starts from no turned pose.
    m_lastSentTurned = false;
}

toolpath::WorkingPlane FiveAxisState::planeOfAngles(const std::array<double, 2>& deg) const
{
    const kinematics::TiltedAxes axes = kinematics::tiltedAxes(*m_chain, deg);
    toolpath::WorkingPlane plane;
    plane.xAxis = axes.x.normalized();
    plane.zAxis = axes.z.normalized();
    return plane;
}

Vec3 FiveAxisState::reframe(const toolpath::WorkingPlane& old, const toolpath::WorkingPlane& next,
                            const Vec3& programmed) const
{
    const bool machineAxes = m_chain && !m_tcpm && m_angles.complete() && m_angles.turned();
    const Vec3 tip = old.tilted() ? old.toWorkpiece(programmed) : machineAxes ? toolPose(programmed).tip : programmed;
    return next.tilted() ? next.toLocal(tip) : machineAxes ? programmedFor(tip) : tip;
}

Vec3 FiveAxisState::toolAxis() const { return toolPose(Vec3{}).axis.normalized(); }

std::optional<std::string> FiveAxisState::orientPlane(const Vec3& axis, int branch)
{
    const MachinePose previous = pose(Vec3{});
    const ToolPose tool{Vec3{}, axis.normalized()};
    const std::vector<kinematics::PoseCandidate> candidates =
        solver().candidates(tool, m_angles.complete() ? &previous : nullptr);
    const kinematics::PoseCandidate* chosen = nullptr;
    double nearest = 0;
    for (const kinematics::PoseCandidate& c : candidates) {
        if (branch != 0 && c.branch != 0 && c.branch != branch)
            continue;
        double travel = 0;
        for (std::size_t j = 0; j < 2; ++j)
            travel +=
                m_angles.known[j] ? std::abs(c.pose.rotaryDeg[j] - m_angles.deg[j]) : std::abs(c.pose.rotaryDeg[j]);
        if (!chosen || travel < nearest) {
            chosen = &c;
            nearest = travel;
        }
    }
    if (!chosen)
        return orient(Vec3{}, axis);  // no pose on that branch: the solver's choice, or its reason
    m_angles.deg = chosen->pose.rotaryDeg;
    m_angles.known = {true, true};
    return std::nullopt;
}

std::optional<std::string> FiveAxisState::orient(const Vec3& tip, const Vec3& axis)
{
    const MachinePose previous = pose(tip);
    const auto solved = solver().solve(ToolPose{tip, axis.normalized()}, m_angles.complete() ? &previous : nullptr);
    if (!solved)
        return solved.error().message;
    m_angles.deg = solved.value().pose.rotaryDeg;
    m_angles.known = {true, true};
    return std::nullopt;
}

Vec3 spatialToolAxis(double aDeg, double bDeg, double cDeg)
{
    const double k = std::numbers::pi / 180;
    const double a = aDeg * k, b = bDeg * k, c = cDeg * k;
    // Rz(c) * Ry(b) * Rx(a) * (0, 0, 1)
    const Vec3 afterA{0, -std::sin(a), std::cos(a)};
    const Vec3 afterB{afterA.x * std::cos(b) + afterA.z * std::sin(b), afterA.y,
                      -afterA.x * std::sin(b) + afterA.z * std::cos(b)};
    return {afterB.x * std::cos(c) - afterB.y * std::sin(c), afterB.x * std::sin(c) + afterB.y * std::cos(c), afterB.z};
}

}  // namespace camwb::nc
