// CYCLE800 read back: the swivelled frame from _MODE's axis sequence (27: Z, Y', X'' — the
// spatial angles of PLANE SPATIAL; 57: X, Y', Z''), the offsets before (_X0.._Z0) and after
// (_X1.._Z1) the turn, additive planes, direct mode through the machine, CYCLE800() as the reset,
// the moves after it in the swivelled frame, and the diagnostics of what is not traced.
#include "TestSupport.h"

#include "kinematics/Machine.h"
#include "toolpath/PlaneFrames.h"

#include <cmath>

namespace camwb::nc::sinumerik::test {
namespace {

using namespace camwb::toolpath;

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SinumerikSwivel, ModeTwentySevenIsThePlaneOfTheSpatialAnglesWithItsOrigin)
{
    const NcRun r = run("G0 X0 Y0 Z100\n"
                        "CYCLE800(1,\"TC1\",0,27,10,20,0,30,20,10,0,0,0,1)\n"
                        "G0 X1 Y2\nG0 Z5\nG1 Z-1 F100\n"
                        "CYCLE800()\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics();
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    const WorkingPlane spatial = planeFromSpatialAngles(10, 20, 30, {10, 20, 0});
    expectNear(planes[0].origin, spatial.origin);
    expectNear(planes[0].xAxis, spatial.xAxis);
    expectNear(planes[0].zAxis, spatial.zAxis);
    EXPECT_FALSE(planes[1].tilted());
    // _FR 1 retracted first: the position is unknown until the blocks give it, in the plane's frame.
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    EXPECT_FALSE(rapids[1].axes.has(2));
    expectNear(rapids[2].to, {1, 2, 5});
    expectNear(r.all<Linear>()[0].to, {1, 2, -1});
}

TEST(SinumerikSwivel, ModeFiftySevenTurnsAboutXThenTheTurnedY)
{
    // X by 90, then Y' by 90: the tool axis lies along +X and the plane's X along +Y (the other
    // order would point the tool along -Y).
    const NcRun r = run("CYCLE800(0,\"\",0,57,0,0,0,90,90,0,0,0,0,0)\n");
    ASSERT_EQ(r.all<WorkingPlane>().size(), 1u);
    expectNear(r.all<WorkingPlane>()[0].zAxis, {1, 0, 0});
    expectNear(r.all<WorkingPlane>()[0].xAxis, {0, 1, 0});
}

TEST(SinumerikSwivel, OffsetsBeforeAndAfterTheTurnAndAdditivePlanes)
{
    // About Z by 90: X1 5 is along the turned X, i.e. the workpiece's +Y.
    const NcRun r = run("CYCLE800(0,\"\",0,27,1,0,0,90,0,0,5,0,0,0)\n"
                        "CYCLE800(0,\"\",1,27,0,0,0,90,0,0,0,0,0,0)\n");
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].origin, {1, 5, 0});
    expectNear(planes[0].xAxis, {0, 1, 0});
    expectNear(planes[1].origin, {1, 5, 0});  // _ST 1: on top of the first, 180 in all
    expectNear(planes[1].xAxis, {-1, 0, 0});
}

TEST(SinumerikSwivel, DirectModeTakesTheRotaryAxesThroughTheMachine)
{
    auto machine = kinematics::loadMachine(std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines/dmu50-840d.json");
    ASSERT_TRUE(machine.ok());
    InterpretOptions options = fromOrigin();
    options.machine = &machine.value();
    // The DMU's B turns the table about -Y: B30 tilts the tool towards +X as the workpiece sees it.
    // The zero plane with _DIR turns the table home.
    const NcRun r = run("CYCLE800(0,\"TC1\",0,192,0,0,0,30,0,0,0,0,0,1)\nG0 X1 Y2 Z3\n"
                        "CYCLE800(1,\"TC1\",0,27,0,0,0,0,0,0,0,0,0,1)\nG0 X0 Y0 Z50\n",
                        {}, options);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics();
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 2u);
    expectNear(planes[0].zAxis, {0.5, 0, std::sqrt(3.0) / 2});
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());  // in the plane and after the table home: 3-axis moves
    ASSERT_EQ(r.all<Rapid>().size(), 2u);
    expectNear(r.all<Rapid>()[0].to, {1, 2, 3});

    const NcRun without = run("G0 X0 Y0 Z0\nCYCLE800(0,\"TC1\",0,192,0,0,0,30,0,0,0,0,0,1)\n");
    ASSERT_NE(without.find("direct mode gives rotary axis positions"), nullptr) << without.diagnostics();
    EXPECT_EQ(without.find("direct mode")->line, 2);
    EXPECT_TRUE(without.all<WorkingPlane>().empty());
}

TEST(SinumerikSwivel, WhatIsNotTracedIsAnErrorOnItsLine)
{
    const NcRun r = run("G0 X0 Y0 Z0\n"
                        "CYCLE800(0,\"\",0,3,0,0,0,10,0,0,0,0,0,0)\n"
                        "CYCLE800(0,\"\",0,64,0,0,0,10,20,0,0,0,0,0)\n"
                        "CYCLE800(0,\"\",0,128,0,0,0,10,20,0,0,0,0,0)\n");
    ASSERT_NE(r.find("bits 3-2 name no axis for B"), nullptr) << r.diagnostics();
    EXPECT_EQ(r.find("bits 3-2")->line, 2);
    ASSERT_NE(r.find("swivel by solid angles is not traced"), nullptr);
    EXPECT_EQ(r.find("solid angles")->line, 3);
    ASSERT_NE(r.find("swivel by projection angles is not traced"), nullptr);
    EXPECT_EQ(r.find("projection angles")->line, 4);
    EXPECT_EQ(r.errors(), 3);
    EXPECT_TRUE(r.all<WorkingPlane>().empty());
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
