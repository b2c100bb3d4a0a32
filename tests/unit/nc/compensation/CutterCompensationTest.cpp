// The compensation filter fed by hand: corners of each kind with their exact points, the records
// that wait behind a held move, the source lines, and each diagnostic.
#include "CompensationSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::test {
namespace {

void expectAt(const Vec3& actual, double x, double y, double z = 0)
{
    EXPECT_NEAR(actual.x, x, 1e-9);
    EXPECT_NEAR(actual.y, y, 1e-9);
    EXPECT_NEAR(actual.z, z, 1e-9);
}

TEST(CutterCompensation, OutsideCornerGoesAroundOnAnArcAboutTheCorner)
{
    Compensated c(CompensationRules::linuxCnc());
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, Rapid{{-20, 0, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Linear{{0, -20, 0}, 200});
    c.block(5, CutterComp{CutterCompSide::Off});
    c.block(6, Linear{{10, -30, 0}, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto lines = c.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectAt(lines[0].to, 0, 2);  // LinuxCNC: square to the entry move itself
    const auto arcs = c.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectAt(arcs[0].to, 2, 0);
    expectAt(arcs[0].center, 0, 0);
    EXPECT_TRUE(arcs[0].clockwise);
    EXPECT_EQ(arcs[0].feedMmPerMin, 200);  // the next block's feed
    expectAt(lines[1].to, 2, -20);
    expectAt(lines[2].to, 10, -30);  // G40: from the compensated point to the programmed one
    // The corner arc belongs to the block after the corner.
    const Toolpath& p = c.path();
    for (std::size_t i = 0; i < p.size(); ++i)
        if (std::holds_alternative<Arc>(p.record(i)))
            EXPECT_EQ(p.source(i).line, 4);
}

TEST(CutterCompensation, MovesKeepTheirFeedKindAndACornerArcTakesTheNextMovesKind)
{
    Compensated c(CompensationRules::linuxCnc());
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, Rapid{{-20, 0, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100, {}, FeedKind::Cutting});
    c.block(4, Linear{{0, -20, 0}, 200, {}, FeedKind::Finishing});  // outside corner before it
    c.block(5, Arc{{10, -30, 0}, {10, -20, 0}, {0, 0, 1}, false, 0, 200, FeedKind::Finishing});
    c.block(6, Linear{{10, -30, -2}, 50, {}, FeedKind::Plunge});  // in Z: waits behind the arc
    c.block(7, CutterComp{CutterCompSide::Off});
    c.block(8, Linear{{20, -40, -2}, 100, {}, FeedKind::Exit});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto lines = c.all<Linear>();
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].feedKind, FeedKind::Cutting);
    EXPECT_EQ(lines[1].feedKind, FeedKind::Finishing);
    EXPECT_EQ(lines[2].feedKind, FeedKind::Plunge);
    EXPECT_EQ(lines[3].feedKind, FeedKind::Exit);
    const auto arcs = c.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    EXPECT_EQ(arcs[0].feedMmPerMin, 200);  // round the corner: the next block's feed and kind
    EXPECT_EQ(arcs[0].feedKind, FeedKind::Finishing);
    EXPECT_EQ(arcs[1].feedKind, FeedKind::Finishing);  // the programmed arc, its radius changed
}

TEST(CutterCompensation, InsideCornerTrimsBothMovesToWhereTheirOffsetsMeet)
{
    Compensated c(CompensationRules::linuxCnc());
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, Rapid{{-20, 0, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Linear{{0, 20, 0}, 100});
    c.block(5, Linear{{-10, 30, 0}, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto lines = c.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectAt(lines[0].to, -2, 2);
    // x = -2 meets the offset of the 45 degree line y - 20 = -(x) shifted by 2 to its left.
    const double s = std::sqrt(2.0);
    expectAt(lines[1].to, -2, 22 - 2 * s);
    EXPECT_TRUE(c.all<Arc>().empty());
}

TEST(CutterCompensation, NormEntryEndsSquareToTheContoursFirstElement)
{
    Compensated c(CompensationRules::sinumerik());  // NORM
    c.comp.setRadius(3.0, "T1 D1");
    c.block(1, Rapid{{-20, -20, 0}});
    c.block(2, CutterComp{CutterCompSide::Right});
    c.block(2, Linear{{0, 0, 0}, 100});
    c.block(3, Linear{{0, 30, 0}, 100});
    c.block(4, CutterComp{CutterCompSide::Off});
    c.block(4, Linear{{-20, 40, 0}, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto lines = c.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectAt(lines[0].to, 3, 0);  // right of +Y travel
    expectAt(lines[1].to, 3, 30);
    expectAt(lines[2].to, -20, 40);
    EXPECT_TRUE(c.all<Arc>().empty());
}

TEST(CutterCompensation, ArcsKeepTheirCentreAndChangeTheirRadius)
{
    Compensated c;
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, Rapid{{0, -10, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Linear{{10, 0, 0}, 100});
    c.block(5, Arc{{20, 10, 0}, {10, 10, 0}, {0, 0, 1}, false, 0, 100});  // tangent, tool inside
    c.block(6, Arc{{30, 20, -1}, {30, 10, 0}, {0, 0, 1}, true, 0, 100});  // tangent, tool outside; a helix
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto arcs = c.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    expectAt(arcs[0].to, 18, 10);
    expectAt(arcs[0].center, 10, 10);
    expectAt(arcs[1].to, 30, 22, -1);
    expectAt(arcs[1].center, 30, 10);
}

TEST(CutterCompensation, G451TakesTheIntersectionAtOutsideCornersUpToItsLimit)
{
    Compensated c;
    c.comp.setRadius(2.0, "T1 D1");
    c.comp.setOutsideIntersection(true, 100);
    c.block(1, Rapid{{0, -10, 0}});
    c.block(2, CutterComp{CutterCompSide::Right});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Linear{{20, 0, 0}, 100});
    c.block(5, Linear{{20, 20, 0}, 100});  // turns 90 degrees: the intersection
    c.block(6, Linear{{10, 10, 0}, 100});  // turns 135 degrees: past the limit, an arc
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    const auto lines = c.all<Linear>();
    ASSERT_EQ(lines.size(), 4u);
    expectAt(lines[1].to, 22, -2);
    expectAt(lines[2].to, 22, 20);
    ASSERT_EQ(c.all<Arc>().size(), 1u);
    expectAt(c.all<Arc>()[0].center, 20, 20);
}

TEST(CutterCompensation, MovesInZAndOtherRecordsWaitBehindTheHeldMoveInTheirOrder)
{
    Compensated c(CompensationRules::linuxCnc());
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, Rapid{{-20, 0, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Comment{"plunge"});
    c.block(5, Linear{{0, 0, -3}, 50});
    c.block(6, Linear{{0, 20, -3}, 100});  // inside corner: the plunge moves to the trimmed corner too
    c.finish();
    const Toolpath& p = c.path();
    std::vector<int> lines;
    for (std::size_t i = 0; i < p.size(); ++i)
        lines.push_back(p.source(i).line);
    EXPECT_EQ(lines, (std::vector<int>{1, 2, 3, 4, 5, 6}));
    const auto moves = c.all<Linear>();
    ASSERT_EQ(moves.size(), 3u);
    expectAt(moves[0].to, -2, 2);
    expectAt(moves[1].to, -2, 2, -3);
    expectAt(moves[2].to, -2, 20, -3);
}

TEST(CutterCompensation, ARadiusTooLargeForAnInsideArcIsAGougeError)
{
    Compensated c;
    c.comp.setRadius(4.0, "tool 1");
    c.block(1, Rapid{{0, -10, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Arc{{0, 6, 0}, {0, 3, 0}, {0, 0, 1}, false, 0, 100});  // ccw R3, the tool inside
    c.finish();
    EXPECT_EQ(c.diagnostics(), "4: error: the tool radius 4 mm is not smaller than the radius 3 mm of the inside arc: "
                               "the tool cannot follow it (gouge); the arc is traced as programmed and compensation "
                               "starts again\n");
}

TEST(CutterCompensation, AnInsideCornerTooNarrowForTheToolIsAGougeError)
{
    Compensated c;
    c.comp.setRadius(3.0, "tool 1");
    c.block(1, Rapid{{0, -10, 0}});
    c.block(2, CutterComp{CutterCompSide::Left});
    c.block(3, Linear{{0, 0, 0}, 100});
    c.block(4, Linear{{10, 0, 0}, 100});
    c.block(5, Linear{{10, 2, 0}, 100});  // 2 mm up, then back left: a slot 2 mm wide for a 6 mm tool
    c.block(6, Linear{{0, 2, 0}, 100});
    c.finish();
    EXPECT_NE(
        c.diagnostics().find("error: the tool (radius 3 mm) does not fit into the inside corner at (10.000, 2.000)"),
        std::string::npos)
        << c.diagnostics();
}

TEST(CutterCompensation, StartingOrEndingOnAnArcIsAnErrorWhereTheControlRefusesIt)
{
    Compensated c;
    c.comp.setRadius(2.0, "tool 1");
    c.block(1, CutterComp{CutterCompSide::Left});
    c.block(2, Arc{{10, 10, 0}, {10, 0, 0}, {0, 0, 1}, true, 0, 100});
    c.block(3, Linear{{20, 10, 0}, 100});
    c.block(4, CutterComp{CutterCompSide::Off});
    c.block(4, Arc{{30, 0, 0}, {30, 10, 0}, {0, 0, 1}, true, 0, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(),
              "2: error: cutter compensation must start on a straight move (G41/G42 with a line): the arc is traced "
              "as programmed\n"
              "4: error: cutter compensation must end on a straight move (G40 with a line): the arc starts from the "
              "compensated position\n");
    expectAt(c.all<Arc>()[0].to, 10, 10);  // as programmed
}

TEST(CutterCompensation, AnUnknownRadiusTracesTheProgrammedContourWithAWarning)
{
    Compensated c;
    c.comp.setRadius(std::nullopt, "tool 7");
    c.block(1, CutterComp{CutterCompSide::Left});
    c.block(2, Linear{{10, 0, 0}, 100});
    c.block(3, Linear{{10, 10, 0}, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "2: warning: cutter compensation (G41/G42): the radius of tool 7 is not known (no tool "
                               "table entry, no tool data in the program): the programmed contour is traced, not the "
                               "tool centre\n");
    const auto lines = c.all<Linear>();
    expectAt(lines[0].to, 10, 0);
    expectAt(lines[1].to, 10, 10);
}

TEST(CutterCompensation, RadiusZeroAndNoCompensationPassEveryRecordUnchanged)
{
    Compensated c;
    c.comp.setRadius(0.0, "T1 D0");
    c.block(1, Linear{{10, 0, 0}, 100});
    c.block(2, CutterComp{CutterCompSide::Right});
    c.block(3, Linear{{10, 10, 0}, 100});
    c.block(4, Arc{{0, 20, 0}, {0, 10, 0}, {0, 0, 1}, false, 0, 100});
    c.finish();
    EXPECT_EQ(c.diagnostics(), "");
    expectAt(c.all<Linear>()[1].to, 10, 10);
    expectAt(c.all<Arc>()[0].to, 0, 20);
}

}  // namespace
}  // namespace camwb::nc::test
