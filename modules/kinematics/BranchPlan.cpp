// planBranches(): a shortest path over the candidate poses of consecutive tool poses (Viterbi),
// with a reconfiguration costing more than any rotary travel.
#include "kinematics/PoseSolver.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace camwb::kinematics {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxStates = 4;  // per tool pose: two branches, each at two turns of C at most

struct Cost {
    int reconfigurations = 0;
    double travelDeg = 0;
    int offPreferred = 0;

    bool operator<(const Cost& o) const
    {
        return std::tie(reconfigurations, travelDeg, offPreferred) <
               std::tie(o.reconfigurations, o.travelDeg, o.offPreferred);
    }
};

// One state of the search, kept small: a 1M-move operation stores a few of these per move.
struct State {
    std::array<double, 2> rotaryDeg{};
    int parent = -1;
    bool reconfigure = false;
    signed char branch = 0, pole = -1, poleJoint = 1;
    float poleDistanceDeg = 0;
    Cost cost;
};

State stateOf(const PoseCandidate& c, int parent, bool reconfigure, const Cost& cost)
{
    return {c.pose.rotaryDeg,
            parent,
            reconfigure,
            static_cast<signed char>(c.branch),
            static_cast<signed char>(c.pole),
            static_cast<signed char>(c.poleJoint),
            static_cast<float>(c.poleDistanceDeg),
            cost};
}

double angleBetweenDeg(const Vec3& a, const Vec3& b) { return a.angleTo(b) * 180 / kPi; }

bool needsReconfigure(const PoseCandidate& from, const PoseCandidate& to, double toolTurnDeg,
                      const BranchPlanOptions& options)
{
    for (int j = 0; j < 2; ++j) {
        const bool nearPole = (from.poleJoint == j && from.poleDistanceDeg <= options.poleConeDeg) ||
                              (to.poleJoint == j && to.poleDistanceDeg <= options.poleConeDeg);
        if (nearPole)
            continue;
        if (std::abs(to.pose.rotaryDeg[j] - from.pose.rotaryDeg[j]) > toolTurnDeg + options.reconfigureStepDeg)
            return true;
    }
    return false;
}

}  // namespace

base::Result<std::vector<PlannedPose>> planBranches(const PoseSolver& solver, const std::vector<ToolPose>& tools,
                                                    const MachinePose* start, const BranchPlanOptions& options)
{
    const KinematicChain& chain = solver.chain();
    const int preferred = chain.preferredJoint >= 0 ? chain.preferredSign : 0;
    // Every step's states in one array (stepStart[i] is where step i's begin): a 1M-move
    // operation keeps a few small states per move and allocates once.
    std::vector<State> states;
    std::vector<std::size_t> stepStart;
    states.reserve(tools.size() * 2);
    stepStart.reserve(tools.size() + 1);
    std::vector<PoseCandidate> previous, next, found;  // the candidates of the last and this step
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const std::size_t begin = states.size();
        next.clear();
        auto consider = [&](const PoseCandidate& c, int parent, bool reconfigure, Cost cost) {
            for (std::size_t k = 0; k < next.size(); ++k) {
                if (std::abs(next[k].pose.rotaryDeg[0] - c.pose.rotaryDeg[0]) < 1e-6 &&
                    std::abs(next[k].pose.rotaryDeg[1] - c.pose.rotaryDeg[1]) < 1e-6) {
                    if (cost < states[begin + k].cost) {
                        states[begin + k] = stateOf(c, parent, reconfigure, cost);
                        next[k] = c;
                    }
                    return;
                }
            }
            states.push_back(stateOf(c, parent, reconfigure, cost));
            next.push_back(c);
        };
        if (i == 0) {
            for (const PoseCandidate& c : solver.candidates(tools[0], start)) {
                Cost cost;
                cost.offPreferred = preferred != 0 && c.branch == -preferred ? 1 : 0;
                if (start)
                    cost.travelDeg = std::abs(c.pose.rotaryDeg[0] - start->rotaryDeg[0]) +
                                     std::abs(c.pose.rotaryDeg[1] - start->rotaryDeg[1]);
                consider(c, -1, false, cost);
            }
        } else {
            const double toolTurn = angleBetweenDeg(tools[i - 1].axis, tools[i].axis);
            const std::size_t last = stepStart.back();
            // Away from the pole the solutions do not depend on the previous pose: solve once and
            // only move the angles by whole turns for each state.
            const std::vector<IkSolution> solutions =
                inverseOrientation(chain, tools[i].axis, previous.front().pose.rotaryDeg);
            const bool pole =
                std::any_of(solutions.begin(), solutions.end(), [](const IkSolution& s) { return s.pole >= 0; });
            for (std::size_t p = 0; p < previous.size(); ++p) {
                found.clear();
                if (pole)
                    found = solver.candidates(tools[i], &previous[p].pose);
                else
                    solver.appendCandidates(solutions, previous[p].pose.rotaryDeg, found);
                for (const PoseCandidate& c : found) {
                    const bool reconfigure = needsReconfigure(previous[p], c, toolTurn, options);
                    Cost cost = states[last + p].cost;
                    cost.reconfigurations += reconfigure ? 1 : 0;
                    cost.travelDeg += std::abs(c.pose.rotaryDeg[0] - previous[p].pose.rotaryDeg[0]) +
                                      std::abs(c.pose.rotaryDeg[1] - previous[p].pose.rotaryDeg[1]);
                    consider(c, static_cast<int>(p), reconfigure, cost);
                }
            }
        }
        if (next.empty()) {
            auto why = solver.solve(tools[i], nullptr);
            return base::makeError(
                "tool pose " + std::to_string(i) + ": " +
                (why ? std::string("no pose continues the path within the rotary limits") : why.error().message));
        }
        if (next.size() > kMaxStates) {  // keep the cheapest
            std::vector<std::size_t> order(next.size());
            for (std::size_t k = 0; k < order.size(); ++k)
                order[k] = k;
            std::sort(order.begin(), order.end(),
                      [&](auto a, auto b) { return states[begin + a].cost < states[begin + b].cost; });
            order.resize(kMaxStates);
            std::vector<State> kept;
            std::vector<PoseCandidate> keptCandidates;
            for (std::size_t k : order) {
                kept.push_back(states[begin + k]);
                keptCandidates.push_back(next[k]);
            }
            states.resize(begin);
            states.insert(states.end(), kept.begin(), kept.end());
            next = std::move(keptCandidates);
        }
        stepStart.push_back(begin);
        std::swap(previous, next);
    }
    if (stepStart.empty())
        return std::vector<PlannedPose>{};
    const std::size_t lastBegin = stepStart.back();
    int best = static_cast<int>(std::min_element(states.begin() + static_cast<std::ptrdiff_t>(lastBegin), states.end(),
                                                 [](const State& a, const State& b) { return a.cost < b.cost; }) -
                                states.begin() - static_cast<std::ptrdiff_t>(lastBegin));
    std::vector<PlannedPose> plan(tools.size());
    for (std::size_t i = tools.size(); i-- > 0;) {
        const State& s = states[stepStart[i] + static_cast<std::size_t>(best)];
        PoseCandidate& c = plan[i].candidate;
        c.pose.rotaryDeg = s.rotaryDeg;
        c.pose.linear = linearAxesFor(chain, tools[i].tip, s.rotaryDeg, solver.toolLengthMm());
        c.branch = s.branch;
        c.pole = s.pole;
        c.poleJoint = s.poleJoint;
        c.poleDistanceDeg = s.poleDistanceDeg;
        plan[i].reconfigure = s.reconfigure;
        best = s.parent;
    }
    if (!options.allowReconfigure) {
        for (std::size_t i = 0; i < plan.size(); ++i) {
            if (plan[i].reconfigure)
                return base::makeError("tool pose " + std::to_string(i) +
                                       ": no branch finishes the operation within the rotary limits without "
                                       "retracting to turn the rotary axes (a reconfiguration)");
        }
    }
    return plan;
}

}  // namespace camwb::kinematics
