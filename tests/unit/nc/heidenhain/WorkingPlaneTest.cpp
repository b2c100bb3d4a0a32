// Tilted working planes in Klartext: PLANE SPATIAL (TURN, STAY with Q120..Q122), PLANE RESET,
// VECTOR and AXIAL, CYCL DEF 19 with the machine's axis angles (its frame is the machine's axes as
// the table turns them) and without a machine, the datum shift of CYCL DEF 7 before and after the
// tilt, the rotation of CYCL DEF 10, and the diagnostics of bad PLANE blocks. On the MAS MCVL
// 1000's B/C table.
#include "TestSupport.h"

#include "kinematics/Machine.h"
#include "toolpath/PlaneFrames.h"

#include <cmath>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

const double kS30 = 0.5, kC30 = std::sqrt(3.0) / 2;

kinematics::Machine mcvl1000()
{
    auto m = kinematics::loadMachine(std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines/mas-mcvl1000.json");
    EXPECT_TRUE(m.ok());
    return m.value();
}

Traced runOn(const kinematics::Machine* machine, std::string_view body)
{
    InterpretOptions options = fromOrigin();
    options.machine = machine;
    return run(program(body), options);
}

TEST(HeidenhainWorkingPlane, PlaneSpatialTurnTiltsTheFrameAndTheMovesStayInIt)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(&m, "2 L X+0 Y+0 Z+100 R0 FMAX\n"
                               "3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n"
                               "4 L X+10 Y+5 R0 FMAX\n"
                               "5 L Z+20 R0 FMAX\n"
                               "6 L Z+10 F100\n"
                               "7 PLANE RESET TURN MB MAX FMAX\n"
                               "8 L X+0 Y+0 Z+50 FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].zAxis, {kS30, 0, kC30});
    expectNear(planes[0].xAxis, {kC30, 0, -kS30});
    expectNear(planes[0].origin, {});
    EXPECT_FALSE(planes[1].tilted());
    EXPECT_EQ(r.lines<WorkingPlane>(), (std::vector<int>{4, 8}));
    // The plane's moves are 3-axis records in its frame; MB MAX retracts to the end of Z's travel
    // before each turn (RetractTest.cpp).
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 6u);
    expectNear(rapids[1].to, {0, 0, 660});
    EXPECT_NEAR(rapids[2].to.x, 10, 1e-9);
    EXPECT_NEAR(rapids[2].to.y, 5, 1e-9);
    expectNear(rapids[3].to, {10, 5, 20});
    expectNear(r.all<Linear>()[0].to, {10, 5, 10});
    expectNear(rapids[4].to, {10, 5, 660});
    expectNear(rapids[5].to, {0, 0, 50});  // TURN brought the table home: a 3-axis move again
}

TEST(HeidenhainWorkingPlane, StayLeavesTheAxesAndGivesTheirAnglesInQ120ToQ122)
{
    const kinematics::Machine m = mcvl1000();
    // SEQ+: B+30 with C+180 (the other branch of the same tool axis); the program turns them itself.
    const Traced r = runOn(&m, "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY SEQ+\n"
                               "3 L B+Q121 C+Q122 R0 FMAX\n"
                               "4 L X+1 Y+2 Z+3 R0 FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    expectNear(r.all<Rapid>()[0].to, {1, 2, 3});
    // The wrong angles: the tool stands off the plane's Z, which the trace cannot show: an error.
    const Traced wrong = runOn(&m, "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY SEQ+\n"
                                   "3 L B+30 C+0 R0 FMAX\n"
                                   "4 L X+1 Y+2 Z+3 R0 FMAX\n");
    EXPECT_TRUE(wrong.has(Severity::Error, 5, "60.000 degrees off the tilted working plane's Z axis"))
        << wrong.diagnostics().size();
}

TEST(HeidenhainWorkingPlane, CycleNineteenTakesTheMachinesAxesAsTheTableTurnsThem)
{
    const kinematics::Machine m = mcvl1000();
    // As the iTNC post writes it: B-30 C-180 points the tool along (-0.5, 0, 0.866); the tilted X is
    // the machine's X seen from the turned table, not the workpiece's X projected.
    const Traced r = runOn(&m, "2 L M140 MB MAX\n"
                               "3 CYCL DEF 19.0 WORKING PLANE\n"
                               "4 CYCL DEF 19.1 B-30 C-180\n"
                               "5 L C-180 B-30 R0 FMAX\n"
                               "6 L X-9.641 Y-12 R0 FMAX\n"
                               "7 L Z+60 R0 FMAX\n"
                               "8 CYCL DEF 19.0 WORKING PLANE\n"
                               "9 CYCL DEF 19.1 B+0 C+0\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].zAxis, {-kS30, 0, kC30});
    expectNear(planes[0].xAxis, {-kC30, 0, -kS30});
    EXPECT_FALSE(planes[1].tilted());
    expectNear(r.all<Rapid>().back().to, {-9.641, -12, 60});

    const Traced without = runOn(nullptr, "2 CYCL DEF 19.0 WORKING PLANE\n3 CYCL DEF 19.1 B-30 C-180\n"
                                          "4 CYCL DEF 19.1 B+0 C+0\n");
    EXPECT_TRUE(without.has(Severity::Error, 4, "CYCL DEF 19 gives the machine's rotary axis positions"));
    ASSERT_EQ(without.all<WorkingPlane>().size(), 1u);  // the reset needs no machine
    EXPECT_FALSE(without.all<WorkingPlane>()[0].tilted());
}

TEST(HeidenhainWorkingPlane, DatumShiftBeforeTheTiltMovesItsOriginAfterItShiftsInTheTiltedFrame)
{
    const Traced r = runOn(nullptr, "2 CYCL DEF 7.0 DATUM SHIFT\n"
                                    "3 CYCL DEF 7.1 X+10\n"
                                    "4 CYCL DEF 7.2 Y+20\n"
                                    "5 PLANE SPATIAL SPA+0 SPB+0 SPC+90 STAY\n"
                                    "6 L X+1 Y+0 Z+0 R0 FMAX\n"
                                    "7 CYCL DEF 7.0 DATUM SHIFT\n"
                                    "8 CYCL DEF 7.1 X+5\n"
                                    "9 L X+1 Y+0 Z+0 R0 FMAX\n"
                                    "10 PLANE RESET STAY\n"
                                    "11 L X+0 Y+0 Z+0 R0 FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].origin, {10, 20, 0});  // the plane turns about the shifted datum
    expectNear(planes[0].xAxis, {0, 1, 0});
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    expectNear(planes[0].toWorkpiece(rapids[0].to), {10, 21, 0});
    expectNear(planes[0].toWorkpiece(rapids[1].to), {10, 26, 0});  // X+5 along the tilted X
    expectNear(rapids[2].to, {10, 25, 0});                         // untilted, the datum stays where both shifts put it
}

TEST(HeidenhainWorkingPlane, VectorAndAxialForms)
{
    const kinematics::Machine m = mcvl1000();
    const Traced r = runOn(&m, "2 PLANE VECTOR BX+0 BY+2 BZ+0 NX+0 NY+0 NZ+3 TURN FMAX\n"
                               "3 PLANE AXIAL B-30 TURN FMAX\n"
                               "4 L X+1 Y+2 Z+3 R0 FMAX\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].xAxis, {0, 1, 0});
    expectNear(planes[0].zAxis, {0, 0, 1});
    // AXIAL B-30 with C at 0: the table tilts the workpiece, the tool stands along (0.5, 0, 0.866).
    expectNear(planes[1].zAxis, {kS30, 0, kC30});
    expectNear(planes[1].xAxis, {kC30, 0, -kS30});
}

TEST(HeidenhainWorkingPlane, BadPlaneBlocksAreDiagnosedOnTheirLines)
{
    const Traced r = runOn(nullptr, "2 PLANE SPATIAL SPA SPB+0 SPC+0 TURN\n"
                                    "3 PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN SEQ*\n"
                                    "4 PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+0\n"
                                    "5 PLANE EULER EULPR+0 EULNU+30 EULROT+0 TURN\n"
                                    "6 PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN FOO\n"
                                    "7 PLANE AXIAL B+30\n");
    EXPECT_TRUE(r.has(Severity::Error, 3, "SPA needs a value"));
    EXPECT_TRUE(r.has(Severity::Error, 4, "SEQ must be followed by + or -"));
    EXPECT_TRUE(r.has(Severity::Error, 5, "PLANE VECTOR needs a base vector"));
    EXPECT_TRUE(r.has(Severity::Warning, 6, "PLANE EULER is not traced"));
    EXPECT_TRUE(r.has(Severity::Error, 7, "unknown word 'FOO' in PLANE"));
    EXPECT_TRUE(r.has(Severity::Error, 8, "PLANE AXIAL gives the machine's rotary axis positions"));
    EXPECT_TRUE(r.all<WorkingPlane>().empty());
}

// CYCL DEF 10 ROTATION turns the coordinates about the working plane's tool axis (through the
// datum): ROT absolute, IROT added, 0 undoes it; in a CYCL DEF 19 plane it turns the machine's
// tilted X onto the plane's X, as the iTNC post writes it.
TEST(HeidenhainWorkingPlane, RotationCycleTurnsTheFrameAboutTheToolAxis)
{
    const Traced flat = runOn(nullptr, "2 L X+0 Y+0 Z+50 R0 FMAX\n"
                                       "3 CYCL DEF 10.0 ROTATION\n4 CYCL DEF 10.1 ROT+90\n"
                                       "5 L X+10 Y+0 FMAX\n"
                                       "6 CYCL DEF 10.0 ROTATION\n7 CYCL DEF 10.1 IROT-45\n"
                                       "8 L X+10 Y+0 FMAX\n"
                                       "9 CYCL DEF 10.0 ROTATION\n10 CYCL DEF 10.1 ROT+0\n");
    EXPECT_TRUE(flat.result.diagnostics.empty()) << flat.diagnostics()[0];
    const auto planes = flat.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 3u);
    expectNear(planes[0].xAxis, {0, 1, 0});
    expectNear(planes[0].zAxis, {0, 0, 1});
    expectNear(planes[0].toWorkpiece({10, 0, 50}), {0, 10, 50});
    expectNear(planes[1].xAxis, {std::sqrt(0.5), std::sqrt(0.5), 0});
    EXPECT_FALSE(planes[2].tilted());

    const kinematics::Machine m = mcvl1000();
    const Traced tilted = runOn(&m, "2 L X+0 Y+0 Z+100 R0 FMAX\n"
                                    "3 CYCL DEF 19.0 WORKING PLANE\n4 CYCL DEF 19.1 B-30 C-90\n"
                                    "5 L C-90 B-30 R0 FMAX\n"
                                    "6 CYCL DEF 10.0 ROTATION\n7 CYCL DEF 10.1 ROT-90\n");
    const auto turned = tilted.all<WorkingPlane>();
    ASSERT_EQ(turned.size(), 2u);
    // The tool axis stays; X turns 90 degrees clockwise about it (seen from the spindle).
    expectNear(turned[1].zAxis, turned[0].zAxis);
    expectNear(turned[1].xAxis, turned[0].yAxis() * -1.0);
    const Traced bad = runOn(nullptr, "2 CYCL DEF 10.0 ROTATION\n3 CYCL DEF 10.1 TURN+5\n");
    ASSERT_FALSE(bad.result.diagnostics.empty());
    EXPECT_EQ(bad.result.diagnostics[0].line, 4);
    EXPECT_NE(bad.result.diagnostics[0].message.find("ROT or IROT"), std::string::npos);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
