// M140 MB MAX and PLANE ... MB MAX read through a machine: the retract goes up the tool axis until
// the first linear axis reaches the end of its travel, in machine coordinates as the machine's
// kinematic chain places the workpiece (its workpieceZero). Without a machine, or with one whose
// file has no chain, the retract is not traced and the axes it moves become unknown (a warning).
// On the MAS MCVL 1000's B/C table and a head-table machine with a short X travel.
#include "TestSupport.h"

#include "kinematics/KinematicChain.h"
#include "kinematics/Machine.h"

#include <cmath>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

kinematics::Machine mcvl1000()
{
    auto m = kinematics::loadMachine(std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines/mas-mcvl1000.json");
    EXPECT_TRUE(m.ok());
    return m.value();
}

// A head-table machine (C on the table about Z, B in the head about Y) whose X travel ends at
// 100 mm: with the head tilted the tool axis leans towards +X, so X ends the retract long before Z.
kinematics::Machine shortX()
{
    kinematics::Machine m;
    m.id = "short-x";
    m.axes = {{"X", false, 0, 100},
              {"Y", false, 0, 610},
              {"Z", false, 0, 660},
              {"B", true, -90, 90},
              {"C", true, -INFINITY, INFINITY, true}};
    m.kinematics.type = kinematics::ChainType::HeadTable;
    m.kinematics.joints = {{"C", true, {0, 0, 1}, {}}, {"B", false, {0, 1, 0}, {}}};
    return m;
}

Traced runOn(const kinematics::Machine* machine, std::string_view body, bool fromZero = true)
{
    InterpretOptions options = fromZero ? fromOrigin() : InterpretOptions{};
    options.machine = machine;
    return run(program(body), options);
}

TEST(HeidenhainRetract, ThreeAxisMbMaxGoesToTheTopOfTheZTravel)
{
    kinematics::Machine m = mcvl1000();
    const Traced r = runOn(&m, "2 L X+10 Y+20 Z+50 R0 FMAX\n3 L M140 MB MAX\n4 L X+30 FMAX\n5 L M140 MB-10\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 4u);
    expectNear(rapids[1].to, {10, 20, 660});  // Z 0..660, the workpiece zero at the machine's
    EXPECT_TRUE(rapids[1].axes.all());
    expectNear(rapids[2].to, {30, 20, 660});
    expectNear(rapids[3].to, {30, 20, 650});    // MB with a distance as before
    EXPECT_TRUE(r.all<UnknownAxes>().empty());  // traced: nothing unknown
    EXPECT_EQ(r.lines<Rapid>()[1], 4);

    // The chain's workpiece zero 100 mm up the machine's Z: the travel ends 560 mm above it.
    m.kinematics.workpieceZero = {0, 0, 100};
    const Traced shifted = runOn(&m, "2 L X+10 Y+20 Z+50 R0 FMAX\n3 L M140 MB MAX\n");
    ASSERT_EQ(shifted.all<Rapid>().size(), 2u);
    expectNear(shifted.all<Rapid>()[1].to, {10, 20, 560});
}

TEST(HeidenhainRetract, WithTheTableTurnedTheRetractFollowsTheToolAxisToTheEndOfZ)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(&m, "2 L X+10 Y+20 Z+50 B-30 C+40 FMAX M128\n3 L M140 MB MAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[1].feedMmPerMin, 0);
    const Vec3 up = moves[1].tip - moves[0].tip;
    EXPECT_NEAR(up.normalized().dot(moves[0].axis), 1, 1e-12);  // along the tool axis, upwards
    // On a table-table machine the tool is the machine's Z: only Z moves, up to its end.
    const Vec3 from = kinematics::linearAxesFor(m.kinematics, moves[0].tip, {-30, 40});
    const Vec3 to = kinematics::linearAxesFor(m.kinematics, moves[1].tip, {-30, 40});
    EXPECT_NEAR(to.z, 660, 1e-9);
    EXPECT_NEAR(to.x, from.x, 1e-9);
    EXPECT_NEAR(to.y, from.y, 1e-9);
}

TEST(HeidenhainRetract, TheFirstAxisToReachItsTravelEndStopsTheRetract)
{
    const kinematics::Machine m = shortX();
    const Traced r = runOn(&m, "2 TOOL DEF 1 L+80 R3\n"
                               "3 TOOL CALL 1 Z S3000\n"
                               "4 L X+10 Y+20 Z+50 C+0 B+60 FMAX M128\n"
                               "5 L M140 MB MAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_NEAR((moves[1].tip - moves[0].tip).normalized().dot(moves[0].axis), 1, 1e-12);
    const Vec3 from = kinematics::linearAxesFor(m.kinematics, moves[0].tip, {0, 60}, 80);
    const Vec3 to = kinematics::linearAxesFor(m.kinematics, moves[1].tip, {0, 60}, 80);
    ASSERT_LT(from.x, 100);
    EXPECT_NEAR(to.x, 100, 1e-9);  // X's end, not Z's (which lies much further up the axis)
    EXPECT_LT(to.z, 660);
    EXPECT_GT(to.z, from.z);
}

TEST(HeidenhainRetract, PlaneTurnMbMaxRetractsInTheOldFrameBeforeTheTableTurns)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(&m, "2 L X+0 Y+0 Z+100 R0 FMAX\n"
                               "3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n"
                               "4 L X+10 Y+5 R0 FMAX\n"
                               "5 L Z+20 R0 FMAX\n"
                               "6 PLANE RESET TURN MB MAX FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 5u);
    EXPECT_EQ(r.lines<Rapid>(), (std::vector<int>{3, 4, 5, 6, 7}));
    EXPECT_EQ(r.lines<WorkingPlane>(), (std::vector<int>{4, 7}));
    expectNear(rapids[1].to, {0, 0, 660});  // up Z before the turn
    // In the tilted frame the tool is the machine's Z and the table turns about the workpiece
    // zero: the plane's Z is the machine's, so its end is at plane Z 660.
    EXPECT_TRUE(rapids[2].axes.all());
    expectNear(rapids[3].to, {10, 5, 20});
    expectNear(rapids[4].to, {10, 5, 660});
}

TEST(HeidenhainRetract, WithoutAMachineNothingIsInventedAndTheAxisIsUnknown)
{
    const Traced r = runOn(nullptr, "2 L X+10 Y+20 Z+50 R0 FMAX\n3 L M140 MB MAX\n4 L X+30 FMAX\n");
    EXPECT_TRUE(
        r.has(Severity::Warning, 4,
              "M140 MB MAX: the retract to the travel limit is not traced; Z is unknown until a block gives it"));
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[1].axes.bits, AxisMask::kX | AxisMask::kY);
    // The sinks hear that Z went somewhere unknown, at the retract's block: the next move is not
    // drawn or cut from Z 50.
    ASSERT_EQ(r.all<UnknownAxes>().size(), 1u);
    EXPECT_EQ(r.all<UnknownAxes>()[0].axes.bits, AxisMask::kZ);
    EXPECT_EQ(r.lines<UnknownAxes>(), std::vector<int>{4});
    EXPECT_NE(r.trace().find("4 unknown z\n5 rapid x 30.0000 y 20.0000 "), std::string::npos) << r.trace();

    // A machine file without a kinematic chain does not place the workpiece in its travel either.
    kinematics::Machine threeAxis = mcvl1000();
    threeAxis.kinematics = {};
    const Traced t = runOn(&threeAxis, "2 L X+10 Y+20 Z+50 R0 FMAX\n3 L M140 MB MAX\n4 L X+30 FMAX\n");
    EXPECT_TRUE(t.has(Severity::Warning, 4, "gives no kinematic chain"));
    ASSERT_EQ(t.all<Rapid>().size(), 2u);
    EXPECT_FALSE(t.all<Rapid>()[1].axes.has(2));

    // From an unknown position nothing is lost, and nothing is said.
    const kinematics::Machine m = mcvl1000();
    const Traced unknown = runOn(&m, "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n", false);
    EXPECT_TRUE(unknown.result.diagnostics.empty()) << unknown.diagnostics()[0];
    EXPECT_TRUE(unknown.all<Rapid>().empty());
    EXPECT_TRUE(unknown.all<UnknownAxes>().empty());
}

// M91/M92 positions are in machine coordinates: "L Z+0 R0 FMAX M91" is the top of Z, not workpiece
// Z0, so Z becomes unknown (said to the sinks) until a block gives it; X and Y stay.
TEST(HeidenhainRetract, MachineCoordinatesLeaveTheirAxesUnknown)
{
    const Traced r = runOn(nullptr, "2 L X+10 Y+20 Z-5 R0 FMAX\n3 L Z+0 R0 FMAX M91\n4 L X+30 FMAX\n"
                                    "5 L Z+5 FMAX\n6 L Y+0 R0 FMAX M92\n");
    EXPECT_TRUE(r.has(Severity::Warning, 4, "M91/M92: a move in machine coordinates is not traced"));
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    EXPECT_EQ(rapids[1].axes.bits, AxisMask::kX | AxisMask::kY);  // not at Z0 nor at Z-5
    EXPECT_TRUE(rapids[2].axes.all());
    expectNear(rapids[2].to, {30, 20, 5});
    ASSERT_EQ(r.all<UnknownAxes>().size(), 2u);
    EXPECT_EQ(r.all<UnknownAxes>()[0].axes.bits, AxisMask::kZ);
    EXPECT_EQ(r.all<UnknownAxes>()[1].axes.bits, AxisMask::kY);
    EXPECT_EQ(r.lines<UnknownAxes>(), (std::vector<int>{4, 7}));
}

// Where the machine cannot say where the travel ends, the retract is not traced and says why.
TEST(HeidenhainRetract, AnUntracedRetractSaysWhy)
{
    const kinematics::Machine m = mcvl1000();
    // Above the top of Z already (the file's workpiece zero at the bottom of the travel).
    const Traced above = runOn(&m, "2 L X+10 Y+20 Z+700 R0 FMAX\n3 L M140 MB MAX\n4 L X+30 FMAX\n");
    EXPECT_TRUE(above.has(Severity::Warning, 4, "Z stands at 700.000, past the end of its travel at 660.000"));
    ASSERT_EQ(above.all<Rapid>().size(), 2u);
    EXPECT_FALSE(above.all<Rapid>()[1].axes.has(2));
    // A plane whose rotary axes the program has not turned yet (STAY): the machine's pose is unknown.
    const Traced stay = runOn(&m, "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n3 L X+0 Y+0 Z+50 R0 FMAX\n"
                                  "4 L M140 MB MAX\n");
    EXPECT_TRUE(
        stay.has(Severity::Warning, 5, "the rotary axes have not been positioned for the tilted working plane"));
    ASSERT_EQ(stay.all<Rapid>().size(), 1u);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
