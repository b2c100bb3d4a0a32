// Contour elements of the Klartext interpreter: L (absolute, incremental, FMAX, modal F), C about
// CC, CR with both radius signs and directions, CT, CP circles and helices, LP polar lines,
// RND and CHF corners, inch programs and the datum shift of CYCL DEF 7.
#include "TestSupport.h"
#include "nc/ToolTable.h"

#include <cmath>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

TEST(HeidenhainContour, LinesFeedsAndIncrementalWords)
{
    const Traced r = run(program("2 L X+10 Y+5 Z+20 R0 FMAX M3\n"
                                 "3 L Z-1 F200\n"
                                 "4 L IX+5 IY-2.5\n"
                                 "5 L X+0 FMAX\n"
                                 "6 L Y+0\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.trace();
    const auto rapids = r.all<Rapid>();
    const auto lines = r.all<Linear>();
    ASSERT_EQ(rapids.size(), 2u);
    ASSERT_EQ(lines.size(), 3u);
    expectNear(rapids[0].to, {10, 5, 20});
    expectNear(lines[0].to, {10, 5, -1});
    EXPECT_EQ(lines[0].feedMmPerMin, 200);
    expectNear(lines[1].to, {15, 2.5, -1});
    expectNear(rapids[1].to, {0, 2.5, -1});
    // FMAX holds for its block only: the modal feed comes back.
    expectNear(lines[2].to, {0, 0, -1});
    EXPECT_EQ(lines[2].feedMmPerMin, 200);
    EXPECT_EQ(r.lines<Linear>(), (std::vector<int>{4, 5, 7}));
    EXPECT_TRUE(r.result.completed);
}

TEST(HeidenhainContour, CircleAboutCcBothDirections)
{
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Y+0\n"
                                 "4 C X+0 Y+10 DR+ F100\n"
                                 "5 C X+10 Y+0 DR-\n"
                                 "6 C X+10 Y+0 DR+\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.trace();
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 3u);
    expectNear(arcs[0].to, {0, 10, 0});
    expectNear(arcs[0].center, {0, 0, 0});
    EXPECT_FALSE(arcs[0].clockwise);
    EXPECT_TRUE(arcs[1].clockwise);
    expectNear(arcs[1].to, {10, 0, 0});
    // End = start: a full circle.
    expectNear(arcs[2].to, {10, 0, 0});
    EXPECT_EQ(arcs[2].turns, 0);
    EXPECT_EQ(arcs[2].normal.z, 1);
}

TEST(HeidenhainContour, IncrementalCircleCentreFromTheLastPosition)
{
    const Traced r = run(program("2 L X+10 Y+10 FMAX\n"
                                 "3 CC IX+5 IY+0\n"
                                 "4 C X+20 Y+10 DR- F100\n"));
    EXPECT_TRUE(r.result.diagnostics.empty());
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].center, {15, 10, 0});
}

TEST(HeidenhainContour, RadiusArcsPickTheirCentreBySignAndDirection)
{
    const double h = std::sqrt(75.0);
    struct Case {
        const char* words;
        double centreY;
        bool clockwise;
    } cases[] = {
        {"R+10 DR+", h, false},
        {"R-10 DR+", -h, false},
        {"R+10 DR-", -h, true},
        {"R-10 DR-", h, true},
    };
    for (const Case& c : cases) {
        const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n3 CR X+10 Y+0 " + std::string(c.words) + " F100\n"));
        EXPECT_TRUE(r.result.diagnostics.empty()) << c.words;
        const auto arcs = r.all<Arc>();
        ASSERT_EQ(arcs.size(), 1u);
        expectNear(arcs[0].center, {5, c.centreY, 0});
        EXPECT_EQ(arcs[0].clockwise, c.clockwise) << c.words;
    }
}

TEST(HeidenhainContour, RadiusTooSmallForTheChordIsAnError)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n3 CR X+30 Y+0 R+10 DR+ F100\n"));
    EXPECT_TRUE(r.has(Severity::Error, 4, "smaller than half the chord")) << r.diagnostics()[0];
    EXPECT_TRUE(r.all<Arc>().empty());
}

TEST(HeidenhainContour, TangentialArcsFollowTheElementBefore)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L X+10 Y+0 F100\n"
                                 "4 CT X+20 Y+10\n"
                                 "5 CT X+30 Y+20\n"
                                 "6 CT X+40 Y+20\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    // Tangent +X at (10,0): a quarter circle about (10,10) ending heading +Y ...
    expectNear(arcs[0].center, {10, 10, 0});
    EXPECT_FALSE(arcs[0].clockwise);
    // ... then (30,20) lies right of that tangent: clockwise about (30,10), ending heading +X ...
    expectNear(arcs[1].center, {30, 10, 0});
    EXPECT_TRUE(arcs[1].clockwise);
    // ... so (40,20) lies on the tangent: a straight line.
    ASSERT_EQ(r.all<Linear>().size(), 2u);
    expectNear(r.all<Linear>()[1].to, {40, 20, 0});
}

TEST(HeidenhainContour, TangentialArcWithoutAnElementBeforeIsAnError)
{
    const Traced r = run(program("2 CT X+10 Y+10 F100\n"));
    EXPECT_TRUE(r.has(Severity::Error, 3, "CT needs a preceding contour element"));
}

TEST(HeidenhainContour, PolarCircleAndHelix)
{
    const Traced r = run(program("2 CC X+0 Y+0\n"
                                 "3 L X+5 Y+0 Z+0 FMAX\n"
                                 "4 CP IPA+1080 IZ-6 DR+ F100\n"
                                 "5 CP IPA-450 IZ-3 DR-\n"
                                 "6 CP PA+90 DR+\n"
                                 "7 CP PA+0 DR-\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 4u);
    expectNear(arcs[0].to, {5, 0, -6});
    EXPECT_EQ(arcs[0].turns, 2);
    EXPECT_FALSE(arcs[0].clockwise);
    expectNear(arcs[1].to, {0, -5, -9}, 1e-12);
    EXPECT_EQ(arcs[1].turns, 1);
    EXPECT_TRUE(arcs[1].clockwise);
    // From -90 degrees counter-clockwise to +90: half a circle.
    expectNear(arcs[2].to, {0, 5, -9}, 1e-12);
    EXPECT_EQ(arcs[2].turns, 0);
    // From +90 clockwise to 0.
    expectNear(arcs[3].to, {5, 0, -9}, 1e-12);
    EXPECT_TRUE(arcs[3].clockwise);
    for (const Arc& a : arcs)
        expectNear(a.center, {0, 0, a.center.z});
}

TEST(HeidenhainContour, PolarLines)
{
    const Traced r = run(program("2 CC X+10 Y+10\n"
                                 "3 LP PR+5 PA+90 FMAX\n"
                                 "4 LP IPA+90 F100\n"
                                 "5 LP IPR+5\n"
                                 "6 LP PA-90 Z-2\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectNear(r.all<Rapid>()[0].to, {10, 15, 0}, 1e-12);
    expectNear(lines[0].to, {5, 10, 0}, 1e-12);
    expectNear(lines[1].to, {0, 10, 0}, 1e-12);
    expectNear(lines[2].to, {10, 0, -2}, 1e-12);
}

TEST(HeidenhainContour, RoundingBetweenTwoLines)
{
    const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n"
                                 "3 L X+10 Y+0 F300\n"
                                 "4 RND R2 F100\n"
                                 "5 L X+10 Y+10\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto lines = r.all<Linear>();
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(lines.size(), 2u);
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(lines[0].to, {8, 0, 0}, 1e-12);
    expectNear(arcs[0].to, {10, 2, 0}, 1e-12);
    expectNear(arcs[0].center, {8, 2, 0}, 1e-12);
    EXPECT_FALSE(arcs[0].clockwise);
    EXPECT_EQ(arcs[0].feedMmPerMin, 100);  // F in the RND block holds for it alone
    expectNear(lines[1].to, {10, 10, 0});
    EXPECT_EQ(lines[1].feedMmPerMin, 300);
    EXPECT_EQ(r.lines<Arc>(), std::vector<int>{5});
}

TEST(HeidenhainContour, RoundingAnObtuseRightTurn)
{
    // 45 degree deflection to the right: tangent length R * tan(22.5).
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L X+20 Y+0 F300\n"
                                 "4 RND R5\n"
                                 "5 L X+30 Y-10\n"));
    EXPECT_TRUE(r.result.diagnostics.empty());
    const double t = 5 * std::tan(M_PI / 8);
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(r.all<Linear>()[0].to, {20 - t, 0, 0}, 1e-12);
    expectNear(arcs[0].to, {20 + t / std::sqrt(2.0), -t / std::sqrt(2.0), 0}, 1e-12);
    expectNear(arcs[0].center, {20 - t, -5, 0}, 1e-12);
    EXPECT_TRUE(arcs[0].clockwise);
}

TEST(HeidenhainContour, ChamferBetweenTwoLines)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L X+10 Y+0 F300\n"
                                 "4 ; the chamfer\n"
                                 "5 CHF 3\n"
                                 "6 L X+10 Y+10\n"));
    EXPECT_TRUE(r.result.diagnostics.empty());
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectNear(lines[0].to, {7, 0, 0});
    expectNear(lines[1].to, {10, 3, 0});
    expectNear(lines[2].to, {10, 10, 0});
    EXPECT_EQ(r.lines<Linear>(), (std::vector<int>{4, 6, 7}));
}

TEST(HeidenhainContour, RoundingTooLargeIsAnErrorAndTheCornerStaysSharp)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L X+2 Y+0 F300\n"
                                 "4 RND R5\n"
                                 "5 L X+2 Y+10\n"));
    EXPECT_TRUE(r.has(Severity::Error, 5, "does not fit"));
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 2u);
    expectNear(lines[0].to, {2, 0, 0});
    EXPECT_TRUE(r.all<Arc>().empty());
}

TEST(HeidenhainContour, RoundingBetweenALineAndACircle)
{
    // Line heading +X into a clockwise arc about (20,0) that leaves heading +Y: a left turn. The
    // rounding centre lies 2 above the line and 12 from the arc's centre.
    const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n"
                                 "3 L X+10 Y+0 F300\n"
                                 "4 RND R2\n"
                                 "5 CC X+20 Y+0\n"
                                 "6 C X+20 Y+10 DR-\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const double cx = 20 - std::sqrt(140.0);
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    expectNear(r.all<Linear>()[0].to, {cx, 0, 0}, 1e-9);
    expectNear(arcs[0].center, {cx, 2, 0}, 1e-9);
    EXPECT_FALSE(arcs[0].clockwise);
    expectNear(arcs[0].to, {20 + (cx - 20) * 10 / 12, 2.0 * 10 / 12, 0}, 1e-9);
    // The circle goes on about its own centre to its programmed end.
    expectNear(arcs[1].center, {20, 0, 0});
    expectNear(arcs[1].to, {20, 10, 0});
    EXPECT_TRUE(arcs[1].clockwise);
    EXPECT_NEAR(distance(arcs[0].to.xy(), arcs[1].center.xy()), 10, 1e-9);
}

TEST(HeidenhainContour, RoundingBetweenACircleAndALine)
{
    // Counter-clockwise quarter about (0,0) from (10,0) to (0,10), ending heading -X, then a line
    // heading -Y: a left turn rounded with R1. The centre lies 1 left of the line (x = 1) and
    // 10 - 1 from the circle's centre.
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Y+0\n"
                                 "4 C X+0 Y+10 DR+ F300\n"
                                 "5 RND R1\n"
                                 "6 L X+0 Y+0\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    const double cy = std::sqrt(81.0 - 1.0);
    expectNear(arcs[1].center, {1, cy, 0}, 1e-9);
    expectNear(arcs[1].to, {0, cy, 0}, 1e-9);
    expectNear(arcs[0].to, {1.0 * 10 / 9, cy * 10 / 9, 0}, 1e-9);
    expectNear(arcs[0].center, {0, 0, 0});
    expectNear(r.all<Linear>().back().to, {0, 0, 0});
}

TEST(HeidenhainContour, IncrementalWordsAfterACornerCountFromTheCorner)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L IX+10 F300\n"
                                 "4 CHF 2\n"
                                 "5 L IY+10\n"));
    EXPECT_TRUE(r.result.diagnostics.empty());
    expectNear(r.all<Linear>().back().to, {10, 10, 0});
}

TEST(HeidenhainContour, ChamferNextToACircleWarns)
{
    const Traced r = run(program("2 L X+0 Y+0 FMAX\n"
                                 "3 L X+10 Y+0 F300\n"
                                 "4 CHF 2\n"
                                 "5 CC X+20 Y+0\n"
                                 "6 C X+20 Y+10 DR-\n"));
    EXPECT_TRUE(r.has(Severity::Warning, 5, "CHF is a chamfer between two straight lines"));
    EXPECT_EQ(r.count(Severity::Warning), 1u) << r.diagnostics()[0];
    EXPECT_EQ(r.all<Arc>().size(), 1u);
}

TEST(HeidenhainContour, InchProgramsScaleCoordinatesAndFeeds)
{
    const Traced r = run("0 BEGIN PGM T INCH\n1 L X+1 Y+2 F10\n2 END PGM T INCH\n");
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 1u);
    expectNear(lines[0].to, {25.4, 50.8, 0}, 1e-12);
    EXPECT_NEAR(lines[0].feedMmPerMin, 25.4, 1e-12);  // F in 1/10 inch/min
}

TEST(HeidenhainContour, DatumShiftMovesLaterPositions)
{
    const Traced r = run(program("2 CYCL DEF 7.0 DATUM SHIFT\n"
                                 "3 CYCL DEF 7.1 X+100\n"
                                 "4 CYCL DEF 7.2 Y+50\n"
                                 "5 L X+10 Y+10 FMAX\n"
                                 "6 CYCL DEF 7.0 DATUM SHIFT\n"
                                 "7 CYCL DEF 7.1 IX+5\n"
                                 "8 CC X+0 Y+0\n"
                                 "9 L X+10 Y+10 FMAX\n"
                                 "10 C X+10 Y+10 DR+ F100\n"
                                 "11 CYCL DEF 7.0 DATUM SHIFT\n"
                                 "12 CYCL DEF 7.1 X+0\n"
                                 "13 CYCL DEF 7.2 Y+0\n"
                                 "14 L X+10 Y+10 FMAX\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    expectNear(rapids[0].to, {110, 60, 0});
    expectNear(rapids[1].to, {115, 60, 0});
    expectNear(r.all<Arc>()[0].center, {105, 50, 0});
    expectNear(rapids[2].to, {10, 10, 0});
}

TEST(HeidenhainContour, CompensationAndSpindleRecordsInTheControlsOrder)
{
    const Traced r = run(program("2 L X+0 Y+0 RL F100 M13\n"
                                 "3 L X+10 R0 M5 M9\n"));
    const auto& recs = r.path.records();
    std::vector<std::size_t> kinds;
    for (const Record& rec : recs)
        kinds.push_back(rec.index());
    // ToolChange, Spindle (M13), Coolant, CutterComp(Left), Linear, CutterComp(Off), Linear, Spindle 0, Coolant off.
    const std::vector<std::size_t> expected{
        Record(ToolChange{}).index(), Record(Spindle{}).index(), Record(Coolant{}).index(),
        Record(CutterComp{}).index(), Record(Linear{}).index(),  Record(CutterComp{}).index(),
        Record(Linear{}).index(),     Record(Spindle{}).index(), Record(Coolant{}).index()};
    EXPECT_EQ(kinds, expected);
    EXPECT_EQ(r.all<CutterComp>()[0].side, CutterCompSide::Left);
    EXPECT_EQ(r.all<Spindle>()[0].rpm, 3000);
    EXPECT_EQ(r.all<Spindle>()[1].rpm, 0);
}

TEST(HeidenhainContour, ContinuationLinesAndCrlf)
{
    const Traced r = run("0 BEGIN PGM T MM\r\n1 L X+10 ~\r\n  Y+20 FMAX\r\n2 END PGM T MM\r\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    expectNear(r.all<Rapid>()[0].to, {10, 20, 0});
    EXPECT_EQ(r.lines<Rapid>(), std::vector<int>{2});
}

TEST(HeidenhainContour, CompensationRadiusIsToolDefRPlusToolCallDr)
{
    ToolTable table;
    table.set({2, 2, 8.0, 0.0, {}});
    InterpretOptions options = fromOrigin();
    options.toolTable = &table;
    const Traced r = run("0 BEGIN PGM T MM\n1 TOOL DEF 1 L+40 R+3\n2 TOOL CALL 1 Z S1000 DR+0.5\n"
                         "3 L X-10 Y+0 R0 F100\n4 L X+0 RL\n5 L X+10\n6 L X+20 Y-10 R0\n"
                         "7 TOOL CALL 2 Z S1000\n8 L X+30 Y-10 RR\n9 L X+40\n10 L X+50 Y+0 R0\n"
                         "11 TOOL CALL 5 Z\n12 L X+60 RL\n13 L X+70\n14 L X+80 Y+10 R0\n15 END PGM T MM\n",
                         options);
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 10u);
    EXPECT_NEAR(lines[1].to.y, 3.5, 1e-12);  // TOOL DEF R3 + DR 0.5 (tool left of +X)
    EXPECT_NEAR(lines[4].to.y, -14, 1e-12);  // the table's 8 mm tool, right of +X
    EXPECT_NEAR(lines[7].to.y, 0, 1e-12);    // tool 5: no radius anywhere, the programmed path
    ASSERT_EQ(r.result.diagnostics.size(), 1u) << r.diagnostics()[0];
    EXPECT_EQ(r.result.diagnostics[0].line, 13);
    EXPECT_NE(r.result.diagnostics[0].message.find("the radius of tool 5 is not known"), std::string::npos);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
