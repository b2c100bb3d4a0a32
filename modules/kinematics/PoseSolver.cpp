#include "kinematics/PoseSolver.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::kinematics {

namespace {

constexpr double kLimitSlackDeg = 1e-7;  // a rounding error is not a limit violation

double rotaryTravel(const MachinePose& a, const MachinePose& b)
{
    return std::abs(a.rotaryDeg[0] - b.rotaryDeg[0]) + std::abs(a.rotaryDeg[1] - b.rotaryDeg[1]);
}

// The values of `deg` plus whole turns that lie within [min, max], nearest `near` first; for an
// endless axis only the nearest. At most five (a limited axis spanning up to four turns).
struct Turns {
    double value[5];
    int count = 0;
};

Turns turnsWithin(double deg, double near, double min, double max)
{
    Turns out;
    const double nearest = deg + 360.0 * std::round((near - deg) / 360.0);
    if (!std::isfinite(min) && !std::isfinite(max)) {
        out.value[out.count++] = nearest;
        return out;
    }
    // Nearest first: 0, -1, +1, -2, +2 turns away (ties keep that order).
    for (int k : {0, -1, 1, -2, 2}) {
        const double v = nearest + 360.0 * k;
        if (v >= min - kLimitSlackDeg && v <= max + kLimitSlackDeg)
            out.value[out.count++] = v;
    }
    std::stable_sort(out.value, out.value + out.count,
                     [near](double a, double b) { return std::abs(a - near) < std::abs(b - near); });
    return out;
}

std::string number(double value, int decimals)
{
    base::NumberFormat f;
    f.decimals = decimals;
    f.trimTrailingZeros = true;
    return f.format(value);
}

std::string formatDeg(double deg) { return number(deg, 4); }

}  // namespace

PoseSolver::PoseSolver(const Machine& machine, double toolLengthMm) :
    m_chain(machine.kinematics),
    m_toolLengthMm(toolLengthMm)
{
    for (std::size_t i = 0; i < m_chain.joints.size() && i < 2; ++i) {
        const Axis* axis = machine.axis(m_chain.joints[i].axis);
        m_min[i] = axis ? axis->min : -std::numeric_limits<double>::infinity();
        m_max[i] = axis ? axis->max : std::numeric_limits<double>::infinity();
    }
    m_branchJoint = m_chain.preferredJoint >= 0             ? m_chain.preferredJoint
                    : m_chain.type == ChainType::TableTable ? 0
                                                            : 1;
}

std::optional<std::string> PoseSolver::outsideLimits(const MachinePose& pose) const
{
    for (int i = 0; i < 2; ++i) {
        const double v = pose.rotaryDeg[i];
        const std::string& axis = m_chain.joints[i].axis;
        if (v < m_min[i] - kLimitSlackDeg)
            return axis + formatDeg(v) + " is below the axis' limit " + formatDeg(m_min[i]);
        if (v > m_max[i] + kLimitSlackDeg)
            return axis + formatDeg(v) + " is above the axis' limit " + formatDeg(m_max[i]);
    }
    return std::nullopt;
}

std::vector<PoseCandidate> PoseSolver::candidates(const ToolPose& tool, const MachinePose* previous) const
{
    const std::array<double, 2> near = previous ? previous->rotaryDeg : std::array<double, 2>{0, 0};
    std::vector<PoseCandidate> out;
    appendCandidates(inverseKinematics(m_chain, tool, near, m_toolLengthMm), near, out);
    return out;
}

void PoseSolver::appendCandidates(const std::vector<IkSolution>& solutions, const std::array<double, 2>& near,
                                  std::vector<PoseCandidate>& out) const
{
    for (const IkSolution& s : solutions) {
        const Turns first = turnsWithin(s.pose.rotaryDeg[0], near[0], m_min[0], m_max[0]);
        const Turns second = turnsWithin(s.pose.rotaryDeg[1], near[1], m_min[1], m_max[1]);
        for (int i = 0; i < first.count; ++i) {
            for (int k = 0; k < second.count; ++k) {
                PoseCandidate c;
                c.pose = {s.pose.linear, {first.value[i], second.value[k]}};  // whole turns leave the linear axes
                c.pole = s.pole;
                c.poleJoint = s.poleJoint;
                c.poleDistanceDeg = s.poleDistanceDeg;
                const double branchAngle = std::remainder(c.pose.rotaryDeg[m_branchJoint], 360.0);
                c.branch = s.pole >= 0 || std::abs(branchAngle) < 1e-9 ? 0 : (branchAngle > 0 ? 1 : -1);
                out.push_back(c);
            }
        }
    }
}

base::Result<PoseCandidate> PoseSolver::solve(const ToolPose& tool, const MachinePose* previous) const
{
    const std::vector<PoseCandidate> all = candidates(tool, previous);
    if (all.empty()) {
        const auto raw = inverseKinematics(m_chain, tool, {0, 0}, m_toolLengthMm);
        if (raw.empty())
            return base::makeError("the machine's rotary axes cannot point the tool along (" + number(tool.axis.x, 6) +
                                   ", " + number(tool.axis.y, 6) + ", " + number(tool.axis.z, 6) + ")");
        std::string why;
        for (const IkSolution& s : raw) {
            if (auto out = outsideLimits(s.pose))
                why += (why.empty() ? "" : "; the other solution: ") + *out;
        }
        return base::makeError("no solution within the rotary limits: " + why);
    }
    const int preferred = m_chain.preferredJoint >= 0 ? m_chain.preferredSign : 0;
    auto rank = [&](const PoseCandidate& c) {
        // Without a previous pose the preferred branch wins; with one, the nearest pose (a
        // continuous path stays on its branch through the pole), the preferred branch breaking ties.
        const double offPreferred = preferred != 0 && c.branch == -preferred ? 1 : 0;
        const double travel = rotaryTravel(c.pose, previous ? *previous : MachinePose{});
        return previous ? std::pair{travel, offPreferred} : std::pair{offPreferred, travel};
    };
    return *std::min_element(all.begin(), all.end(),
                             [&](const PoseCandidate& a, const PoseCandidate& b) { return rank(a) < rank(b); });
}

}  // namespace camwb::kinematics
