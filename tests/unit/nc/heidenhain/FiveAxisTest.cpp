// Five-axis Klartext read back through a machine's kinematics: M128 / FUNCTION TCPM (X Y Z the tip
// in the workpiece frame), machine coordinates without it (seed 000 eq. 20: Q = X·P), M126's
// shorter way, and the errors of words the machine cannot read. The numbers are seed 000's §3.4
// check, B = 30°, C = 40° on the MAS MCVL 1000's B/C table (B about +Y, C about +Z, through MRZP).
#include "TestSupport.h"

#include "kinematics/Machine.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

// The MAS MCVL 1000 of resources/machines/mas-mcvl1000.json: a B/C table whose axes meet at the
// origin, the workpiece zero (MRZP).
kinematics::Machine mcvl1000()
{
    kinematics::Machine m;
    m.id = "mas-mcvl1000";
    m.name = "MAS MCVL 1000";
    m.control = "heidenhain-itnc530";
    m.axes = {{"X", false, 0, 1016},
              {"Y", false, 0, 610},
              {"Z", false, 0, 660},
              {"B", true, -120, 30},
              {"C", true, -INFINITY, INFINITY, true}};
    m.kinematics.type = kinematics::ChainType::TableTable;
    m.kinematics.joints = {{"B", true, {0, 1, 0}, {}}, {"C", true, {0, 0, 1}, {}}};
    return m;
}

Traced runOn(const kinematics::Machine& machine, std::string_view body)
{
    InterpretOptions options = fromOrigin();
    options.machine = &machine;
    return run(program(body), options);
}

// Seed 000 eq. 14 for B = 30°, C = 40°.
const Vec3 kAxis3040{-std::cos(40 * std::numbers::pi / 180) * 0.5, std::sin(40 * std::numbers::pi / 180) * 0.5,
                     std::sqrt(3.0) / 2};

TEST(HeidenhainFiveAxis, M128TracesTheTipAndTheToolAxisOfTheRotaryAxes)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+10 Y+20 Z+5 B+30 C+40 F500 M128\n3 L X+15 F500\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    expectNear(moves[0].tip, {10, 20, 5});
    expectNear(moves[0].axis, kAxis3040, 1e-12);
    EXPECT_NEAR(moves[0].axis.x, -0.3830, 5e-5);  // seed 000 §3.4: K = (-0.3830, 0.3214, 0.8660)
    EXPECT_NEAR(moves[0].axis.y, 0.3214, 5e-5);
    EXPECT_NEAR(moves[0].axis.z, 0.8660, 5e-5);
    EXPECT_EQ(moves[0].machine.known, RotaryAxes::kB | RotaryAxes::kC);
    EXPECT_EQ(moves[0].machine.bDeg, 30);
    EXPECT_EQ(moves[0].machine.cDeg, 40);
    EXPECT_EQ(moves[0].feedMmPerMin, 500);
    // With TCPM the next X is the tip's, in the workpiece frame.
    expectNear(moves[1].tip, {15, 20, 5});
    EXPECT_TRUE(r.all<Linear>().empty());
    EXPECT_NE(r.trace().find("3 linear5 10.0000 20.0000 5.0000 axis -0.3830 0.3214 0.8660 b 30.0000 c 40.0000 f "
                             "500.0000"),
              std::string::npos)
        << r.trace();
}

TEST(HeidenhainFiveAxis, WithoutTcpmTheAxesAreTheMachinesAndTheTipFollowsTheTable)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+10 Y+0 Z+0 B+30 C+40 FMAX\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 1u);
    // Seed 000 eq. 20, Q = X·P with P = (10, 0, 0): (cC·cB·10, -sC·cB·10, sB·10).
    const double c = 40 * std::numbers::pi / 180, b = 30 * std::numbers::pi / 180;
    expectNear(moves[0].tip, {std::cos(c) * std::cos(b) * 10, -std::sin(c) * std::cos(b) * 10, 5}, 1e-9);
    EXPECT_NEAR(moves[0].tip.x, 6.6341, 5e-5);
    EXPECT_NEAR(moves[0].tip.y, -5.5667, 5e-5);
    expectNear(moves[0].axis, kAxis3040, 1e-12);
    EXPECT_EQ(moves[0].feedMmPerMin, 0);  // FMAX
}

TEST(HeidenhainFiveAxis, FunctionTcpmAndItsResetConvertTheProgrammedPosition)
{
    const kinematics::Machine m = mcvl1000();
    // B+90 with TCPM off: the tip at machine X+10 lies at workpiece Z+10 (the table turned the part).
    const Traced r = runOn(m, "2 L X+10 Y+0 Z+0 B+90 C+0 FMAX\n"
                              "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                              "4 L IZ+5 F100\n"
                              "5 FUNCTION RESET TCPM\n"
                              "6 L IX+1 F100\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 3u);
    expectNear(moves[0].tip, {0, 0, 10}, 1e-9);
    expectNear(moves[0].axis, {-1, 0, 0}, 1e-12);
    expectNear(moves[1].tip, {0, 0, 15}, 1e-9);  // IZ in the workpiece frame under TCPM
    expectNear(moves[2].tip, {0, 0, 16}, 1e-9);  // IX of the machine again: the part turned, +Z of the part
}

TEST(HeidenhainFiveAxis, M126TurnsTheEndlessAxisTheShorterWay)
{
    const kinematics::Machine m = mcvl1000();
    const Traced shorter = runOn(m, "2 L X+0 Y+0 Z+50 B+0 C+355 FMAX M128 M126\n3 L C+5 FMAX\n4 L C+0 FMAX M127\n");
    EXPECT_EQ(shorter.count(Severity::Error), 0u) << shorter.diagnostics()[0];
    const auto moves = shorter.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 3u);
    EXPECT_EQ(moves[0].machine.cDeg, 355);
    EXPECT_EQ(moves[1].machine.cDeg, 365);  // C355 -> C5 is +10 degrees
    EXPECT_EQ(moves[2].machine.cDeg, 0);    // M127: the position as written
    expectNear(moves[1].tip, {0, 0, 50});

    const Traced along = runOn(m, "2 L X+0 Y+0 Z+50 B+0 C+355 FMAX M128\n3 L C+5 FMAX\n");
    ASSERT_EQ(along.all<ToolAxisMove>().size(), 2u);
    EXPECT_EQ(along.all<ToolAxisMove>()[1].machine.cDeg, 5);  // without M126: -350 degrees
}

TEST(HeidenhainFiveAxis, BackToZeroIsTheLastFiveAxisMoveAndThreeAxisMovesFollow)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+0 Y+0 Z+50 B-30 C+90 FMAX M128\n3 L B+0 C+0 FMAX\n4 L X+5 FMAX\n");
    EXPECT_EQ(r.all<ToolAxisMove>().size(), 2u);
    expectNear(r.all<ToolAxisMove>()[1].axis, {0, 0, 1}, 1e-12);
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    expectNear(r.all<Rapid>()[0].to, {5, 0, 50});
}

TEST(HeidenhainFiveAxis, AThreeAxisProgramTracesAsWithoutTheMachine)
{
    const kinematics::Machine m = mcvl1000();
    const std::string body = "2 L X+0 Y+0 Z+5 B+0 C+0 FMAX M3 M126\n3 L Z-2 F100\n4 CC X+5 Y+0\n"
                             "5 C X+0 Y+0 DR+\n6 L Z+50 FMAX M128\n7 L X+10 FMAX M129\n";
    InterpretOptions options = fromOrigin();
    options.machine = &m;
    const Traced on = run(program(body), options);
    const Traced off = run(program(body));
    EXPECT_EQ(on.trace(), off.trace());
    EXPECT_TRUE(on.all<ToolAxisMove>().empty());
    EXPECT_EQ(on.count(Severity::Error), 0u) << on.diagnostics()[0];
}

TEST(HeidenhainFiveAxis, WordsTheMachineCannotReadAreErrorsWithTheirColumn)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+10 A+20 FMAX\n3 L C+40 FMAX\n4 L IB+5 FMAX\n5 L X+3 FMAX\n");
    EXPECT_TRUE(r.has(Severity::Error, 3, "the MAS MCVL 1000 has no A axis")) << r.diagnostics()[0];
    EXPECT_EQ(r.result.diagnostics[0].column, 10);
    // C turned while B is unknown: the tool axis needs B.
    EXPECT_TRUE(r.has(Severity::Error, 4, "B is unknown here"));
    EXPECT_TRUE(r.has(Severity::Error, 5, "B is unknown here"));
    // Nothing moved on a guess; the program runs on.
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_EQ(r.all<Rapid>()[0].to.x, 3);
}

TEST(HeidenhainFiveAxis, WithoutAMachineRotaryWordsWarnAndMoveNothing)
{
    const Traced r = run(program("2 L X+10 B+30 C+40 FMAX M128\n"));
    EXPECT_EQ(r.count(Severity::Error), 0u);
    EXPECT_TRUE(r.has(Severity::Warning, 3, "need a five-axis machine (--machine, or the NC inspector's Machine)"));
    EXPECT_TRUE(r.has(Severity::Warning, 3, "M128"));
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
}

TEST(HeidenhainFiveAxis, CyclesAndCirclesWithTheTableTurned)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+0 Y+0 Z+10 B+0 C+90 FMAX\n"
                              "3 CYCL DEF 200 DRILLING Q200=2 Q201=-5 Q206=100 Q202=5 Q210=0 Q203=+0 Q204=50 Q211=0\n"
                              "4 CYCL CALL\n"
                              "5 CC X+0 Y+0\n"
                              "6 L X+10 Y+0 F100\n"
                              "7 C X+0 Y+10 DR+ C+5\n"
                              "8 C X+0 Y+10 DR+\n");
    EXPECT_TRUE(r.has(Severity::Error, 5, "cycle called with the rotary axes turned"));
    EXPECT_TRUE(r.has(Severity::Error, 8, "C in a circle block"));
    EXPECT_TRUE(r.all<Cycle>().empty());
    // The circle of the machine's axes about the turned table: C+90 turns the part by -90 about Z.
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].to, {10, 0, 10}, 1e-9);
    expectNear(arcs[0].center, {0, 0, 10}, 1e-9);
    expectNear(arcs[0].normal, {0, 0, 1}, 1e-12);
}

TEST(HeidenhainFiveAxis, M140RetractsAlongTheToolAxis)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+0 Y+0 Z+0 B+30 C+40 F100 M128\n3 L M140 MB+10\n");
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    expectNear(moves[1].tip, kAxis3040 * 10, 1e-9);
    EXPECT_EQ(moves[1].feedMmPerMin, 0);
}

// The five-axis post's frame of an operation: M140 MB MAX, the table turned up there, TCPM on,
// the first move giving every axis. The retract goes to the end of Z's travel (RetractTest.cpp),
// the table turns up there and the tool comes down from it; after the second retract the table
// turns home at the top of Z again.
TEST(HeidenhainFiveAxis, AfterM140MbMaxTheTableTurnsAtTheTopOfTheTravel)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 L X+0 Y+0 Z+50 R0 FMAX M3\n"
                              "3 L M140 MB MAX\n"
                              "4 L C+40 B+30 FMAX\n"
                              "5 L M128\n"
                              "6 L X+10 FMAX\n"
                              "7 L X+10 Y+20 Z+50 C+40 B+30 FMAX\n"
                              "8 L M140 MB MAX\n"
                              "9 L M129\n"
                              "10 L C+0 B+0 FMAX\n"
                              "11 L X+0 Y+0 FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    expectNear(rapids[1].to, {0, 0, 660});
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 5u);  // blocks 4, 6, 7, 8 and 10
    // Block 4 without TCPM: the machine's axes stay at the top while the table turns under them.
    EXPECT_NEAR(kinematics::linearAxesFor(m.kinematics, moves[0].tip, {30, 40}).z, 660, 1e-9);
    expectNear(moves[2].tip, {10, 20, 50});
    expectNear(moves[2].axis, kAxis3040, 1e-12);
    EXPECT_NEAR(kinematics::linearAxesFor(m.kinematics, moves[3].tip, {30, 40}).z, 660, 1e-9);
    // Back to 3-axis: the table home, the tool still at the top of Z.
    EXPECT_NEAR(rapids[2].to.z, 660, 1e-9);
    EXPECT_TRUE(rapids[2].axes.all());
}

TEST(HeidenhainFiveAxis, FunctionTcpmWordsAreChecked)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(m, "2 FUNCTION TCPM F TCP AXIS POSITION PATHCTRL AXIS\n3 FUNCTION TCPM F CONT WOBBLE\n");
    EXPECT_TRUE(r.has(Severity::Error, 3, "AXIS of FUNCTION TCPM is POS or SPAT, not 'POSITION'"));
    EXPECT_TRUE(r.has(Severity::Error, 4, "unknown word 'WOBBLE'"));
}

TEST(HeidenhainFiveAxis, AxisSpatGivesTheToolAxisBySpatialAngles)
{
    const kinematics::Machine m = mcvl1000();
    // SPB+30 then SPC+... : the tool turned about Y by 30 degrees, then about Z.
    const Traced r = runOn(m, "2 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n3 L X+1 Y+2 Z+3 B+30 C+0 F100\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 1u);
    expectNear(moves[0].tip, {1, 2, 3});
    expectNear(moves[0].axis, {0.5, 0, std::sqrt(3.0) / 2}, 1e-9);
    EXPECT_TRUE(moves[0].machine.has(RotaryAxes::kB));
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
