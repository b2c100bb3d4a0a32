// Drilling cycles: CYCLE81..85 as the 828D post writes them, with MCALL or per hole; one Cycle
// record per hole with clearance = RTP, R plane = RFP + SDIS, top = RFP, bottom = DP or RFP - DPR.
#include "TestSupport.h"

namespace camwb::nc::sinumerik::test {
namespace {

using toolpath::CycleKind;

TEST(SinumerikCycles, ModalCallDrillsAtEveryPosition)
{
    const NcRun r = run("G0 X0 Y0 Z50\nF120\nMCALL CYCLE81(25,0,2,-10)\nX10 Y10\nX20\nY20\nMCALL\nG0 X30\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto cycles = r.all<toolpath::Cycle>();
    ASSERT_EQ(cycles.size(), 3u);
    EXPECT_EQ(cycles[0].kind, CycleKind::Drill);
    EXPECT_DOUBLE_EQ(cycles[0].clearanceZ, 25);
    EXPECT_DOUBLE_EQ(cycles[0].retractZ, 2);
    EXPECT_DOUBLE_EQ(cycles[0].topZ, 0);
    EXPECT_DOUBLE_EQ(cycles[0].bottomZ, -10);
    EXPECT_DOUBLE_EQ(cycles[0].feedMmPerMin, 120);
    EXPECT_TRUE(cycles[0].returnToClearance);
    ASSERT_EQ(cycles[2].holes.size(), 1u);
    EXPECT_DOUBLE_EQ(cycles[2].holes[0].x, 20);
    EXPECT_DOUBLE_EQ(cycles[2].holes[0].y, 20);
    // The positioning rapids are the cycles' own moves; after MCALL the rapid is traced again and
    // starts at the return plane.
    const auto rapids = r.all<toolpath::Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_DOUBLE_EQ(rapids[1].to.z, 25);
    EXPECT_EQ(r.path.source(r.path.size() - 1).line, 8);
}

TEST(SinumerikCycles, ParameterListsOfThePost)
{
    const NcRun r = run("M3 S1800\nG0 X0 Y0 Z25\nF100\n"
                        "CYCLE82(2.000,0.000,2.000,-4.000,,0.5)\n"
                        "CYCLE83(25.000,0.000,3.000,-30.000,,-6.000,,0,0,0,1,1,,6.000,0.500,0.25,0.500)\n"
                        "CYCLE83(2.000,-5.000,7.000,-25.000,,-9.000,,0,0,0,1,0,,4.000,0.500,0,0.500)\n"
                        "CYCLE83(15.000,3.000,0.000,-12.000,,0.000,,0,0,0,1,1,,3.000,0.500,0,0.500)\n"
                        "CYCLE84(25.000,0.000,4.000,-12.000,,0,3,,1.250,0,1800,1800)\n"
                        "CYCLE85(2.000,0.000,2.000,-15.000,,1,80,80)\n"
                        "CYCLE81(10,0,2,,5)\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto c = r.all<toolpath::Cycle>();
    ASSERT_EQ(c.size(), 7u);
    EXPECT_EQ(c[0].kind, CycleKind::DrillDwell);
    EXPECT_DOUBLE_EQ(c[0].dwellSeconds, 0.5);
    EXPECT_EQ(c[1].kind, CycleKind::Peck);
    EXPECT_DOUBLE_EQ(c[1].peckMm, 6);
    EXPECT_DOUBLE_EQ(c[1].dwellSeconds, 0.25);
    EXPECT_DOUBLE_EQ(c[1].retractZ, 3);
    EXPECT_EQ(c[2].kind, CycleKind::ChipBreak);
    EXPECT_DOUBLE_EQ(c[2].peckMm, 4);
    EXPECT_DOUBLE_EQ(c[2].topZ, -5);
    EXPECT_DOUBLE_EQ(c[2].retractZ, 2);
    EXPECT_DOUBLE_EQ(c[3].peckMm, 3);  // FDEP 0 from RFP 3
    EXPECT_EQ(c[4].kind, CycleKind::Tap);
    EXPECT_DOUBLE_EQ(c[4].feedMmPerMin, 2250);  // 1.25 mm x 1800 rpm
    EXPECT_EQ(c[5].kind, CycleKind::Bore);
    EXPECT_DOUBLE_EQ(c[5].feedMmPerMin, 80);
    EXPECT_DOUBLE_EQ(c[5].dwellSeconds, 1);
    EXPECT_DOUBLE_EQ(c[6].bottomZ, -5);  // DPR
}

TEST(SinumerikCycles, InchAndErrors)
{
    const NcRun r = run("G700 F10\nG0 X1 Y1 Z1\nCYCLE81(1.0000,0.0000,0.1000,-0.5000)\nCYCLE81(,0,2,-1)\n"
                        "CYCLE81(5,0,2)\nCYCLE93(1,2,3)\nCYCLE800(0,\"TABLE\",200000,57,0,0,0,0,0,0,0,0,0,1)\n");
    const auto c = r.all<toolpath::Cycle>();
    ASSERT_EQ(c.size(), 1u) << r.diagnostics();
    EXPECT_DOUBLE_EQ(c[0].clearanceZ, 25.4);
    EXPECT_NEAR(c[0].retractZ, 2.54, 1e-12);
    EXPECT_DOUBLE_EQ(c[0].bottomZ, -12.7);
    EXPECT_DOUBLE_EQ(c[0].feedMmPerMin, 254);
    EXPECT_NE(r.find("RTP (return plane) is missing"), nullptr);
    EXPECT_NE(r.find("no depth"), nullptr);
    EXPECT_NE(r.find("CYCLE93 is not interpreted"), nullptr);
    // Every angle and offset 0 (a real 840D program's _ST 200000): the untilted plane, no diagnostic.
    ASSERT_EQ(r.all<toolpath::WorkingPlane>().size(), 1u);
    EXPECT_FALSE(r.all<toolpath::WorkingPlane>()[0].tilted());
    EXPECT_EQ(r.find("CYCLE800"), nullptr);
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
