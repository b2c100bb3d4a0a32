// Which feed each helix move says it uses, hole by hole: down to the top at the plunge feed
// (Plunge), the helix at the ramp feed (Entry), the circle at the bottom (Cutting), the spring
// circle (Finishing), off the wall to the centre (Exit). Drilling writes cycles, no feed moves.
#include "../support/FeedKinds.h"
#include "HoleTestSupport.h"
#include "ops/DrillOp.h"
#include "ops/HelixOp.h"

#include <gtest/gtest.h>

using namespace camwb;
using namespace camwb::ops::test;
using toolpath::FeedKind;

namespace {

std::vector<FeedKind> expectedHole(int helixArcs, bool finishing, bool leavesToCentre)
{
    std::vector<FeedKind> kinds{FeedKind::Plunge};
    kinds.insert(kinds.end(), helixArcs, FeedKind::Entry);
    kinds.insert(kinds.end(), 2, FeedKind::Cutting);
    if (finishing)
        kinds.insert(kinds.end(), 2, FeedKind::Finishing);
    if (leavesToCentre)
        kinds.push_back(FeedKind::Exit);
    return kinds;
}

ops::HelixParams helixParams(bool finishingCircle)
{
    ops::HelixParams p;
    p.heights = {25, 3, 0, 0};
    p.pitchMm = 2;
    p.finishingCircle = finishingCircle;
    return p;
}

}  // namespace

TEST(HoleFeedKinds, HelixPlungesEntersCutsFinishesAndLeaves)
{
    // Blind, 4 mm deep at 2 mm pitch: four half turns down.
    const std::vector<geom::Hole> holes{{1, {0, 0}, 12, 0, -4, false}, {2, {30, 0}, 12, 0, -4, false}};
    auto result = ops::computeHelix(holes, helixParams(true), toolController(8), 1);
    ASSERT_TRUE(result) << result.error().message;
    expectFeedKindsAgreeWithSections(result->toolpath);
    std::vector<FeedKind> expected = expectedHole(4, true, true);
    const std::vector<FeedKind> second = expectedHole(4, true, true);
    expected.insert(expected.end(), second.begin(), second.end());
    EXPECT_EQ(feedKinds(result->toolpath), expected);
    const auto& begin = std::get<toolpath::SectionBegin>(result->toolpath.record(0));
    EXPECT_EQ(begin.feeds.finishingMmPerMin, 600);
    EXPECT_EQ(begin.feeds.exitMmPerMin, 600);
    EXPECT_EQ(begin.feeds.entryMmPerMin, 300);
}

TEST(HoleFeedKinds, NoSpringPassNoFinishingAndACoreLeavesStraightUp)
{
    // A 6 mm tool in a 20 mm hole leaves a core: no move to the centre, so nothing exits.
    const std::vector<geom::Hole> holes{{1, {0, 0}, 20, 0, -2, false}};
    auto result = ops::computeHelix(holes, helixParams(false), toolController(6), 1);
    ASSERT_TRUE(result) << result.error().message;
    expectFeedKindsAgreeWithSections(result->toolpath);
    EXPECT_EQ(feedKinds(result->toolpath), expectedHole(2, false, false));
    EXPECT_EQ(std::get<toolpath::SectionBegin>(result->toolpath.record(0)).feeds.finishingMmPerMin, 0);
}

TEST(HoleFeedKinds, TooShallowForAHelixPlungesTwice)
{
    const std::vector<geom::Hole> holes{{1, {0, 0}, 12, 0, -0.0001, false}};
    auto result = ops::computeHelix(holes, helixParams(false), toolController(8), 1);
    ASSERT_TRUE(result) << result.error().message;
    expectFeedKindsAgreeWithSections(result->toolpath);
    EXPECT_EQ(feedKinds(result->toolpath), (std::vector<FeedKind>{FeedKind::Plunge, FeedKind::Plunge, FeedKind::Cutting,
                                                                  FeedKind::Cutting, FeedKind::Exit}));
}

TEST(HoleFeedKinds, DrillingWritesCyclesAndNoFeedMoves)
{
    ops::DrillParams p;
    p.heights = {25, 3, 0, 0};
    auto result = ops::computeDrill({{1, {0, 0}, 5, 0, -10, false}}, p, toolController(5), 1);
    ASSERT_TRUE(result) << result.error().message;
    EXPECT_TRUE(feedKinds(result->toolpath).empty());
}
