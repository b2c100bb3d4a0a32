#include "sim/MachineAxes.h"

#include <cmath>
#include <limits>

namespace camwb::sim {

namespace {

// `deg` moved by whole turns to lie nearest `near`: an endless C goes the short way from where it is.
double nearestTurn(double deg, double near) { return deg + 360.0 * std::round((near - deg) / 360.0); }

// The tip at `u` along the move's straight piece, its ends exactly.
Vec3 tipAt(const Move& move, double u) { return u == 1 ? move.to : move.from + (move.to - move.from) * u; }

}  // namespace

kinematics::ToolPose toolAt(const Move& move, double u)
{
    kinematics::ToolPose pose;
    pose.tip = tipAt(move, u);
    pose.axis = move.axisAt(u);
    return pose;
}

bool knownRotaries(const kinematics::KinematicChain& chain, const Move& move, bool end,
                   std::array<double, 2>& rotaryDeg)
{
    if (!chain.fiveAxis())
        return false;
    const toolpath::RotaryAxes& r = end ? move.toMachine() : move.fromMachine();
    for (int j = 0; j < 2; ++j) {
        const std::optional<double> deg = r.of(chain.joints[j].axis);
        if (!deg)
            return false;
        rotaryDeg[j] = *deg;
    }
    return true;
}

kinematics::MachinePose machinePoseAt(const kinematics::KinematicChain& chain, const Move& move, double u,
                                      const std::array<double, 2>& previousRotaryDeg, double toolLengthMm)
{
    kinematics::MachinePose pose;
    if (!chain.fiveAxis()) {  // the tool's axis does not matter
        pose.linear = kinematics::linearAxesFor(chain, tipAt(move, u), {0, 0}, toolLengthMm);
        return pose;
    }
    const kinematics::ToolPose tool = toolAt(move, u);
    std::array<double, 2> a{}, b{};
    if (knownRotaries(chain, move, false, a) && knownRotaries(chain, move, true, b)) {
        for (int j = 0; j < 2; ++j)
            pose.rotaryDeg[j] = a[j] + (b[j] - a[j]) * u;
        pose.linear = kinematics::linearAxesFor(chain, tool.tip, pose.rotaryDeg, toolLengthMm);
        return pose;
    }
    const auto solutions = kinematics::inverseKinematics(chain, tool, previousRotaryDeg, toolLengthMm);
    if (solutions.empty()) {  // the chain cannot point the tool so: stay put rather than invent
        pose.rotaryDeg = previousRotaryDeg;
        pose.linear = kinematics::linearAxesFor(chain, tool.tip, pose.rotaryDeg, toolLengthMm);
        return pose;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const auto& s : solutions) {
        std::array<double, 2> deg{nearestTurn(s.pose.rotaryDeg[0], previousRotaryDeg[0]),
                                  nearestTurn(s.pose.rotaryDeg[1], previousRotaryDeg[1])};
        const double d = std::abs(deg[0] - previousRotaryDeg[0]) + std::abs(deg[1] - previousRotaryDeg[1]);
        if (d < best) {
            best = d;
            pose.rotaryDeg = deg;
        }
    }
    pose.linear = kinematics::linearAxesFor(chain, tool.tip, pose.rotaryDeg, toolLengthMm);
    return pose;
}

std::vector<std::array<double, 2>> rotaryAtMoveStarts(const kinematics::KinematicChain& chain, const MoveList& moves)
{
    std::vector<std::array<double, 2>> starts;
    if (!chain.fiveAxis())
        return starts;
    starts.reserve(moves.moves.size());
    std::array<double, 2> previous{0, 0};
    for (const Move& move : moves.moves) {
        starts.push_back(previous);
        if (!move.moves() || !move.positionKnown)
            continue;
        const toolpath::Tool* tool = moves.tool(move.tool);
        const double toolLength = tool != nullptr ? tool->lengthMm : 0;
        for (int p = 0; p <= kRotaryPiecesPerMove; ++p)
            previous = machinePoseAt(chain, move, double(p) / kRotaryPiecesPerMove, previous, toolLength).rotaryDeg;
    }
    return starts;
}

}  // namespace camwb::sim
