// The simulator's machine frame (Cam.Sim.MachineFrame): at a point of the playback, the motion
// that carries the workpiece side (stock, model, path, rotary table) to where the machine's
// table joints hold it, and the rotary table drawn under the stock in both frames. Plain C++
// (no Qt, no VTK); the pose math is kinematics::machineFrameMotion at the angles
// sim::machinePoseAt gives from sim::rotaryAtMoveStarts (SimRun::rotaryAtStart).
#pragma once

#include "base/Vec.h"
#include "gui/sim/Timeline.h"
#include "kinematics/KinematicChain.h"

#include <array>
#include <optional>

namespace camwb::gui {

struct SimRun;

// Why a run cannot be shown as the machine sees it (the dock's tooltip says so).
enum class MachineFrameSupport {
    Available,
    NoRun,      // nothing simulated yet
    NoMachine,  // simulated on the default limits: no machine chosen, no chain
    NoChain,    // the machine's file gives no five-axis kinematic chain
};
MachineFrameSupport machineFrameSupport(const SimRun* run);

// The rotary angles (chain order) at `at`, as the motion plan follows them; {0, 0} unless the
// run's machine is five-axis.
std::array<double, 2> rotaryAt(const SimRun& run, const MovePoint& at);
// The workpiece side's motion at `at`; the identity unless machineFrameSupport is Available.
kinematics::RigidMotion machineFrameAt(const SimRun& run, const MovePoint& at);

// The rotary table as drawn, in the workpiece frame at the zero pose: a disc on the table's own
// axis (the chain's innermost table joint) whose top face is at the bottom of the stock.
struct RotaryTable {
    base::Vec3 centre;           // the top face's centre
    base::Vec3 normal{0, 0, 1};  // up, out of the top face
    base::Vec3 zero{1, 0, 0};    // where the table's C = 0 mark points (workpiece +X at the zero pose)
    double radiusMm = 0;
    double thicknessMm = 0;
};
// None without a five-axis chain with a table joint (a head-head machine has no rotary table),
// or when that joint's axis is not upright at the zero pose (a table that stands on its side is
// not a disc under the stock).
std::optional<RotaryTable> rotaryTableOf(const SimRun& run);

}  // namespace camwb::gui
