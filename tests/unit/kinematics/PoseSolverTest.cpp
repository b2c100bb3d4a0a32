// The pose choice: limits, the preferred branch, the pole, C continuity over full turns, errors
// that say which limit; and the operation-wide branch plan (fewest reconfigurations first).
#include "kinematics/PoseSolver.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace camwb;
using namespace camwb::kinematics;

namespace {

constexpr double kPi = 3.14159265358979323846;

Machine mcvl1000()
{
    auto machine = findMachine("mas-mcvl1000", defaultMachineDirs());
    EXPECT_TRUE(machine.ok()) << machine.error().toString();
    return machine.ok() ? machine.value() : Machine{};
}

// The tool axis tilted `tiltDeg` from Z towards the azimuth `azimuthDeg` (from +X about +Z).
Vec3 tilted(double tiltDeg, double azimuthDeg)
{
    const double t = tiltDeg * kPi / 180, a = azimuthDeg * kPi / 180;
    return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

}  // namespace

TEST(PoseSolver, PrefersTheMachinesBranchWithoutAPreviousPose)
{
    const Machine m = mcvl1000();  // preferred: B negative
    PoseSolver solver(m);
    auto pose = solver.solve({{10, 20, 5}, tilted(20, 30)}, nullptr);
    ASSERT_TRUE(pose.ok()) << pose.error().toString();
    EXPECT_NEAR(pose->pose.rotaryDeg[0], -20, 1e-9);
    EXPECT_EQ(pose->branch, -1);
    const ToolPose back = forwardKinematics(m.kinematics, pose->pose);
    EXPECT_NEAR(back.tip.x, 10, 1e-9);
    EXPECT_NEAR(back.tip.y, 20, 1e-9);
    EXPECT_NEAR(back.tip.z, 5, 1e-9);
}

TEST(PoseSolver, OnlyTheBranchWithinTheLimits)
{
    Machine m = mcvl1000();
    m.kinematics.preferredSign = 1;  // prefer B positive: B +60 is beyond +30, so B -60 it is
    PoseSolver solver(m);
    auto pose = solver.solve({{0, 0, 0}, tilted(60, 0)}, nullptr);
    ASSERT_TRUE(pose.ok());
    EXPECT_NEAR(pose->pose.rotaryDeg[0], -60, 1e-9);
    EXPECT_EQ(solver.candidates({{0, 0, 0}, tilted(60, 0)}, nullptr).size(), 1u);
}

TEST(PoseSolver, NoSolutionWithinTheLimitsSaysWhichLimit)
{
    PoseSolver solver(mcvl1000());
    auto pose = solver.solve({{0, 0, 0}, tilted(130, 45)}, nullptr);
    ASSERT_FALSE(pose.ok());
    EXPECT_NE(pose.error().message.find("B-130 is below the axis' limit -120"), std::string::npos)
        << pose.error().message;
    EXPECT_NE(pose.error().message.find("B130 is above the axis' limit 30"), std::string::npos) << pose.error().message;
    EXPECT_EQ(solver.outsideLimits({{}, {-119, 1e6}}), std::nullopt);  // C is endless
}

TEST(PoseSolver, PoleKeepsThePreviousC)
{
    PoseSolver solver(mcvl1000());
    MachinePose previous{{0, 0, 0}, {-3, 417.5}};
    auto pose = solver.solve({{1, 2, 3}, {0, 0, 1}}, &previous);
    ASSERT_TRUE(pose.ok());
    EXPECT_EQ(pose->pole, 1);
    EXPECT_EQ(pose->branch, 0);
    EXPECT_NEAR(pose->pose.rotaryDeg[0], 0, 1e-12);
    EXPECT_EQ(pose->pose.rotaryDeg[1], 417.5);
}

TEST(PoseSolver, CFollowsAFullTurnOfTheToolAxisWithoutJumps)
{
    // The tool axis circles the C axis at 35 degrees: C grows through 360 to 720 on an endless
    // table, one step at a time, and B stays on its branch.
    PoseSolver solver(mcvl1000());
    std::optional<MachinePose> previous;
    double firstC = 0;
    for (int step = 0; step <= 720; ++step) {
        auto pose = solver.solve({{0, 0, 0}, tilted(35, -step)}, previous ? &*previous : nullptr);
        ASSERT_TRUE(pose.ok());
        if (previous) {
            EXPECT_NEAR(std::abs(pose->pose.rotaryDeg[1] - previous->rotaryDeg[1]), 1, 1e-9) << step;
            EXPECT_NEAR(pose->pose.rotaryDeg[0], -35, 1e-9) << step;
        } else {
            firstC = pose->pose.rotaryDeg[1];
        }
        previous = pose->pose;
    }
    EXPECT_NEAR(std::abs(previous->rotaryDeg[1] - firstC), 720, 1e-6);
}

TEST(PoseSolver, LimitedCTurnsBackWithinItsRange)
{
    Machine m = mcvl1000();
    for (Axis& a : m.axes) {
        if (a.name == "C") {
            a.endless = false;
            a.min = -200;
            a.max = 200;
        }
    }
    PoseSolver solver(m);
    MachinePose previous{{}, {-40, 190}};
    // C would continue to 215, beyond 200: the same orientation at C -145 is the one left (the
    // other branch's B +40 is beyond +30).
    auto pose = solver.solve({{0, 0, 0}, forwardKinematics(m.kinematics, {{}, {-40, 215}}).axis}, &previous);
    ASSERT_TRUE(pose.ok());
    EXPECT_NEAR(pose->pose.rotaryDeg[1], -145, 1e-9);
}

TEST(BranchPlan, ChoosesTheBranchThatFinishesTheOperation)
{
    // Preferring B positive, the first poses could start at B +20, but the operation tilts to 60
    // degrees where only B -60 lies within -120..+30: the plan starts on the negative branch and
    // needs no reconfiguration, where a move-by-move choice would have flipped half way.
    Machine m = mcvl1000();
    m.kinematics.preferredSign = 1;
    PoseSolver solver(m);
    std::vector<ToolPose> tools;
    for (int i = 0; i <= 40; ++i)
        tools.push_back({{double(i), 0, 0}, tilted(20 + i, 10)});
    auto plan = planBranches(solver, tools, nullptr);
    ASSERT_TRUE(plan.ok()) << plan.error().toString();
    for (const PlannedPose& p : plan.value()) {
        EXPECT_FALSE(p.reconfigure);
        EXPECT_LT(p.candidate.pose.rotaryDeg[0], 0);
    }
    // Move by move, the first pose takes the preferred branch.
    auto greedy = solver.solve(tools[0], nullptr);
    ASSERT_TRUE(greedy.ok());
    EXPECT_GT(greedy->pose.rotaryDeg[0], 0);
    // Every planned pose gives its tool pose.
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const ToolPose back = forwardKinematics(m.kinematics, plan.value()[i].candidate.pose);
        EXPECT_NEAR(distance(back.tip, tools[i].tip), 0, 1e-9);
        EXPECT_NEAR(distance(back.axis, tools[i].axis), 0, 1e-12);
    }
}

TEST(BranchPlan, ReconfiguresWhereNoBranchFinishes)
{
    // B within -40..+40 and C within -90..90: with the tool axis tilted 35 degrees, the B-negative
    // branch (C = -azimuth) reaches the azimuths -90..90 and the B-positive one (C = 180 - azimuth)
    // 90..270; a sweep from 0 to 200 must change branch once.
    Machine m = mcvl1000();
    for (Axis& a : m.axes) {
        if (a.name == "B") {
            a.min = -40;
            a.max = 40;
        } else if (a.name == "C") {
            a.endless = false;
            a.min = -90;
            a.max = 90;
        }
    }
    PoseSolver solver(m);
    std::vector<ToolPose> tools;
    for (int azimuth = 0; azimuth <= 200; azimuth += 10)
        tools.push_back({{0, 0, 0}, tilted(35, azimuth)});
    auto plan = planBranches(solver, tools, nullptr);
    ASSERT_TRUE(plan.ok()) << plan.error().toString();
    int reconfigurations = 0;
    std::size_t first = 0;
    for (std::size_t i = 0; i < plan->size(); ++i) {
        if (plan.value()[i].reconfigure && reconfigurations++ == 0)
            first = i;
    }
    EXPECT_EQ(reconfigurations, 1);
    BranchPlanOptions refuse;
    refuse.allowReconfigure = false;
    auto refused = planBranches(solver, tools, nullptr, refuse);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("tool pose " + std::to_string(first) + ":"), std::string::npos)
        << refused.error().message;
}

TEST(BranchPlan, UnreachablePoseIsNamed)
{
    PoseSolver solver(mcvl1000());
    std::vector<ToolPose> tools = {{{0, 0, 0}, tilted(10, 0)}, {{0, 0, 0}, tilted(50, 0)}, {{0, 0, 0}, tilted(125, 0)}};
    auto plan = planBranches(solver, tools, nullptr);
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().message.find("tool pose 2: no solution within the rotary limits"), std::string::npos)
        << plan.error().message;
}
