// kinematics::machineFrameMotion, the simulator's machine-frame view: a known B/C pose turns a
// workpiece point where the chain says, the tool comes out along the spindle for a table-table
// chain (checked against forwardKinematics), the zero pose and a head-head chain give the identity.
#include "kinematics/KinematicChain.h"
#include "kinematics/Machine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace camwb;
using namespace camwb::kinematics;

namespace {

void expectNear(const Vec3& actual, const Vec3& expected, double tolerance, const std::string& what)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// A B/C trunnion: B about +Y through a pivot 50 below and 20 beside the workpiece zero, C about
// +Z through the zero; the workpiece zero stands at (300, 200, -350) in machine coordinates.
KinematicChain trunnion()
{
    KinematicChain chain;
    chain.type = ChainType::TableTable;
    chain.joints = {{"B", true, {0, 1, 0}, {320, 200, -400}}, {"C", true, {0, 0, 1}, {300, 200, -350}}};
    chain.workpieceZero = {300, 200, -350};
    return chain;
}

}  // namespace

TEST(MachineFrame, ZeroPoseIsTheIdentity)
{
    const RigidMotion m = machineFrameMotion(trunnion(), {0, 0});
    expectNear(m.apply({12, -7, 33}), {12, -7, 33}, 1e-12, "point");
    expectNear(m.turn({0, 1, 0}), {0, 1, 0}, 1e-12, "direction");
}

TEST(MachineFrame, KnownPoseTurnsAWorkpiecePoint)
{
    // C = 90 alone turns (10, 0, 0) right-handed about +Z through the zero: to (0, 10, 0).
    const KinematicChain chain = trunnion();
    expectNear(machineFrameMotion(chain, {0, 90}).apply({10, 0, 0}), {0, 10, 0}, 1e-12, "C90");
    // B = 90 then: the B pivot sits at (20, 0, -50) from the zero; about +Y, (x, z) -> (z, -x)
    // relative to it: (0, 10, 0) - (20, 0, -50) = (-20, 10, 50) -> (50, 10, 20), + pivot = (70, 10, -30).
    expectNear(machineFrameMotion(chain, {90, 90}).apply({10, 0, 0}), {70, 10, -30}, 1e-12, "B90 C90");
}

TEST(MachineFrame, ToolComesOutAlongTheSpindleOfATableTableChain)
{
    // Checked against the forward kinematics: the tool FK puts on the workpiece, carried into the
    // machine frame, is the spindle (+Z) at the machine's linear axes less the workpiece zero.
    const KinematicChain chain = trunnion();
    for (const auto& rotary : {std::array<double, 2>{-35, 20}, {60, -140}, {90, 90}}) {
        const MachinePose pose{{310, 180, -290}, rotary};
        const ToolPose tool = forwardKinematics(chain, pose);
        const RigidMotion m = machineFrameMotion(chain, rotary);
        expectNear(m.turn(tool.axis), {0, 0, 1}, 1e-12, "axis");
        expectNear(m.apply(tool.tip), pose.linear - chain.workpieceZero, 1e-9, "tip");
    }
}

TEST(MachineFrame, SeedMachineFileTiltsTheWorkpieceNotTheTool)
{
    // The example's machine (mas-mcvl1000, B about +Y and C about +Z through the zero): a tool
    // tilted 30 degrees towards +X on the workpiece stands vertical in the machine frame.
    auto machine = findMachine("mas-mcvl1000", defaultMachineDirs());
    ASSERT_TRUE(machine.ok()) << machine.error().toString();
    const double s = std::sin(30 * M_PI / 180), c = std::cos(30 * M_PI / 180);
    const ToolPose tilted{{5, 0, 0}, {s, 0, c}};
    const auto solutions = inverseKinematics(machine->kinematics, tilted);
    ASSERT_FALSE(solutions.empty());
    for (const IkSolution& solution : solutions) {
        const RigidMotion m = machineFrameMotion(machine->kinematics, solution.pose.rotaryDeg);
        expectNear(m.turn(tilted.axis), {0, 0, 1}, 1e-12, "axis");
        expectNear(m.apply(tilted.tip), solution.pose.linear - machine->kinematics.workpieceZero, 1e-9, "tip");
    }
}

TEST(MachineFrame, HeadHeadTurnsNothingOnTheTable)
{
    KinematicChain chain;
    chain.type = ChainType::HeadHead;
    chain.joints = {{"C", false, {0, 0, 1}, {0, 0, 250}}, {"A", false, {1, 0, 0}, {0, 10, 120}}};
    chain.workpieceZero = {40, 30, 10};
    const RigidMotion m = machineFrameMotion(chain, {45, 30});
    expectNear(m.apply({1, 2, 3}), {1, 2, 3}, 1e-12, "point");
    // The head tilts the tool: its axis in the frame is what FK says on the workpiece.
    const ToolPose tool = forwardKinematics(chain, {{0, 0, 0}, {45, 30}}, 80);
    expectNear(m.turn(tool.axis), tool.axis, 1e-12, "axis");
    EXPECT_GT(std::abs(tool.axis.z - 1), 0.1);
}

TEST(MachineFrame, HeadTableTurnsTheTableAndKeepsTheHeadsTilt)
{
    // C turns the table about +Z through (15, -5) of the machine, B tilts the head about +Y.
    KinematicChain chain;
    chain.type = ChainType::HeadTable;
    chain.joints = {{"C", true, {0, 0, 1}, {15, -5, 0}}, {"B", false, {0, 1, 0}, {2, 0, 180}}};
    chain.workpieceZero = {40, 30, 10};
    const std::array<double, 2> rotary{30, 40};
    const RigidMotion m = machineFrameMotion(chain, rotary);
    // The tool FK puts on the workpiece stands as the head holds it: B 40 about +Y.
    const ToolPose tool = forwardKinematics(chain, {{100, 50, 20}, rotary}, 90);
    const double b = 40 * M_PI / 180;
    expectNear(m.turn(tool.axis), {std::sin(b), 0, std::cos(b)}, 1e-12, "axis");
    // The table's axis stays where it is; a point beside it goes round by C 30.
    const Vec3 axisPoint = chain.joints[0].pivot - chain.workpieceZero;
    expectNear(m.apply(axisPoint), axisPoint, 1e-12, "on the C axis");
    const double c = 30 * M_PI / 180;
    expectNear(m.apply(axisPoint + Vec3{10, 0, 5}), axisPoint + Vec3{10 * std::cos(c), 10 * std::sin(c), 5}, 1e-12,
               "beside it");
}
