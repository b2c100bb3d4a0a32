// Motion in time: exact trapezoid and triangle times, corner and continuation junction speeds,
// axis velocity limits, dwell/tool change/spindle ramp times, inverse time, cycle-time totals,
// and the fixed-step samples on a three- and a five-axis machine.
#include "sim/MotionPlan.h"
#include "sim/MachineAxes.h"
#include "sim/MotionSamples.h"

#include "toolpath/ProgramStats.h"
#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace camwb;
using sim::Move;
using sim::MoveKind;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A three-axis machine: X Y Z at 6000 mm/min (100 mm/s) and 1000 mm/s², no spindle ramp unless
// the spindle changes (tests keep it at 0).
kinematics::Machine machine3(double xMaxMmPerMin = 6000)
{
    kinematics::Machine m;
    for (const char* name : {"X", "Y", "Z"}) {
        kinematics::Axis a;
        a.name = name;
        a.maxVelocity = name[0] == 'X' ? xMaxMmPerMin : 6000;
        a.maxAcceleration = 1000;
        m.axes.push_back(a);
    }
    m.rapidMmPerMin = 6000;
    m.toolChangeSeconds = 7;
    m.spindleRampSeconds = 2;
    m.spindleMaxRpm = 12000;
    return m;
}

Move feed(base::Vec3 from, base::Vec3 to, double mmPerMin)
{
    Move m;
    m.from = from;
    m.to = to;
    m.feedMmPerMin = mmPerMin;
    return m;
}

Move pause(MoveKind kind, base::Vec3 at, double seconds = 0)
{
    Move m;
    m.kind = kind;
    m.from = m.to = at;
    m.seconds = seconds;
    return m;
}

}  // namespace

TEST(MotionPlan, OneMoveIsAnExactTrapezoid)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {100, 0, 0}, 600));  // 10 mm/s, a = 1000 mm/s²
    const sim::MotionPlan plan = sim::planMotion(list, machine3());
    const sim::PlannedMove& p = plan.moves[0];
    EXPECT_DOUBLE_EQ(p.entrySpeed, 0);
    EXPECT_DOUBLE_EQ(p.cruiseSpeed, 10);
    EXPECT_DOUBLE_EQ(p.exitSpeed, 0);
    EXPECT_NEAR(p.moveSeconds, 100.0 / 10 + 10.0 / 1000, 1e-12);  // s/v + v/a
    EXPECT_NEAR(plan.totalSeconds, 10.01, 1e-12);
    EXPECT_NEAR(p.distanceAt(0.005), 0.5 * 1000 * 0.005 * 0.005, 1e-12);  // still accelerating
    EXPECT_NEAR(p.distanceAt(5), 10 * 5 - 0.05, 1e-9);                    // cruising
}

TEST(MotionPlan, AShortMoveIsATriangle)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {0.01, 0, 0}, 600));
    const sim::PlannedMove p = sim::planMotion(list, machine3()).moves[0];
    EXPECT_NEAR(p.cruiseSpeed, std::sqrt(1000 * 0.01), 1e-12);  // never reaches 10 mm/s
    EXPECT_NEAR(p.moveSeconds, 2 * std::sqrt(0.01 / 1000), 1e-12);
}

TEST(MotionPlan, ARightAngleCornerSlowsToTheJunctionSpeed)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {100, 0, 0}, 6000));
    list.moves.push_back(feed({100, 0, 0}, {100, 100, 0}, 6000));
    const sim::MotionPlan plan = sim::planMotion(list, machine3());
    // X stops and Y starts at the corner: each axis' step v·1 may be a·t = 1000 · 0.003.
    EXPECT_NEAR(plan.moves[0].exitSpeed, 3, 1e-12);
    EXPECT_NEAR(plan.moves[1].entrySpeed, 3, 1e-12);
    const double one = 100.0 / 100 + 100.0 / (2 * 1000) + (100.0 - 3) / 1000 - (100.0 * 100 - 9) / (2 * 1000 * 100);
    EXPECT_NEAR(plan.moves[0].moveSeconds, one, 1e-12);
}

TEST(MotionPlan, AStraightContinuationDoesNotSlow)
{
    sim::MoveList split;
    split.moves.push_back(feed({0, 0, 0}, {50, 0, 0}, 6000));
    split.moves.push_back(feed({50, 0, 0}, {100, 0, 0}, 6000));
    const sim::MotionPlan plan = sim::planMotion(split, machine3());
    EXPECT_DOUBLE_EQ(plan.moves[0].exitSpeed, 100);
    EXPECT_NEAR(plan.totalSeconds, 100.0 / 100 + 100.0 / 1000, 1e-12);  // as one 100 mm move
}

TEST(MotionPlan, ShortMovesInARowSpeedUpAndBrakeAsOne)
{
    // Ten collinear 0.5 mm moves at 100 mm/s, a = 1000 mm/s²: too short to reach the feed. The
    // junctions are what the passes allow, speeding up from the start and braking to the end: the
    // five millimetres are one triangle.
    sim::MoveList list;
    for (int k = 0; k < 10; ++k)
        list.moves.push_back(feed({0.5 * k, 0, 0}, {0.5 * (k + 1), 0, 0}, 6000));
    const sim::MotionPlan plan = sim::planMotion(list, machine3());
    for (int k = 0; k < 10; ++k) {
        const double d = 0.5 * (k + 1);  // where move k ends
        EXPECT_NEAR(plan.moves[k].exitSpeed, std::sqrt(2 * 1000 * std::min(d, 5 - d)), 1e-9) << "move " << k;
    }
    EXPECT_DOUBLE_EQ(plan.moves[0].entrySpeed, 0);
    EXPECT_NEAR(plan.totalSeconds, 2 * std::sqrt(5.0 / 1000), 1e-12);
}

TEST(MotionPlan, AnAxisVelocityLimitLowersADiagonalsPathSpeed)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {100, 100, 0}, 6000));
    const sim::PlannedMove p = sim::planMotion(list, machine3(600)).moves[0];  // X at most 10 mm/s
    EXPECT_NEAR(p.cruiseSpeed, 10 * std::sqrt(2.0), 1e-9);                     // X moves 1/√2 mm per mm of path
    // A rapid on the same machine: the same cap, not the rapid rate.
    list.moves[0].kind = MoveKind::Rapid;
    EXPECT_NEAR(sim::planMotion(list, machine3(600)).moves[0].cruiseSpeed, 10 * std::sqrt(2.0), 1e-9);
}

TEST(MotionPlan, DwellToolChangeAndSpindleRampAddExactlyTheirTime)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {100, 0, 0}, 600));
    list.moves.push_back(pause(MoveKind::Dwell, {100, 0, 0}, 2.5));
    list.moves.push_back(pause(MoveKind::ToolChange, {100, 0, 0}));
    list.moves.push_back(pause(MoveKind::Stop, {100, 0, 0}));
    list.moves.push_back(feed({100, 0, 0}, {200, 0, 0}, 600));
    const sim::MotionPlan plan = sim::planMotion(list, machine3());
    EXPECT_NEAR(plan.totalSeconds, 2 * 10.01 + 2.5 + 7, 1e-9);  // the stop counts 0
    EXPECT_DOUBLE_EQ(plan.moves[0].exitSpeed, 0);               // a pause stands the tool

    // Half the spindle's range: half the ramp up, and half again to stop it at the program's end.
    list.moves[4].spindleRpm = 6000;
    EXPECT_NEAR(sim::planMotion(list, machine3()).totalSeconds, 2 * 10.01 + 2.5 + 7 + 1 + 1, 1e-9);
}

// The spindle stops at the end (an M5 after the last move, or the program's end itself), and no
// move follows to carry that ramp: the plan counts it after the last move, in the last move's
// tool, section and operation; a spindle already stopped before the last move counts nothing more.
TEST(MotionPlan, TheSpindleStopAtTheProgramsEndIsCounted)
{
    toolpath::Toolpath p;
    toolpath::Tool t1;
    t1.number = 1;
    p.add(toolpath::SectionBegin{"Face", "profile", 1}, {4, 0});
    p.add(toolpath::ToolChange{t1}, {4, -1});
    p.add(toolpath::Spindle{9000}, {4, 1});  // three quarters of 12000 rpm: 1.5 s up, 1.5 s down
    p.add(toolpath::Rapid{{0, 0, 10}}, {4, 2});
    p.add(toolpath::Linear{{0, 0, 0}, 600}, {4, 3});
    p.add(toolpath::Spindle{0}, {4, 4});  // M5, and nothing moves after it
    p.add(toolpath::SectionEnd{}, {4, -1});
    const sim::MoveList list = sim::buildMoves(p);
    const kinematics::Machine m = machine3();
    const sim::MotionPlan plan = sim::planMotion(list, m);
    EXPECT_NEAR(plan.endPauseSeconds, 1.5, 1e-12);
    const sim::PlannedMove& last = plan.moves.back();
    EXPECT_NEAR(plan.totalSeconds, last.end() + 1.5, 1e-12);
    const sim::CycleTimes c = sim::cycleTimes(list, plan, toolpath::programStats(p, {}));
    EXPECT_NEAR(c.planned.totalSeconds(), plan.totalSeconds, 1e-9);
    EXPECT_NEAR(c.planned.pauseSeconds, 7 + 1.5 + 1.5, 1e-9);  // tool change, ramp up, ramp down
    EXPECT_NEAR(c.plannedPerTool.at(1).totalSeconds(), plan.totalSeconds, 1e-9);
    ASSERT_EQ(c.sections.size(), 1u);
    EXPECT_NEAR(c.sections[0].planned.totalSeconds(), plan.totalSeconds, 1e-9);
    EXPECT_NEAR(sim::secondsPerOperation(p, list, plan).at(4), plan.totalSeconds, 1e-9);

    // Stopped before a last retract: the ramp down was counted at that move, not again.
    toolpath::Toolpath q = p;
    q.add(toolpath::Rapid{{0, 0, 50}});
    const sim::MotionPlan stopped = sim::planMotion(sim::buildMoves(q), m);
    EXPECT_DOUBLE_EQ(stopped.endPauseSeconds, 0);
    EXPECT_NEAR(stopped.moves.back().pauseSeconds, 1.5, 1e-12);
    EXPECT_NEAR(stopped.totalSeconds, plan.totalSeconds + stopped.moves.back().moveSeconds, 1e-9);
}

TEST(MotionPlan, InverseTimeMovesTakeTheirProgrammedTime)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {10, 0, 0}, 0));
    list.moves[0].minutes = 0.05;
    list.moves.push_back(feed({10, 0, 0}, {10, 20, 0}, 0));
    list.moves[1].minutes = 0.1;
    const sim::MotionPlan plan = sim::planMotion(list, machine3());
    EXPECT_DOUBLE_EQ(plan.moves[0].moveSeconds, 3);
    EXPECT_DOUBLE_EQ(plan.moves[1].moveSeconds, 6);
    EXPECT_DOUBLE_EQ(plan.totalSeconds, 9);
}

TEST(MotionPlan, CycleTimesPerToolAndSectionAddUpToTheTotal)
{
    toolpath::Toolpath p;
    toolpath::Tool t1, t2;
    t1.number = 1;
    t2.number = 2;
    p.add(toolpath::SectionBegin{"Face", "profile", 1});
    p.add(toolpath::ToolChange{t1});
    p.add(toolpath::Rapid{{0, 0, 10}});
    p.add(toolpath::Linear{{0, 0, 0}, 300});
    p.add(toolpath::Linear{{40, 0, 0}, 1200});
    p.add(toolpath::Dwell{1.5});
    p.add(toolpath::SectionEnd{});
    p.add(toolpath::SectionBegin{"Pocket", "pocket", 2});
    p.add(toolpath::ToolChange{t2});
    p.add(toolpath::Rapid{{40, 30, 10}});
    p.add(toolpath::Linear{{40, 30, -2}, 200});
    p.add(toolpath::Linear{{0, 30, -2}, 800});
    p.add(toolpath::SectionEnd{});
    const sim::MoveList list = sim::buildMoves(p);
    const kinematics::Machine m = machine3();
    const sim::MotionPlan plan = sim::planMotion(list, m);
    toolpath::StatsOptions so;
    so.rapidMmPerMin = m.rapidMmPerMin;
    const sim::CycleTimes c = sim::cycleTimes(list, plan, toolpath::programStats(p, so));
    EXPECT_NEAR(c.planned.totalSeconds(), plan.totalSeconds, 1e-9);
    double perTool = 0, perSection = 0;
    for (const auto& [tool, split] : c.plannedPerTool)
        perTool += split.totalSeconds();
    for (const auto& s : c.sections)
        perSection += s.planned.totalSeconds();
    EXPECT_NEAR(perTool, plan.totalSeconds, 1e-9);
    EXPECT_NEAR(perSection, plan.totalSeconds, 1e-9);
    ASSERT_EQ(c.sections.size(), 2u);
    EXPECT_EQ(c.sections[1].name, "Pocket");
    EXPECT_GE(c.planned.pauseSeconds, 1.5 + 2 * 7);  // the dwell and two tool changes
    // The simple estimate knows no acceleration and no tool change: it is shorter.
    EXPECT_GT(c.simpleSeconds, 0);
    EXPECT_LT(c.simpleSeconds, c.planned.totalSeconds());
    EXPECT_EQ(c.simplePerTool.size(), 2u);
}

TEST(MotionPlan, SecondsPerOperationFollowTheRecordsSources)
{
    toolpath::Toolpath p;
    toolpath::Tool t1;
    t1.number = 1;
    p.add(toolpath::Rapid{{0, 0, 30}});  // before any operation: from where, then a move
    p.add(toolpath::Rapid{{0, 0, 20}});
    p.add(toolpath::SectionBegin{"Face", "profile", 1}, {3, 0});
    p.add(toolpath::ToolChange{t1}, {3, -1});
    p.add(toolpath::Rapid{{0, 0, 10}}, {3, 1});
    p.add(toolpath::Linear{{40, 0, 10}, 1200}, {3, 2});
    p.add(toolpath::SectionEnd{}, {3, 3});
    p.add(toolpath::SectionBegin{"Other", "profile", 1}, {5, 0});
    p.add(toolpath::Linear{{40, 30, 10}, 600}, {5, 1});
    p.add(toolpath::SectionEnd{}, {5, 2});
    const sim::MoveList list = sim::buildMoves(p);
    const kinematics::Machine m = machine3();
    const sim::MotionPlan plan = sim::planMotion(list, m);
    const std::map<int, double> seconds = sim::secondsPerOperation(p, list, plan);
    ASSERT_EQ(seconds.size(), 3u);
    EXPECT_NEAR(seconds.at(-1) + seconds.at(3) + seconds.at(5), plan.totalSeconds, 1e-9);
    EXPECT_GE(seconds.at(3), m.toolChangeSeconds) << "the tool change counts for its operation";
    EXPECT_GT(seconds.at(5), 30.0 / 10.0) << "30 mm at 10 mm/s, and some acceleration";
    EXPECT_LT(seconds.at(-1), m.toolChangeSeconds);
}

TEST(MotionSamples, FixedStepSamplesFollowThePlan)
{
    sim::MoveList list;
    list.moves.push_back(feed({0, 0, 0}, {10, 0, 0}, 600));
    const kinematics::Machine m = machine3();
    const sim::MotionPlan plan = sim::planMotion(list, m);
    const auto samples = sim::sampleMotion(list, plan, m);
    ASSERT_EQ(samples.size(), std::size_t(std::floor(plan.totalSeconds / 0.003 + 1e-9)) + 1);
    EXPECT_NEAR(samples[1].at.time, 0.003, 1e-15);
    EXPECT_NEAR(samples[1].at.linear.x, 0.5 * 1000 * 0.003 * 0.003, 1e-12);
    EXPECT_NEAR(samples[1].feedMmPerMin, 1000 * 0.003 * 60, 1e-9);
    EXPECT_NEAR(samples[200].feedMmPerMin, 600, 1e-9);
    EXPECT_NEAR(samples.back().at.tip.x, plan.moves[0].distanceAt(samples.back().at.time), 1e-12);
    std::size_t streamed = 0;
    sim::sampleMotion(list, plan, m, [&](const sim::MotionSample&) { return ++streamed < 10; });
    EXPECT_EQ(streamed, 10u);  // the callback stopped it
}

// Seed 003's machine (A/C on the table, eq. 9 with r = P = 0) with the default rotary limits:
// 60 deg/s and 360 deg/s².
kinematics::Machine seed003Machine()
{
    kinematics::Machine m = machine3();
    m.kinematics.type = kinematics::ChainType::TableTable;
    m.kinematics.joints = {{"A", true, {-1, 0, 0}, {}}, {"C", true, {0, 0, -1}, {}}};
    for (const char* name : {"A", "C"}) {
        kinematics::Axis a;
        a.name = name;
        a.rotary = true;
        a.maxVelocity = kinematics::kDefaultRotaryDegPerMin;
        a.maxAcceleration = kinematics::kDefaultRotaryAccelerationDegPerS2;
        m.axes.push_back(a);
    }
    return m;
}

// A tool-tip move along X (on A's axis, so the linear axes only move X) while A tilts 30° in
// 10 mm: A turns 3° per mm, so its 60 deg/s caps the tip at 20 mm/s and its 360 deg/s² the
// acceleration at 120 mm/s², far below the programmed 100 mm/s and X's 1000 mm/s².
TEST(MotionPlan, ARotaryAxisLimitCapsAFiveAxisMovesTipSpeed)
{
    const kinematics::Machine m = seed003Machine();
    Move tilt = feed({0, 0, 0}, {10, 0, 0}, 6000);
    tilt.fiveAxis = true;
    tilt.setToAxis(kinematics::forwardKinematics(m.kinematics, {{}, {30, 0}}).axis);
    sim::MoveList list;
    list.moves.push_back(tilt);
    // The program's own angles (A 0 → 30, C 0): A turns evenly.
    toolpath::RotaryAxes from, to;
    from.known = to.known = toolpath::RotaryAxes::kA | toolpath::RotaryAxes::kC;
    to.aDeg = 30;
    list.moves[0].setFromMachine(from);
    list.moves[0].setToMachine(to);
    sim::PlannedMove p = sim::planMotion(list, m).moves[0];
    EXPECT_NEAR(p.cruiseSpeed, 20, 1e-9);
    EXPECT_NEAR(p.acceleration, 120, 1e-9);
    // Angles from the inverse kinematics of the axis as the move turns it (evenly: Move::axisAt),
    // so A turns evenly too: the same cap.
    list.moves[0].setFromMachine({});
    list.moves[0].setToMachine({});
    p = sim::planMotion(list, m).moves[0];
    EXPECT_NEAR(p.cruiseSpeed, 20, 1e-6);
    EXPECT_NEAR(p.acceleration, 120, 1e-6);
}

// C turns 90° under a tip held at X 50 of the workpiece. The tip stands on the workpiece, so the move is a rotation in
// place at C's default 60 deg/s and 360 deg/s²; the machine's X and Y carry the tip round the table.
TEST(MotionSamples, FiveAxisRotationInPlaceMovesTheLinearAxesThroughTheChain)
{
    const kinematics::Machine m = seed003Machine();
    Move turn = feed({50, 0, 0}, {50, 0, 0}, 0);
    turn.kind = MoveKind::Rapid;
    turn.fiveAxis = true;
    toolpath::RotaryAxes from, to;
    from.known = to.known = toolpath::RotaryAxes::kA | toolpath::RotaryAxes::kC;
    to.cDeg = 90;
    turn.setFromMachine(from);
    turn.setToMachine(to);
    sim::MoveList list;
    list.moves.push_back(turn);
    const sim::MotionPlan plan = sim::planMotion(list, m);
    EXPECT_TRUE(plan.moves[0].rotationOnly);
    EXPECT_NEAR(plan.totalSeconds, 90.0 / 60 + 60.0 / 360, 1e-9);
    const auto samples = sim::sampleMotion(list, plan, m);
    const auto& last = samples.back().at;
    for (const auto& s : samples) {
        const auto tool = kinematics::forwardKinematics(m.kinematics, {s.at.linear, s.at.rotaryDeg});
        ASSERT_NEAR(base::distance(tool.tip, {50, 0, 0}), 0, 1e-9);  // the tip never leaves its point
        ASSERT_NEAR(std::hypot(s.at.linear.x, s.at.linear.y), 50, 1e-9);
    }
    EXPECT_NEAR(last.rotaryDeg[1], 90 * plan.moves[0].distanceAt(last.time) / 90, 1e-9);
    EXPECT_NEAR(std::atan2(samples[300].at.linear.y, samples[300].at.linear.x) * 180 / kPi,
                -samples[300].at.rotaryDeg[1], 1e-6);  // C about -Z: the point turns clockwise
}

// A tilted working plane after three-axis moves: the tool turns from Z onto the plane's axis as
// a move of its own (sim::buildMoves), which takes the tilt's time at A's speed instead of a
// jump in no time (an infinite axis speed in the samples).
TEST(MotionPlan, ATurnOntoANewPlaneTakesTheRotaryAxesTime)
{
    const kinematics::Machine m = seed003Machine();
    toolpath::Toolpath program;
    program.add(toolpath::Rapid{{0, 0, 50}});
    program.add(toolpath::Rapid{{0, 0, 60}});
    toolpath::WorkingPlane plane;  // tilted 30° about X
    plane.zAxis = {0, -0.5, std::sqrt(0.75)};
    plane.xAxis = {1, 0, 0};
    program.add(plane);
    program.add(toolpath::Rapid{{0, 0, 70}});
    const sim::MoveList list = sim::buildMoves(program);
    ASSERT_EQ(list.moves.size(), 4u);  // standing at Z 50, up to 60, the turn, up to 70
    const sim::MotionPlan plan = sim::planMotion(list, m);
    EXPECT_TRUE(plan.moves[2].rotationOnly);
    EXPECT_NEAR(plan.moves[2].length, 30, 1e-6);  // degrees of A
    EXPECT_GT(plan.moves[2].moveSeconds, 30.0 / 60);
    double fastestA = 0;
    const auto samples = sim::sampleMotion(list, plan, m);
    for (std::size_t k = 1; k < samples.size(); ++k)
        fastestA = std::max(fastestA, std::abs(samples[k].at.rotaryDeg[0] - samples[k - 1].at.rotaryDeg[0]) /
                                          (samples[k].at.time - samples[k - 1].at.time));
    EXPECT_LE(fastestA, 60 + 1e-6);  // never above A's speed
}

// The playback's machine frame jumps into a program: the angles at each move's start come from
// the walk over the moves before it. A tilt to A 30 by the inverse kinematics, a tool change
// (stands: keeps them), then C turned by the program's own angles past 180 and on to 270: the
// start of the last move is at C 270, not wound back to -90.
TEST(MachineAxes, RotaryAtMoveStartsFollowTheProgram)
{
    const kinematics::Machine m = seed003Machine();
    Move tilt = feed({0, 0, 0}, {10, 0, 0}, 6000);
    tilt.fiveAxis = true;
    const std::array<double, 2> tilted{30, 0};
    tilt.setToAxis(kinematics::forwardKinematics(m.kinematics, {{}, tilted}).axis);
    Move turn = feed({10, 0, 0}, {10, 0, 0}, 0);
    turn.kind = MoveKind::Rapid;
    turn.fiveAxis = true;
    turn.setAxis(tilt.toAxis());
    toolpath::RotaryAxes from, to;
    from.known = to.known = toolpath::RotaryAxes::kA | toolpath::RotaryAxes::kC;
    from.aDeg = to.aDeg = 30;
    to.cDeg = 270;
    turn.setFromMachine(from);
    turn.setToMachine(to);
    Move last = feed({10, 0, 0}, {12, 0, 0}, 1000);
    last.fiveAxis = true;
    last.setAxis(kinematics::forwardKinematics(m.kinematics, {{}, {30, 270}}).axis);
    sim::MoveList list;
    list.moves = {tilt, pause(MoveKind::ToolChange, {10, 0, 0}), turn, last};
    const auto starts = sim::rotaryAtMoveStarts(m.kinematics, list);
    ASSERT_EQ(starts.size(), 4u);
    EXPECT_NEAR(starts[0][0], 0, 1e-12);
    EXPECT_NEAR(starts[1][0], 30, 1e-9);
    EXPECT_NEAR(starts[1][1], 0, 1e-9);
    EXPECT_EQ(starts[2], starts[1]);
    EXPECT_NEAR(starts[3][0], 30, 1e-9);
    EXPECT_NEAR(starts[3][1], 270, 1e-9);
    // Inside the last move the pose continues from there (the same solution, C on its turn).
    const auto inside = sim::machinePoseAt(m.kinematics, list.moves[3], 0.5, starts[3], 0);
    EXPECT_NEAR(inside.rotaryDeg[1], 270, 1e-6);
    EXPECT_TRUE(sim::rotaryAtMoveStarts(machine3().kinematics, list).empty());
}
