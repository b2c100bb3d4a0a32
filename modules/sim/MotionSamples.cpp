#include "sim/MotionSamples.h"

#include "sim/MachineAxes.h"

#include <cmath>

namespace camwb::sim {

namespace {

// Speed along the move's parameter `t` seconds into its motion (the trapezoid's slope).
double speedAt(const PlannedMove& p, double t)
{
    if (p.moveSeconds <= 0 || t < 0 || t > p.moveSeconds)
        return 0;
    if (p.fixedTime)
        return p.cruiseSpeed;
    const double a = p.acceleration;
    const double up = (p.cruiseSpeed - p.entrySpeed) / a, down = (p.cruiseSpeed - p.exitSpeed) / a;
    if (t < up)
        return p.entrySpeed + a * t;
    if (t > p.moveSeconds - down)
        return p.exitSpeed + a * (p.moveSeconds - t);
    return p.cruiseSpeed;
}

}  // namespace

void sampleMotion(const MoveList& list, const MotionPlan& plan, const kinematics::Machine& machine,
                  const std::function<bool(const MotionSample&)>& visit, const SampleOptions& options)
{
    const double step = options.stepSeconds > 0 ? options.stepSeconds : 0.003;
    const kinematics::KinematicChain& chain = machine.kinematics;
    const std::size_t n = std::min(list.moves.size(), plan.moves.size());
    // The first move whose position is known: before it, there is nothing to show.
    std::size_t i = 0;
    while (i < n && !list.moves[i].positionKnown)
        ++i;
    if (i == n)
        return;
    std::array<double, 2> rotary{0, 0};
    const auto count = static_cast<std::size_t>(std::floor(plan.totalSeconds / step + 1e-9));
    for (std::size_t k = 0; k <= count; ++k) {
        const double t = double(k) * step;
        while (i + 1 < n && plan.moves[i].end() < t)  // zero-time moves are passed over here
            ++i;
        const Move& move = list.moves[i];
        const PlannedMove& p = plan.moves[i];
        const double inMotion = t - p.start - p.pauseSeconds;
        const double u = p.length > 0 ? std::clamp(p.distanceAt(inMotion) / p.length, 0.0, 1.0) : 1.0;
        const toolpath::Tool* tool = list.tool(move.tool);
        const kinematics::MachinePose pose =
            machinePoseAt(chain, move, u, rotary, tool != nullptr ? tool->lengthMm : 0);
        rotary = pose.rotaryDeg;
        MotionSample s;
        const kinematics::ToolPose tp = toolAt(move, u);
        s.at = {t, pose.linear, pose.rotaryDeg, tp.tip, tool != nullptr ? tool->lengthMm : 0};
        s.toolAxis = tp.axis;
        s.move = i;
        s.feedMmPerMin = p.rotationOnly ? 0 : speedAt(p, inMotion) * 60.0;
        if (!visit(s))
            return;
    }
}

std::vector<MotionSample> sampleMotion(const MoveList& moves, const MotionPlan& plan,
                                       const kinematics::Machine& machine, const SampleOptions& options)
{
    std::vector<MotionSample> samples;
    const double step = options.stepSeconds > 0 ? options.stepSeconds : 0.003;
    samples.reserve(static_cast<std::size_t>(plan.totalSeconds / step) + 2);
    sampleMotion(
        moves, plan, machine,
        [&](const MotionSample& s) {
            samples.push_back(s);
            return true;
        },
        options);
    return samples;
}

}  // namespace camwb::sim
