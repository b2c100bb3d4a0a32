// RegionOps: offsets in exact lines and arcs (fillets that collapse into sharp corners, loops
// that merge where they cross), nesting of loops, booleans, exact polyline clipping, segment-inside
// tests and swept areas; empty and out-of-range inputs give empty results.
#include "RegionTestUtil.h"
#include "geom/RegionOps.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace camwb::geom;
namespace t = camwb::geom::test;
constexpr double kPi = std::numbers::pi;

TEST(OffsetRegions, ShrinkOfRoundedRectangleWithIslandGivesArcsBack)
{
    const Region input = t::roundedRectWithCircle(60, 40, 10, {30, 20}, 5);
    const double tol = 0.01, d = 3;
    const std::vector<Region> result = offsetRegions({input}, -d, tol);
    ASSERT_EQ(result.size(), 1u);
    const Region& region = result[0];
    EXPECT_EQ(t::countLines(region.outer), 4u);
    EXPECT_EQ(t::countArcs(region.outer), 4u);
    const double margin = offsetSafetyMargin(tol);
    for (const Segment& s : region.outer.segments)
        if (s.isArc()) {
            EXPECT_NEAR(s.radius(), 10 - d - margin, 1e-9);  // exact: no discretisation left
        }
    ASSERT_EQ(region.holes.size(), 1u);
    EXPECT_EQ(t::countArcs(region.holes[0]), region.holes[0].segments.size());
    EXPECT_LE(region.holes[0].segments.size(), 3u);
    for (const Segment& s : region.holes[0].segments) {
        EXPECT_NEAR(s.radius(), 5 + d + margin, 1e-9);
        EXPECT_NEAR(distance(s.center, {30, 20}), 0, 1e-12);
    }
    EXPECT_LT(region.holes[0].signedArea(), 0);
    EXPECT_GT(region.outer.signedArea(), 0);
}

TEST(OffsetRegions, FilletsSmallerThanTheDistanceBecomeExactCorners)
{
    const double tol = 0.01, d = 3;
    const std::vector<Region> result = offsetRegions({Region{t::roundedRectangle(0, 0, 40, 30, 1), {}}}, -d, tol);
    ASSERT_EQ(result.size(), 1u);
    const double at = d + offsetSafetyMargin(tol);
    EXPECT_EQ(result[0].outer.segments.size(), 4u);
    EXPECT_EQ(t::countArcs(result[0].outer), 0u);
    for (const Segment& s : result[0].outer.segments) {
        const bool onX = std::abs(s.start.x - at) < 1e-9 || std::abs(s.start.x - (40 - at)) < 1e-9;
        const bool onY = std::abs(s.start.y - at) < 1e-9 || std::abs(s.start.y - (30 - at)) < 1e-9;
        EXPECT_TRUE(onX && onY) << s.start.x << ", " << s.start.y;
    }
}

TEST(OffsetRegions, IslandsThatGrowTogetherMeetExactlyOnBothCircles)
{
    const Vec2 a{40, 50}, b{52, 50};
    const Region input{t::rectangle(0, 0, 100, 100), {t::circle(a, 3).reversed(), t::circle(b, 3).reversed()}};
    const double tol = 0.01;
    const std::vector<Region> result = offsetRegions({input}, -4, tol);
    ASSERT_EQ(result.size(), 1u);
    ASSERT_EQ(result[0].holes.size(), 1u);  // the two grown islands make one hole
    const double r = 3 + 4 + offsetSafetyMargin(tol);
    int crossings = 0;
    for (const Segment& s : result[0].holes[0].segments) {
        ASSERT_TRUE(s.isArc());
        EXPECT_TRUE(distance(s.center, a) < 1e-12 || distance(s.center, b) < 1e-12);
        EXPECT_NEAR(s.radius(), r, 1e-9);
        if (std::abs(distance(s.start, a) - r) < 1e-9 && std::abs(distance(s.start, b) - r) < 1e-9)
            ++crossings;
    }
    EXPECT_EQ(crossings, 2);
}

TEST(OffsetRegions, ShrinkSplitsAndVanishes)
{
    // Two squares joined by a 4 mm neck: a 2.5 mm shrink cuts the neck.
    const Region dumbbell{t::polygon({{0, 0},
                                      {20, 0},
                                      {20, 8},
                                      {30, 8},
                                      {30, 0},
                                      {50, 0},
                                      {50, 20},
                                      {30, 20},
                                      {30, 12},
                                      {20, 12},
                                      {20, 20},
                                      {0, 20}}),
                          {}};
    EXPECT_EQ(offsetRegions({dumbbell}, -1.5, 0.01).size(), 1u);
    EXPECT_EQ(offsetRegions({dumbbell}, -2.5, 0.01).size(), 2u);
    EXPECT_TRUE(offsetRegions({dumbbell}, -10.5, 0.01).empty());
    // An island close to the wall: the gap closes and the hole opens into the outer loop.
    const Region nearWall = t::roundedRectWithCircle(40, 40, 2, {20, 6}, 4);
    const std::vector<Region> merged = offsetRegions({nearWall}, -1.5, 0.01);
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_TRUE(merged[0].holes.empty());
}

TEST(OffsetRegions, GrowRoundsConvexCorners)
{
    const std::vector<Region> result = offsetRegions({Region{t::rectangle(0, 0, 20, 10), {}}}, 2, 0.001);
    ASSERT_EQ(result.size(), 1u);
    EXPECT_EQ(t::countArcs(result[0].outer), 4u);
    EXPECT_EQ(t::countLines(result[0].outer), 4u);
    EXPECT_NEAR(result[0].area(), 200 + 2 * 2 * 30 + kPi * 4, 0.001 * 70);
}

TEST(OffsetRegions, EmptyZeroAndOutOfRange)
{
    EXPECT_TRUE(offsetRegions({}, -1, 0.01).empty());
    const Region square{t::rectangle(0, 0, 10, 10).reversed(), {}};
    const std::vector<Region> same = offsetRegions({square}, 0, 0.01);
    ASSERT_EQ(same.size(), 1u);
    EXPECT_NEAR(same[0].outer.signedArea(), 100, 1e-12);
    EXPECT_TRUE(offsetRegions({Region{t::rectangle(0, 0, 1e12, 10), {}}}, -1, 0.01).empty());
    EXPECT_TRUE(offsetRegions({square}, std::nan(""), 0.01).empty());
}

TEST(RegionsFromLoops, EvenOddNesting)
{
    const std::vector<Profile> loops{
        t::circle({50, 50}, 10),            // hole of the big square
        t::rectangle(0, 0, 100, 100),       // outer
        t::rectangle(47, 47, 6, 6),         // island inside the hole
        t::rectangle(200, 0, 10, 10),       // separate outer
        t::circle({20, 20}, 3).reversed(),  // second hole of the big square (other orientation)
    };
    const std::vector<Region> regions = regionsFromLoops(loops, 0.01);
    ASSERT_EQ(regions.size(), 3u);
    EXPECT_NEAR(totalArea(regions), 10000 - 100 * kPi + 36 + 100 - 9 * kPi, 1e-9);
    for (const Region& region : regions) {
        EXPECT_GT(region.outer.signedArea(), 0);
        for (const Profile& hole : region.holes)
            EXPECT_LT(hole.signedArea(), 0);
    }
    EXPECT_EQ(regions[0].holes.size(), 2u);  // largest first
    EXPECT_FALSE(anyContains(regions, {50, 45}));
    EXPECT_TRUE(anyContains(regions, {50, 50}));
    EXPECT_TRUE(regionsFromLoops({}, 0.01).empty());
}

TEST(RegionBooleans, AreasOfUnionDifferenceIntersection)
{
    const std::vector<Region> a{Region{t::rectangle(0, 0, 20, 20), {}}};
    const std::vector<Region> b{Region{t::circle({20, 10}, 5), {}}};
    const double tol = 0.001;
    const double half = 12.5 * kPi;
    EXPECT_NEAR(totalArea(unite(a, b, tol)), 400 + half, 0.1);
    EXPECT_NEAR(totalArea(subtract(a, b, tol)), 400 - half, 0.1);
    EXPECT_NEAR(totalArea(intersect(a, b, tol)), half, 0.1);
    const std::vector<Region> hollow = subtract(a, {Region{t::circle({10, 10}, 4), {}}}, tol);
    ASSERT_EQ(hollow.size(), 1u);
    ASSERT_EQ(hollow[0].holes.size(), 1u);
    for (const Segment& s : hollow[0].holes[0].segments)
        EXPECT_NEAR(s.radius(), 4, tol);
    EXPECT_TRUE(unite({}, {}, tol).empty());
    EXPECT_EQ(unite(a, {}, tol).size(), 1u);
    EXPECT_TRUE(intersect(a, {}, tol).empty());
}

TEST(ClipPolylines, KeepsDirectionOrderAndExactEnds)
{
    const std::vector<Region> regions{t::roundedRectWithCircle(40, 30, 5, {20, 15}, 4)};
    const std::vector<std::vector<Vec2>> lines{{{-10, 15}, {50, 15}},
                                               {{50, 15.0001}, {-10, 15.0001}},
                                               {{-10, 40}, {50, 40}},
                                               {{10, -5}, {10, 35}, {30, 35}, {30, -5}}};
    const auto pieces = clipPolylines(lines, regions, 0.01);
    ASSERT_EQ(pieces.size(), 6u);
    EXPECT_NEAR(pieces[0].front().x, 0, 1e-12);
    EXPECT_NEAR(pieces[0].back().x, 16, 1e-12);
    EXPECT_NEAR(pieces[1].front().x, 24, 1e-12);
    EXPECT_NEAR(pieces[1].back().x, 40, 1e-12);
    EXPECT_GT(pieces[2].front().x, pieces[2].back().x);  // the reversed line stays reversed
    EXPECT_NEAR(pieces[2].front().x, 40, 1e-12);
    EXPECT_NEAR(pieces[3].back().x, 0, 1e-12);
    // The U-shaped polyline leaves the region at the top: two pieces, each straight.
    EXPECT_EQ(pieces[4].size(), 2u);
    EXPECT_NEAR(pieces[4].front().y, 0, 1e-12);
    EXPECT_NEAR(pieces[4].back().y, 30, 1e-12);
    EXPECT_NEAR(pieces[5].front().y, 30, 1e-12);
    EXPECT_NEAR(pieces[5].back().y, 0, 1e-12);
    // A polyline inside with several vertices stays one piece with all its vertices.
    const auto inner = clipPolylines({{{2, 2}, {10, 3}, {12, 8}, {3, 9}}}, regions, 0.01);
    ASSERT_EQ(inner.size(), 1u);
    EXPECT_EQ(inner[0].size(), 4u);
    EXPECT_TRUE(clipPolylines(lines, {}, 0.01).empty());
}

TEST(ClipPolylines, RunsAlongBoundaryCountAsInside)
{
    const std::vector<Region> regions{Region{t::rectangle(0, 0, 10, 10), {}}};
    const auto pieces = clipPolylines({{{-5, 0}, {15, 0}}, {{-5, 10}, {5, 10}, {5, 20}}}, regions, 0.01);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(distance(pieces[0].front(), {0, 0}), 0, 1e-12);
    EXPECT_NEAR(distance(pieces[0].back(), {10, 0}), 0, 1e-12);
    EXPECT_NEAR(distance(pieces[1].front(), {0, 10}), 0, 1e-12);
    EXPECT_NEAR(distance(pieces[1].back(), {5, 10}), 0, 1e-12);
}

TEST(SegmentInside, CrossingsTouchesAndHoles)
{
    const std::vector<Region> regions{t::roundedRectWithCircle(40, 30, 5, {20, 15}, 4)};
    EXPECT_TRUE(segmentInside({2, 10}, {38, 10}, regions));
    EXPECT_FALSE(segmentInside({2, 15}, {38, 15}, regions));  // through the hole
    EXPECT_TRUE(segmentInside({2, 19}, {38, 19}, regions));   // tangent to the hole
    EXPECT_FALSE(segmentInside({2, 18.99}, {38, 18.99}, regions));
    EXPECT_TRUE(segmentInside({5, 0}, {35, 0}, regions));      // along the bottom edge
    EXPECT_FALSE(segmentInside({1, 0}, {35, 0}, regions));     // past the corner arc
    EXPECT_FALSE(segmentInside({-1, 10}, {10, 10}, regions));  // starts outside
    EXPECT_TRUE(segmentInside({0, 10}, {10, 10}, regions));    // starts on the boundary
    EXPECT_TRUE(segmentInside({3, 3}, {3, 3}, regions));
    EXPECT_FALSE(segmentInside({20, 15}, {20, 15}, regions));
    EXPECT_FALSE(segmentInside({0, 0}, {1, 1}, {}));
    // Two disjoint regions touching at a corner: a segment through the touching point is inside.
    const std::vector<Region> touching{Region{t::rectangle(0, 0, 10, 10), {}},
                                       Region{t::rectangle(10, 10, 10, 10), {}}};
    EXPECT_TRUE(segmentInside({5, 5}, {15, 15}, touching));
    EXPECT_FALSE(segmentInside({5, 6}, {15, 16}, touching));
}

TEST(SweptArea, LineAndPointFootprints)
{
    const double tol = 0.001;
    const std::vector<Region> slot = sweptArea({{{0, 0}, {30, 0}}}, 4, tol);
    ASSERT_EQ(slot.size(), 1u);
    EXPECT_NEAR(slot[0].area(), 8 * 30 + 16 * kPi, 0.1);
    EXPECT_EQ(t::countArcs(slot[0].outer), 2u);
    EXPECT_EQ(t::countLines(slot[0].outer), 2u);
    const std::vector<Region> disc = sweptArea({{{5, 5}}}, 2, tol);
    ASSERT_EQ(disc.size(), 1u);
    EXPECT_NEAR(disc[0].area(), 4 * kPi, 0.02);
    // A closed square path: a frame with a hole.
    const std::vector<Region> frame = sweptArea({{{0, 0}, {20, 0}, {20, 20}, {0, 20}, {0, 0}}}, 1, tol);
    ASSERT_EQ(frame.size(), 1u);
    EXPECT_EQ(frame[0].holes.size(), 1u);
    EXPECT_NEAR(frame[0].area(), 22 * 22 - (4 - kPi) - 18 * 18, 0.1);
    EXPECT_TRUE(sweptArea({}, 2, tol).empty());
    EXPECT_TRUE(sweptArea({{{0, 0}, {1, 1}}}, 0, tol).empty());
}
