// Motion: rapids and feeds, absolute and incremental, AC/IC, units, DIAMON, arcs in all planes by
// centre, CR and AR, helices with TURN, the radius check, records before and after the motion.
#include "TestSupport.h"
#include "nc/ToolTable.h"

#include "../../../support/DecimalCommaLocale.h"

#include <cmath>

namespace camwb::nc::sinumerik::test {
namespace {

using toolpath::Vec3;

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-9)
{
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(SinumerikMotion, ModalMotionAbsoluteIncremental)
{
    const NcRun r = run("G0 X10 Y20 Z5\nG1 Z-1 F100\nX20\nG91 X5 Y-5\nG90 X=IC(1) Y=AC(3)\nG0 Z10\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto lin = r.all<toolpath::Linear>();
    ASSERT_EQ(lin.size(), 4u);
    expectNear(lin[1].to, {20, 20, -1});
    expectNear(lin[2].to, {25, 15, -1});
    expectNear(lin[3].to, {26, 3, -1});
    EXPECT_DOUBLE_EQ(lin[3].feedMmPerMin, 100);
    EXPECT_EQ(r.all<toolpath::Rapid>().size(), 2u);
}

TEST(SinumerikMotion, ArcsInAllPlanesByCentre)
{
    const NcRun r = run("G0 X10 Y0 Z0\nG17 G3 X0 Y10 I-10 J0 F500\nG18 G2 X-10 Z-10 I-10 K0\nG19 G3 Y0 Z0 J-10 K0\n"
                        "G17 G2 X0 Y10 I=AC(0) J=AC(0)\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto arcs = r.all<toolpath::Arc>();
    ASSERT_EQ(arcs.size(), 4u);
    expectNear(arcs[0].center, {0, 0, 0});
    expectNear(arcs[0].normal, {0, 0, 1});
    EXPECT_FALSE(arcs[0].clockwise);
    expectNear(arcs[1].center, {-10, 10, 0});
    expectNear(arcs[1].normal, {0, 1, 0});
    EXPECT_TRUE(arcs[1].clockwise);
    expectNear(arcs[2].center, {-10, 0, -10});
    expectNear(arcs[2].normal, {1, 0, 0});
    EXPECT_FALSE(arcs[2].clockwise);
    expectNear(arcs[3].center, {0, 0, 0});
    expectNear(arcs[3].to, {0, 10, 0});
    EXPECT_EQ(arcs[3].turns, 0);
}

TEST(SinumerikMotion, FullCircleAndHelixWithTurns)
{
    const NcRun r = run("G0 X10 Y0 Z0\nG1 F200\nG2 I-10\nG3 X10 Y0 Z-6 I-10 J0 TURN=2\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto arcs = r.all<toolpath::Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    expectNear(arcs[0].to, {10, 0, 0});
    expectNear(arcs[0].center, {0, 0, 0});
    EXPECT_EQ(arcs[1].turns, 2);
    expectNear(arcs[1].to, {10, 0, -6});
    expectNear(arcs[1].center, {0, 0, 0});
}

TEST(SinumerikMotion, RadiusAndOpeningAngle)
{
    // Quarter circles from (10,0) to (0,10) round the origin, as CR=, CR=- (the long way) and AR=.
    const NcRun r = run("G0 X10 Y0\nG1 F100\nG3 X0 Y10 CR=10\nG0 X10 Y0\nG2 X0 Y10 CR=-10\nG0 X10 Y0\n"
                        "G3 X0 Y10 AR=90\nG0 X10 Y0\nG3 I-10 J0 AR=90\nG0 X10 Y0\nG2 X0 Y10 AR=270\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto arcs = r.all<toolpath::Arc>();
    ASSERT_EQ(arcs.size(), 5u);
    for (const auto& a : arcs) {
        expectNear(a.center, {0, 0, 0}, 1e-9);
        expectNear(a.to, {0, 10, 0}, 1e-9);
    }
    EXPECT_TRUE(arcs[1].clockwise);
    EXPECT_TRUE(arcs[4].clockwise);
}

TEST(SinumerikMotion, RadiusMismatchIsAnError)
{
    InterpretOptions options = fromOrigin();
    options.arcRadiusToleranceMm = 0.01;
    const NcRun r =
        run("G0 X10 Y0\nG1 F100\nG3 X0 Y10.02 I-10 J0\nG3 X-10 Y0 I0 J-10.005\nG2 X0 Y0 CR=2\n", {}, options);
    const Diagnostic* d = r.find("arc radius at the start 10.0000 mm and at the end 10.0200 mm");
    ASSERT_NE(d, nullptr) << r.diagnostics();
    EXPECT_EQ(d->line, 3);
    EXPECT_EQ(d->column, 1);
    EXPECT_NE(r.find("CR=2.0000 is smaller than half the distance"), nullptr);
    EXPECT_EQ(r.all<toolpath::Arc>().size(), 1u);  // within 0.01: traced
    EXPECT_EQ(r.errors(), 2);
}

TEST(SinumerikMotion, MessagesKeepTheDecimalPointInADecimalCommaLocale)
{
    // The GUI runs in the user's locale (Qt sets it); a message must read the same there.
    InterpretOptions options = fromOrigin();
    options.arcRadiusToleranceMm = 0.01;
    const std::string program = "G0 X10 Y0\nG1 F100\nG3 X0 Y10.02 I-10 J0\nG2 X0 Y0 CR=2\nG0 X=99999.9991\n";
    const std::string inC = run(program, {}, options).diagnostics();
    EXPECT_NE(inC.find("10.0200 mm"), std::string::npos) << inC;
    EXPECT_NE(inC.find("value 99999.9991 outside"), std::string::npos) << inC;
    camwb::test::DecimalCommaLocale comma;
    if (!comma.active())
        GTEST_SKIP() << comma.missing();
    EXPECT_EQ(run(program, {}, options).diagnostics(), inC) << comma.name();
}

TEST(SinumerikMotion, InchUnitsScaleToMm)
{
    const NcRun r = run("G700\nG0 X1 Y2\nG1 X2 F10\nG70 G1 X3 F100\nG710 G1 X4\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto lin = r.all<toolpath::Linear>();
    ASSERT_EQ(lin.size(), 3u);
    expectNear(lin[0].to, {50.8, 50.8, 0});
    EXPECT_DOUBLE_EQ(lin[0].feedMmPerMin, 254);  // G700: inch/min
    expectNear(lin[1].to, {76.2, 50.8, 0});
    EXPECT_DOUBLE_EQ(lin[1].feedMmPerMin, 100);  // G70: feed stays metric
    expectNear(lin[2].to, {4, 50.8, 0});
}

TEST(SinumerikMotion, DiamonHalvesXOnALathe)
{
    const NcRun r = run("G18 DIAMON\nG0 X100 Z5\nG1 X80 F0.2\nG91 X-10\nG90 DIAMOF\nG1 X30\n"
                        "DIAMON\nG2 X60 Z-5 I=AC(40) K=AC(0)\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto lin = r.all<toolpath::Linear>();
    ASSERT_EQ(lin.size(), 3u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.x, 50);
    EXPECT_DOUBLE_EQ(lin[0].to.x, 40);
    EXPECT_DOUBLE_EQ(lin[1].to.x, 35);
    EXPECT_DOUBLE_EQ(lin[2].to.x, 30);
}

TEST(SinumerikMotion, StateRecordsInOrder)
{
    const NcRun r = run("; header\nG54\nT3 M6\nG96 S200 LIMS=3000 M3\nG95 F0.1\nM8\nG41 G1 X10 F100\nG4 F1.5\nG40 X0\n"
                        "M5 M9\nG94\nM0\nM1\nG55\nG500\nMSG(\"check\")\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<toolpath::ToolChange>().size(), 1u);
    EXPECT_EQ(r.all<toolpath::ToolChange>()[0].tool.number, 3);
    const auto spindles = r.all<toolpath::Spindle>();
    ASSERT_EQ(spindles.size(), 2u);
    EXPECT_DOUBLE_EQ(spindles[0].surfaceSpeedMPerMin, 200);
    EXPECT_DOUBLE_EQ(spindles[0].rpm, 3000);
    EXPECT_DOUBLE_EQ(spindles[1].rpm, 0);
    const auto modes = r.all<toolpath::FeedModeChange>();
    ASSERT_EQ(modes.size(), 2u);
    EXPECT_EQ(modes[0].mode, toolpath::FeedMode::PerRevolution);
    EXPECT_EQ(modes[1].mode, toolpath::FeedMode::PerMinute);
    EXPECT_EQ(r.all<toolpath::Coolant>().size(), 2u);
    EXPECT_EQ(r.all<toolpath::CutterComp>().size(), 2u);
    ASSERT_EQ(r.all<toolpath::Dwell>().size(), 1u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Dwell>()[0].seconds, 1.5);
    const auto stops = r.all<toolpath::ProgramStop>();
    ASSERT_EQ(stops.size(), 2u);
    EXPECT_FALSE(stops[0].optional);
    EXPECT_TRUE(stops[1].optional);
    const auto offsets = r.all<toolpath::WorkOffset>();
    ASSERT_EQ(offsets.size(), 3u);
    EXPECT_EQ(offsets[0].index, 1);
    EXPECT_EQ(offsets[1].index, 2);
    EXPECT_EQ(offsets[2].index, 0);
    const auto comments = r.all<toolpath::Comment>();
    ASSERT_EQ(comments.size(), 2u);
    EXPECT_EQ(comments[0].text, " header");
    EXPECT_EQ(comments[1].text, "check");
    EXPECT_DOUBLE_EQ(r.all<toolpath::Linear>()[0].feedMmPerMin, 100);
}

TEST(SinumerikMotion, TurretToolChangeWithoutM6)
{
    const NcRun r = run("T=5 D1\nG0 X10\nT2\n");
    ASSERT_EQ(r.all<toolpath::ToolChange>().size(), 2u);
    EXPECT_EQ(r.all<toolpath::ToolChange>()[1].tool.number, 2);
    const NcRun m = run("T5\nG0 X10\nM6\nT=\"DRILL\"\nM6\n");
    ASSERT_EQ(m.all<toolpath::ToolChange>().size(), 2u);
    EXPECT_EQ(m.all<toolpath::ToolChange>()[0].tool.number, 5);
    EXPECT_EQ(m.all<toolpath::ToolChange>()[1].tool.name, "DRILL");
}

TEST(SinumerikMotion, SourceLinesAndFiles)
{
    const NcRun r = run("N10 G0 X1\n\nN30 G1 X2 F10 ; cut\n");
    ASSERT_EQ(r.path.size(), 3u);
    EXPECT_EQ(r.path.source(0).line, 1);
    EXPECT_EQ(r.path.source(1).line, 3);  // the comment
    EXPECT_EQ(r.path.source(2).line, 3);
    EXPECT_EQ(r.path.source(2).file, 0);
}

TEST(SinumerikMotion, CompensationRadiusFromToolDataTheTableOrNone)
{
    // $TC_DP6 + $TC_DP15 of the active cutting edge; D0 compensates nothing; an edge the program
    // gave no data for takes the tool table's radius.
    ToolTable table;
    table.set({2, 2, 8.0, 0.0, {}});
    InterpretOptions options = fromOrigin();
    options.toolTable = &table;
    const NcRun r = run("$TC_DP6[1,1]=3\n$TC_DP15[1,1]=-0.5\nT1 M6\nG0 X-10 Y0\nG41 G1 X0 Y0 F100\nG1 X10 Y0\n"
                        "G40 G1 X20 Y-10\nD0\nG41 G1 X30 Y-10\nG1 X40 Y-10\nG40 G1 X50 Y0\n"
                        "T2 M6\nD1\nG42 G1 X60 Y0\nG1 X70 Y0\nG40 G1 X80 Y10\nM30\n",
                        {}, options);
    EXPECT_EQ(r.diagnostics(), "");
    const auto lines = r.all<toolpath::Linear>();
    ASSERT_EQ(lines.size(), 9u);
    EXPECT_NEAR(lines[0].to.y, 2.5, 1e-12);  // T1 D1: 3 - 0.5
    EXPECT_NEAR(lines[4].to.y, -10, 1e-12);  // D0
    EXPECT_NEAR(lines[7].to.y, -4, 1e-12);   // T2 from the table: right of +X by 4
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
