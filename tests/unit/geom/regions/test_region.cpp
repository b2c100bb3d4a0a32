// Region queries with exact arcs: area, containment (boundary counts as inside), distances,
// orientation; containment checked against a finely discretised polygon on random points.
#include "RegionTestUtil.h"
#include "geom/ClipperAdapter.h"
#include "geom/Region.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

using namespace camwb::geom;
namespace t = camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

bool insidePolygon(const std::vector<Vec2>& poly, Vec2 p)
{
    bool inside = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < poly[j].x + (p.y - poly[j].y) / (poly[i].y - poly[j].y) * (poly[i].x - poly[j].x))
            inside = !inside;
    return inside;
}

}  // namespace

TEST(Region, AreaWithArcsAndHoles)
{
    const Region region = t::roundedRectWithCircle(40, 30, 5, {20, 15}, 4);
    const double expected = 40 * 30 - (4 - kPi) * 25 - kPi * 16;
    EXPECT_NEAR(region.area(), expected, 1e-9);
    EXPECT_NEAR(totalArea({region, Region{t::rectangle(100, 0, 2, 3), {}}}), expected + 6, 1e-9);
}

TEST(Region, ContainsAndBoundary)
{
    const Region region = t::roundedRectWithCircle(40, 30, 5, {20, 15}, 4);
    EXPECT_TRUE(region.contains({2, 15}));
    EXPECT_FALSE(region.contains({20, 15}));                                         // in the hole
    EXPECT_TRUE(region.contains({24, 15}));                                          // on the hole's circle
    EXPECT_TRUE(region.contains({20, 30}));                                          // on the top edge
    EXPECT_FALSE(region.contains({0.5, 0.5}));                                       // cut off by the corner arc
    EXPECT_TRUE(region.contains({5 - 5 / std::sqrt(2.0), 5 - 5 / std::sqrt(2.0)}));  // on the corner arc
    EXPECT_FALSE(region.contains({41, 15}));
    EXPECT_FALSE(region.contains({20, 15 + 3.999}));
    EXPECT_TRUE(region.contains({20, 15 + 4.001}));
    // Rays through the circle's top/bottom and through loop vertices.
    EXPECT_TRUE(region.contains({10, 19}));
    EXPECT_TRUE(region.contains({10, 11}));
    EXPECT_TRUE(region.contains({10, 5}));
    EXPECT_TRUE(anyContains({Region{t::rectangle(100, 0, 1, 1), {}}, region}, {10, 5}));
    EXPECT_FALSE(anyContains({}, {10, 5}));
}

TEST(Region, ContainsAgreesWithFinePolygonOnRandomPoints)
{
    Region region = t::roundedRectWithCircle(40, 30, 8, {28, 18}, 6);
    region.holes.push_back(t::roundedRectangle(5, 5, 12, 9, 3).reversed());
    region.holes.push_back(Region{t::circle({10, 24}, 2.5), {}}.outer.reversed());
    std::vector<std::vector<Vec2>> loops{discretize(region.outer, 1e-6)};
    for (const Profile& hole : region.holes)
        loops.push_back(discretize(hole, 1e-6));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-2, 42), y(-2, 32);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec2 p{x(rng), y(rng)};
        if (region.distanceToBoundary(p) < 1e-5)
            continue;
        bool expected = insidePolygon(loops[0], p);
        for (std::size_t h = 1; h < loops.size(); ++h)
            expected = expected && !insidePolygon(loops[h], p);
        ASSERT_EQ(region.contains(p), expected) << p.x << " " << p.y;
        ++checked;
    }
    EXPECT_GT(checked, 19000);
}

TEST(Region, DistanceToArcSegment)
{
    const Segment quarter = Segment::arc({10, 0}, {0, 10}, {0, 0}, true);
    EXPECT_NEAR(distanceToSegment({0, 0}, quarter), 10, 1e-12);
    EXPECT_NEAR(distanceToSegment({20, 20}, quarter), std::sqrt(800.0) - 10, 1e-12);
    EXPECT_NEAR(distanceToSegment({-5, -5}, quarter), std::hypot(15, 5), 1e-12);  // nearest: an end
    EXPECT_NEAR(distanceToSegment({20, 20}, quarter.reversed()), std::sqrt(800.0) - 10, 1e-12);
    const Segment clockwise = Segment::arc({10, 0}, {0, 10}, {0, 0}, false);  // the long way round
    EXPECT_NEAR(distanceToSegment({-20, -20}, clockwise), std::sqrt(800.0) - 10, 1e-12);
    EXPECT_NEAR(distanceToSegment({3, 4}, Segment::line({0, 0}, {10, 0})), 4, 1e-12);
    const Region region = t::roundedRectWithCircle(40, 30, 5, {20, 15}, 4);
    EXPECT_NEAR(region.distanceToBoundary({20, 15}), 4, 1e-12);
    EXPECT_NEAR(region.distanceToBoundary({1, 1}), std::sqrt(32.0) - 5, 1e-12);
}

TEST(Region, NormalizedOrientsLoops)
{
    const Region messy{t::rectangle(0, 0, 10, 10).reversed(), {t::circle({5, 5}, 2)}};
    const Region region = messy.normalized();
    EXPECT_GT(region.outer.signedArea(), 0);
    EXPECT_LT(region.holes[0].signedArea(), 0);
    EXPECT_NEAR(region.area(), 100 - 4 * kPi, 1e-9);
    EXPECT_NEAR(messy.area(), region.area(), 1e-12);
}
