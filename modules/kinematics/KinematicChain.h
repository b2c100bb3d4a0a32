// A five-axis machine's kinematic chain and its forward and inverse kinematics: which rotary axes
// turn the workpiece (table) and which the tool (head), about which direction and through which
// pivot, and how machine axis positions map to the tool tip and tool axis in the workpiece frame.
// One model for table-table (B/C, A/C), head-table and head-head machines; no Qt, Eigen inside.
#pragma once

#include "base/Vec.h"

#include <array>
#include <string>
#include <vector>

namespace camwb::kinematics {

using base::Vec3;

// One rotary axis of the chain. A positive angle turns what the axis carries right-handed about
// `direction` (so a machine whose axis counts the other way gives the opposite direction: seed
// 000's B and C "taken negative" are directions +Y and +Z of a chain that turns the workpiece).
struct RotaryJoint {
    std::string axis;     // the machine axis it is ("A", "B", "C"), as in Machine::axes
    bool onTable = true;  // turns the workpiece (table) or the tool (head)
    Vec3 direction{0, 0, 1};
    // A point on the axis at the zero pose: machine coordinates for a table axis; for a head axis,
    // relative to the spindle gauge point (where a tool of length 0 would have its tip).
    Vec3 pivot;
};

enum class ChainType { ThreeAxis, TableTable, HeadTable, HeadHead };

struct KinematicChain {
    ChainType type = ChainType::ThreeAxis;
    // Two joints for a five-axis chain, table joints first from the machine frame outwards to the
    // workpiece (the tilt that carries the rotary table first), then head joints from the frame
    // out to the tool. MachinePose::rotaryDeg follows this order.
    std::vector<RotaryJoint> joints;
    // The workpiece zero in machine coordinates at the zero pose (seed 000: MRZP, the origin;
    // seed 003: P above the pivot).
    Vec3 workpieceZero;
    // The solution branch a post takes first: the joint whose angle's sign tells the two
    // branches apart (usually the tilt) and the sign wanted; index -1: none preferred.
    int preferredJoint = -1;
    int preferredSign = 1;

    bool fiveAxis() const { return joints.size() == 2; }
};

// Machine axis positions: linear X Y Z (where the machine's own position display would be with
// the tool's length compensated) and the two rotary angles in degrees, in KinematicChain::joints
// order.
struct MachinePose {
    Vec3 linear;
    std::array<double, 2> rotaryDeg{0, 0};
};

// The tool in the workpiece frame: tip point and unit axis from the tip towards the spindle.
struct ToolPose {
    Vec3 tip;
    Vec3 axis{0, 0, 1};
};

// Machine axes → tool tip and axis in the workpiece frame. `toolLengthMm` matters only for head
// joints (a head turns the tool about a pivot above its tip).
ToolPose forwardKinematics(const KinematicChain& chain, const MachinePose& pose, double toolLengthMm = 0);

// Tool pose → machine axes: the rotary solutions as the chain defines them, each angle in
// (-180, 180], and the linear axes belonging to each. Two solutions in general, one at the pole,
// none when the chain cannot point the tool that way (a head whose axes are not perpendicular, a
// tool axis the directions cannot reach). At the pole (the tool axis on a rotary axis' direction,
// so that axis' angle is free) the free angle takes `freeAngleDeg` of that joint (the previous
// pose's, so a post keeps C) and `pole` says which joint was free.
struct IkSolution {
    MachinePose pose;
    int pole = -1;               // the joint whose angle the tool axis does not fix; -1: none
    int poleJoint = 1;           // the joint whose angle the nearest pole frees
    double poleDistanceDeg = 0;  // how far the tool axis is from that pole (0: on it)
};
std::vector<IkSolution> inverseKinematics(const KinematicChain& chain, const ToolPose& tool,
                                          const std::array<double, 2>& freeAngleDeg = {0, 0}, double toolLengthMm = 0);
// The rotary part alone (the solutions' linear axes left at 0), for a search that needs the
// linear axes of the poses it keeps only (kinematics::planBranches).
std::vector<IkSolution> inverseOrientation(const KinematicChain& chain, const Vec3& toolAxis,
                                           const std::array<double, 2>& freeAngleDeg = {0, 0});

// The linear axes that put the tool tip at `tip` with the rotary angles of `pose` (its linear
// part is ignored): the part of the inverse kinematics after the angles are chosen, e.g. after an
// angle was moved by a whole turn.
Vec3 linearAxesFor(const KinematicChain& chain, const Vec3& tip, const std::array<double, 2>& rotaryDeg,
                   double toolLengthMm = 0);

// How far the tool tip is from each rotary axis at `pose` (mm), in KinematicChain::joints order:
// the radius on which turning that axis alone carries the tip relative to the workpiece, so that
// ω·r is the part of the tip's feed the axis makes. Seed 003 eqs. 25-26 for any chain (r_v1 from
// the tilt, r_v2 from the table it carries, whose axis the tilt has turned); 0 for a chain
// without rotaries.
std::array<double, 2> tipRadii(const KinematicChain& chain, const MachinePose& pose, double toolLengthMm = 0);

// The machine's X and Z axes as the rotary angles turn them, in the workpiece frame: the tilted
// coordinate system a control sets up for axis angles (Heidenhain CYCL DEF 19 with the machine's
// axis positions), whose axes are parallel to the machine's linear axes as the table and head turn.
struct TiltedAxes {
    Vec3 x{1, 0, 0};
    Vec3 z{0, 0, 1};
};
TiltedAxes tiltedAxes(const KinematicChain& chain, const std::array<double, 2>& rotaryDeg);

// A rigid motion x -> rotation · x + translation (rotation row by row).
struct RigidMotion {
    std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
    Vec3 translation;

    Vec3 turn(const Vec3& v) const
    {
        const auto& r = rotation;
        return {r[0] * v.x + r[1] * v.y + r[2] * v.z, r[3] * v.x + r[4] * v.y + r[5] * v.z,
                r[6] * v.x + r[7] * v.y + r[8] * v.z};
    }
    Vec3 apply(const Vec3& p) const { return turn(p) + translation; }
};

// The machine frame as the simulator's view shows it: where the table joints at `rotaryDeg`
// carry a workpiece point, in machine coordinates less the workpiece zero, so the zero pose is
// the identity and the view stays about the part. The tool tip and axis go through the same
// motion (the tip is where it cuts the part): a table-table chain's axis comes out along +Z,
// the spindle, a head-table chain's tilted by its head; a chain without table joints (head-head,
// three-axis) gives the identity, nothing on the table turns.
RigidMotion machineFrameMotion(const KinematicChain& chain, const std::array<double, 2>& rotaryDeg);

const char* name(ChainType type);  // "three-axis", "table-table", "head-table", "head-head"

}  // namespace camwb::kinematics
