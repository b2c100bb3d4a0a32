// Chooses the machine pose for each tool pose of a program: among the inverse kinematics'
// solutions, each rotary angle moved by whole turns to lie within the axis' limits nearest the
// previous pose (an endless C is never wound back: C355 → C365), then the pose on the machine's
// preferred branch, then the one nearest the previous pose. planBranches() makes that choice
// over a whole operation instead, so the branch that finishes it with the fewest reconfigurations
// wins over the one that merely starts nearest.
#pragma once

#include "base/Result.h"
#include "kinematics/KinematicChain.h"
#include "kinematics/Machine.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace camwb::kinematics {

struct PoseCandidate {
    MachinePose pose;
    int branch = 0;              // +1 / -1: the sign of the branch joint's angle (0 on the pole)
    int pole = -1;               // IkSolution::pole
    int poleJoint = 1;           // IkSolution::poleJoint
    double poleDistanceDeg = 0;  // IkSolution::poleDistanceDeg
};

class PoseSolver {
public:
    // `machine.kinematics` must be a five-axis chain whose joints name rotary axes of `machine`.
    PoseSolver(const Machine& machine, double toolLengthMm = 0);

    const KinematicChain& chain() const { return m_chain; }
    double toolLengthMm() const { return m_toolLengthMm; }

    // Every pose within the rotary limits that gives `tool`: per IK solution, each angle at the
    // whole turn nearest `previous` (or nearest 0) that the limits allow, and for a limited axis
    // whose range spans more than a turn the other turns too.
    std::vector<PoseCandidate> candidates(const ToolPose& tool, const MachinePose* previous) const;
    // The same from solutions already found (away from the pole they do not depend on the
    // previous pose, so a search over many previous poses solves once), appended to `out`.
    void appendCandidates(const std::vector<IkSolution>& solutions, const std::array<double, 2>& near,
                          std::vector<PoseCandidate>& out) const;

    // The one pose for `tool`; the error says which axis and limit no solution satisfies.
    base::Result<PoseCandidate> solve(const ToolPose& tool, const MachinePose* previous) const;

    // Whether `pose`'s rotary angles lie within the machine's limits; else what is out, e.g.
    // "B-125 is below the axis' limit -120".
    std::optional<std::string> outsideLimits(const MachinePose& pose) const;

    // The joint whose angle's sign tells the two solutions apart: the preferred joint, else the
    // tilt (a table-table chain's first joint, a head's joint otherwise).
    int branchJoint() const { return m_branchJoint; }

private:
    KinematicChain m_chain;
    int m_branchJoint = 0;
    std::array<double, 2> m_min{}, m_max{};
    double m_toolLengthMm = 0;
};

struct PlannedPose {
    PoseCandidate candidate;
    // The rotary axes move further between the previous pose and this one than the tool axis
    // turns (a branch flip or a rewind): a post retracts along the tool axis, turns, re-enters.
    bool reconfigure = false;
};

struct BranchPlanOptions {
    // A step between consecutive poses in which a rotary axis moves more than this many degrees
    // beyond the tool axis' own turn is a reconfiguration ...
    double reconfigureStepDeg = 30;
    // ... except for the axis the pole frees while the tool axis is within this cone of the pole,
    // where any turn of the tool axis may swing that angle (the post keeps it there).
    double poleConeDeg = 1;
    bool allowReconfigure = true;  // false: a plan that needs one is an error
};

// One pose per tool pose of an operation, chosen together: fewest reconfigurations, then the
// least rotary travel, then the preferred branch. Errors name the 0-based index of the tool pose
// that no solution within the limits reaches, or (allowReconfigure false) the first one a
// reconfiguration would have to precede.
base::Result<std::vector<PlannedPose>> planBranches(const PoseSolver& solver, const std::vector<ToolPose>& tools,
                                                    const MachinePose* start, const BranchPlanOptions& options = {});

}  // namespace camwb::kinematics
