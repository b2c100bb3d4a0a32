#include "sim/MotionPlan.h"

#include "sim/MachineAxes.h"

#include "base/Prefault.h"

#include <algorithm>
#include <cmath>
#include <limits>

// The look-ahead, and why it is honest: every move gets a trapezoid (constant acceleration up to
// a cruise speed, constant deceleration), the speed at each junction is capped by (1) both moves'
// cruise speeds, (2) a per-axis velocity step at the corner no larger than the axis' acceleration
// over one interpolation cycle (PlanOptions::cornerStepSeconds), and (3) what a backward pass and a
// forward pass over the whole program allow, so that every move can brake to the next junction and
// none is entered faster than the previous one could accelerate to. Nothing leaves a move faster
// than it can stop by the end of the program. What it ignores: jerk (real profiles are S-shaped,
// so short moves take a little longer), the control's smoothing filters and tolerance-based corner
// blending (which pass corners faster than rule 2), and the curvature term of the axis
// accelerations inside a five-axis move (the axis limits use the axes' rates at the move's quarter
// points). Its cycle time is therefore a plan a control could follow, not a prediction of one.

namespace camwb::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kAxes = 5;  // X Y Z and the chain's two rotaries
using AxisVector = std::array<double, kAxes>;

struct AxisLimits {
    AxisVector velocity{};      // per second
    AxisVector acceleration{};  // per second squared
    int count = 3;
};

AxisLimits axisLimits(const kinematics::Machine& machine)
{
    AxisLimits limits;
    auto fill = [&](int k, const std::string& name, bool rotary) {
        const kinematics::Axis* a = machine.axis(name);
        const double fallbackVelocity =
            rotary ? kinematics::kDefaultRotaryDegPerMin : kinematics::estimateRapidMmPerMin(&machine);
        limits.velocity[k] = (a != nullptr && a->maxVelocity > 0 ? a->maxVelocity : fallbackVelocity) / 60.0;
        limits.acceleration[k] = a != nullptr && a->maxAcceleration > 0 ? a->maxAcceleration
                                 : rotary                               ? kinematics::kDefaultRotaryAccelerationDegPerS2
                                                                        : kinematics::kDefaultLinearAccelerationMmPerS2;
    };
    fill(0, "X", false);
    fill(1, "Y", false);
    fill(2, "Z", false);
    if (machine.kinematics.fiveAxis()) {
        limits.count = 5;
        fill(3, machine.kinematics.joints[0].axis, true);
        fill(4, machine.kinematics.joints[1].axis, true);
    }
    return limits;
}

AxisVector axesOf(const kinematics::MachinePose& pose)
{
    return {pose.linear.x, pose.linear.y, pose.linear.z, pose.rotaryDeg[0], pose.rotaryDeg[1]};
}

// A move's geometry on the machine: its parameter length and the axes' rates along it (axis
// units per parameter unit) at its start and end, and the speed and acceleration caps they set.
struct MoveGeometry {
    double length = 0;
    bool rotationOnly = false;
    AxisVector startRate{}, endRate{};
    double velocityCap = kInf;
    double accelerationCap = kInf;
};

class GeometryWalker {
public:
    GeometryWalker(const MoveList& list, const kinematics::Machine& machine) :
        m_list(list),
        m_chain(machine.kinematics),
        m_limits(axisLimits(machine))
    {
    }
    const AxisLimits& limits() const { return m_limits; }

    MoveGeometry measure(const Move& move)
    {
        MoveGeometry g;
        if (!move.moves() || !move.positionKnown)
            return g;
        if (move.tool != m_toolNumber) {
            const toolpath::Tool* tool = m_list.tool(move.tool);
            m_toolNumber = move.tool;
            m_toolLength = tool != nullptr ? tool->lengthMm : 0;
        }
        // A three-axis chain maps the tip linearly: one piece. A five-axis move is looked at in
        // quarters, so a rotary axis that turns fast in the middle still caps the speed.
        const bool fiveAxis = m_chain.fiveAxis();
        const int pieces = fiveAxis ? kRotaryPiecesPerMove : 1;
        std::array<AxisVector, kRotaryPiecesPerMove + 1> q{};
        for (int p = 0; p <= pieces; ++p) {
            // Three axes: where the last move ended (with the same tool) is where this one starts.
            if (p == 0 && !fiveAxis && m_endKnown && move.from == m_endTip && m_toolLength == m_endToolLength) {
                q[0] = m_endAxes;
                continue;
            }
            const auto pose = machinePoseAt(m_chain, move, double(p) / pieces, m_previous, m_toolLength);
            q[p] = axesOf(pose);
            m_previous = pose.rotaryDeg;
        }
        m_endKnown = true, m_endTip = move.to, m_endToolLength = m_toolLength, m_endAxes = q[pieces];
        g.length = move.lengthMm();
        if (g.length < 1e-9) {
            g.length = 0;
            for (int k = 3; k < m_limits.count; ++k)
                g.length = std::max(g.length, std::abs(q[pieces][k] - q[0][k]));
            g.rotationOnly = g.length > 1e-9;
            if (!g.rotationOnly)
                return MoveGeometry{};
        }
        const double pieceLength = g.length / pieces;
        for (int p = 0; p < pieces; ++p) {
            AxisVector rate{};
            for (int k = 0; k < m_limits.count; ++k) {
                rate[k] = (q[p + 1][k] - q[p][k]) / pieceLength;
                if (std::abs(rate[k]) > 1e-12) {
                    g.velocityCap = std::min(g.velocityCap, m_limits.velocity[k] / std::abs(rate[k]));
                    g.accelerationCap = std::min(g.accelerationCap, m_limits.acceleration[k] / std::abs(rate[k]));
                }
            }
            if (p == 0)
                g.startRate = rate;
            if (p == pieces - 1)
                g.endRate = rate;
        }
        return g;
    }

private:
    const MoveList& m_list;
    const kinematics::KinematicChain& m_chain;
    AxisLimits m_limits;
    std::array<double, 2> m_previous{0, 0};
    int m_toolNumber = -1;  // the tool m_toolLength is of
    double m_toolLength = 0;
    bool m_endKnown = false;  // the machine's axes where the last move ended
    Vec3 m_endTip;
    double m_endToolLength = 0;
    AxisVector m_endAxes{};
};

double programmedSpeed(const Move& move, const MoveGeometry& g, const kinematics::Machine& machine, bool& fixedTime)
{
    fixedTime = false;
    if (move.kind == MoveKind::Rapid)  // a rotation in place at rapid: as fast as the axes go
        return g.rotationOnly ? kInf : kinematics::estimateRapidMmPerMin(&machine) / 60.0;
    if (move.minutes > 0) {
        fixedTime = true;
        return g.length / (move.minutes * 60.0);
    }
    // A rotation in place reads the feed as degrees per minute, as controls do for such a block.
    return move.feedMmPerMin / 60.0;
}

// The corner cap of rule 2: each axis' velocity step v·|rateAfter − rateBefore| at most a·t.
double cornerCap(const MoveGeometry& before, const MoveGeometry& after, const AxisLimits& limits, double stepSeconds)
{
    if (before.rotationOnly != after.rotationOnly)
        return 0;  // speeds in different units: the control stops between them
    double cap = kInf;
    for (int k = 0; k < limits.count; ++k) {
        const double jump = std::abs(after.startRate[k] - before.endRate[k]);
        if (jump > 1e-9)
            cap = std::min(cap, limits.acceleration[k] * stepSeconds / jump);
    }
    return cap;
}

double spindleRamp(double fromRpm, double toRpm, const kinematics::Machine& machine)
{
    if (fromRpm == toRpm)
        return 0;
    const double full =
        machine.spindleMaxRpm > 0 ? machine.spindleMaxRpm : std::max(std::abs(fromRpm), std::abs(toRpm));
    return machine.spindleRampSeconds * std::min(1.0, std::abs(toRpm - fromRpm) / full);
}

// The trapezoid (or triangle) from entry to exit within `length`; fills cruise and the time.
void shapeProfile(PlannedMove& m)
{
    if (m.length <= 0 || m.cruiseSpeed <= 0) {
        m.moveSeconds = 0;
        return;
    }
    if (m.fixedTime) {
        m.moveSeconds = m.length / m.cruiseSpeed;
        return;
    }
    const double a = m.acceleration, v0 = m.entrySpeed, v1 = m.exitSpeed;
    const double peak = std::sqrt(a * m.length + 0.5 * (v0 * v0 + v1 * v1));
    m.cruiseSpeed = std::min(m.cruiseSpeed, peak);
    const double vc = m.cruiseSpeed;
    const double up = (vc * vc - v0 * v0) / (2 * a), down = (vc * vc - v1 * v1) / (2 * a);
    const double level = std::max(0.0, m.length - up - down);
    m.moveSeconds = (vc - v0) / a + (vc - v1) / a + level / vc;
}

// min(cap, the speed reached from `speed` over `length` at `acceleration`), for the passes. Most
// junctions are capped by the corners and the feeds, not by what a move can brake or speed up to:
// there the root is skipped, whose latency chained each junction to the next. The result is the
// same double: cap² with a margin above its rounding at most `reach` means cap ≤ √reach exactly,
// and the rounded root cannot fall below cap, so min() gives cap (a cap whose square is not a
// normal double, or NaN, takes the root).
double reachCapped(double cap, double speed, double acceleration, double length)
{
    const double reach = speed * speed + 2 * acceleration * length;
    if (cap > 1e-100 && cap * cap * (1 + 1e-15) <= reach)
        return cap;
    return std::min(cap, std::sqrt(reach));
}

}  // namespace

double PlannedMove::distanceAt(double t) const
{
    if (moveSeconds <= 0 || t >= moveSeconds)
        return length;
    if (t <= 0)
        return 0;
    if (fixedTime)
        return cruiseSpeed * t;
    const double a = acceleration, v0 = entrySpeed, vc = cruiseSpeed;
    const double t1 = (vc - v0) / a, d1 = (vc * vc - v0 * v0) / (2 * a);
    const double d3 = (vc * vc - exitSpeed * exitSpeed) / (2 * a);
    const double t2 = std::max(0.0, length - d1 - d3) / vc;
    if (t < t1)
        return v0 * t + 0.5 * a * t * t;
    if (t < t1 + t2)
        return d1 + vc * (t - t1);
    const double td = t - t1 - t2;
    return std::min(length, d1 + vc * t2 + vc * td - 0.5 * a * td * td);
}

MotionPlan planMotion(const MoveList& list, const kinematics::Machine& machine, const PlanOptions& options)
{
    MotionPlan plan;
    const std::size_t n = list.moves.size();
    plan.moves.reserve(n);
    base::prefault(plan.moves, n);  // megabytes about to be written whole: one call, not a fault per page
    plan.moves.resize(n);
    std::vector<double> junction;  // speed at the start of move i (junction[n]: the end)
    junction.reserve(n + 1);
    base::prefault(junction, n + 1);
    junction.assign(n + 1, 0.0);
    GeometryWalker walker(list, machine);
    MoveGeometry previous;
    bool previousFlows = false;  // the previous move ends in motion another can continue
    double rpm = 0;
    // Asked every few thousand moves (a load is cheap, but not beside a move's few dozen
    // nanoseconds); the passes below are quicker than this one and asked once each.
    constexpr std::size_t kCancelStride = 4096;
    auto cancelled = [&] {
        plan.cancelled = options.cancel && options.cancel->load(std::memory_order_relaxed);
        return plan.cancelled;
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (i % kCancelStride == 0 && cancelled())
            return plan;
        const Move& move = list.moves[i];
        PlannedMove& p = plan.moves[i];
        p.pauseSeconds = move.kind == MoveKind::Dwell        ? move.seconds
                         : move.kind == MoveKind::ToolChange ? machine.toolChangeSeconds
                                                             : 0;
        p.pauseSeconds += spindleRamp(rpm, move.spindleRpm, machine);
        rpm = move.spindleRpm;
        const MoveGeometry g = walker.measure(move);
        p.length = g.length;
        p.rotationOnly = g.rotationOnly;
        const double speed = move.moves() ? programmedSpeed(move, g, machine, p.fixedTime) : 0;
        p.cruiseSpeed = std::min(speed, g.velocityCap);
        p.acceleration = std::isfinite(g.accelerationCap) ? g.accelerationCap : 0;
        if (move.moves() && p.length > 0 && !(p.cruiseSpeed > 0))
            ++plan.movesWithoutSpeed;
        const bool flows = p.length > 0 && p.cruiseSpeed > 0 && p.acceleration > 0;
        if (flows && previousFlows && p.pauseSeconds == 0) {
            const PlannedMove& before = plan.moves[i - 1];
            junction[i] = std::min({before.cruiseSpeed, p.cruiseSpeed,
                                    cornerCap(previous, g, walker.limits(), options.cornerStepSeconds)});
        }
        previous = g;
        previousFlows = flows;
    }
    // Backward: every move can brake to the junction after it. Forward: no move is entered faster
    // than the one before could accelerate to. A fixed-time move runs at one speed, so it passes
    // its junctions on unchanged (both already at most its speed).
    if (cancelled())
        return plan;
    for (std::size_t i = n; i-- > 0;) {
        const PlannedMove& p = plan.moves[i];
        if (!p.fixedTime)
            junction[i] = reachCapped(junction[i], junction[i + 1], p.acceleration, p.length);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const PlannedMove& p = plan.moves[i];
        if (!p.fixedTime)
            junction[i + 1] = reachCapped(junction[i + 1], junction[i], p.acceleration, p.length);
    }
    if (cancelled())
        return plan;
    double t = 0;
    for (std::size_t i = 0; i < n; ++i) {
        PlannedMove& p = plan.moves[i];
        p.start = t;
        p.entrySpeed = junction[i];
        p.exitSpeed = junction[i + 1];
        shapeProfile(p);
        t = p.end();
    }
    plan.endPauseSeconds = spindleRamp(rpm, 0, machine);
    plan.totalSeconds = t + plan.endPauseSeconds;
    return plan;
}

CycleTimes cycleTimes(const MoveList& list, const MotionPlan& plan, const toolpath::ProgramStats& simple)
{
    CycleTimes c;
    auto add = [&](TimeSplit& s, std::size_t i) {
        const PlannedMove& p = plan.moves[i];
        (list.moves[i].kind == MoveKind::Rapid ? s.rapidSeconds : s.feedSeconds) += p.moveSeconds;
        s.pauseSeconds += p.pauseSeconds;
    };
    const std::size_t n = std::min(list.moves.size(), plan.moves.size());
    TimeSplit* toolSplit = nullptr;  // the current tool's, looked up when the tool changes
    int splitTool = 0;
    for (std::size_t i = 0; i < n; ++i) {
        add(c.planned, i);
        if (toolSplit == nullptr || list.moves[i].tool != splitTool) {
            splitTool = list.moves[i].tool;
            toolSplit = &c.plannedPerTool[splitTool];
        }
        add(*toolSplit, i);
    }
    // The spindle's stop at the end belongs to the last move's tool and section.
    if (n > 0) {
        c.planned.pauseSeconds += plan.endPauseSeconds;
        c.plannedPerTool[list.moves[n - 1].tool].pauseSeconds += plan.endPauseSeconds;
    }
    for (const MoveSection& section : list.sections) {
        SectionTime s{section.name, section.tool, {}};
        for (std::size_t i = section.firstMove; i < section.endMove && i < plan.moves.size(); ++i)
            add(s.planned, i);
        if (n > 0 && section.firstMove < n && section.endMove >= n)
            s.planned.pauseSeconds += plan.endPauseSeconds;
        c.sections.push_back(s);
    }
    c.simpleSeconds = simple.totals.totalSeconds();
    for (const toolpath::ToolStats& t : simple.tools)
        c.simplePerTool[t.toolNumber] += t.totals.totalSeconds();
    return c;
}

std::map<int, double> secondsPerOperation(const toolpath::Toolpath& program, const MoveList& moves,
                                          const MotionPlan& plan)
{
    std::map<int, double> seconds;
    for (std::size_t i = 0; i < moves.moves.size() && i < plan.moves.size(); ++i) {
        const std::uint32_t record = moves.moves[i].record;
        const int operation = record < program.size() ? program.source(record).operationIndex : -1;
        seconds[operation] += plan.moves[i].pauseSeconds + plan.moves[i].moveSeconds;
        if (i + 1 == std::min(moves.moves.size(), plan.moves.size()))
            seconds[operation] += plan.endPauseSeconds;
    }
    return seconds;
}

}  // namespace camwb::sim
