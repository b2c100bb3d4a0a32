// Property check of the exact offset against Clipper's round-join polygon offset: same area
// (within 0.5%) and every offset point exactly `d` from the input.
#include "GeomTestUtil.h"
#include "geom/ClipperAdapter.h"
#include "geom/Offset.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <string>

using namespace camwb::geom;
using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

struct Case {
    std::string name;
    Profile profile;
};

Profile randomConvexPolygon(std::mt19937& rng)
{
    std::uniform_real_distribution<double> angle(0, 2 * kPi);
    std::uniform_real_distribution<double> radius(10, 40);
    std::uniform_int_distribution<int> count(3, 12);
    const double r = radius(rng);
    std::vector<double> angles(static_cast<std::size_t>(count(rng)));
    for (double& a : angles)
        a = angle(rng);
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> pts;
    for (double a : angles) {
        const Vec2 p{r * std::cos(a), r * std::sin(a)};
        if (pts.empty() || distance(p, pts.back()) > 0.5)
            pts.push_back(p);
    }
    if (pts.size() >= 3 && distance(pts.front(), pts.back()) < 0.5)
        pts.pop_back();
    return polygon(pts);
}

// L shape with a concave fillet of radius 4 in its inner corner and a convex round of radius 6.
Profile filletedL()
{
    Profile p;
    p.segments = {
        Segment::line({0, 0}, {54, 0}),
        Segment::arc({54, 0}, {60, 6}, {54, 6}, true),
        Segment::line({60, 6}, {60, 20}),
        Segment::line({60, 20}, {24, 20}),
        Segment::arc({24, 20}, {20, 24}, {24, 24}, false),
        Segment::line({20, 24}, {20, 50}),
        Segment::line({20, 50}, {0, 50}),
        Segment::line({0, 50}, {0, 0}),
    };
    return p;
}

// T shape: bar on top, stem ending in a convex half circle, a concave arc meeting a line at an angle.
Profile tShape()
{
    Profile p;
    p.segments = {
        Segment::arc({20, 0}, {40, 0}, {30, 0}, true),
        Segment::line({40, 0}, {40, 40}),
        Segment::line({40, 40}, {60, 40}),
        Segment::line({60, 40}, {60, 60}),
        Segment::line({60, 60}, {0, 60}),
        Segment::line({0, 60}, {0, 40}),
        // concave arc from (0,40) to (20,30) bulging into the part, meeting the stem at an angle
        Segment::arc({0, 40}, {20, 30}, {-5, 5}, false),
        Segment::line({20, 30}, {20, 0}),
    };
    return p;
}

// U shape: a slot with a concave half-circle bottom, rounded outer corners.
Profile uShape()
{
    Profile p;
    p.segments = {
        Segment::line({5, 0}, {55, 0}),    Segment::arc({55, 0}, {60, 5}, {55, 5}, true),
        Segment::line({60, 5}, {60, 40}),  Segment::line({60, 40}, {40, 40}),
        Segment::line({40, 40}, {40, 20}), Segment::arc({40, 20}, {20, 20}, {30, 20}, false),
        Segment::line({20, 20}, {20, 40}), Segment::line({20, 40}, {0, 40}),
        Segment::line({0, 40}, {0, 5}),    Segment::arc({0, 5}, {5, 0}, {5, 5}, true),
    };
    return p;
}

// Two concave arcs meeting each other at a corner (arc-arc trim), closed by lines.
Profile twoConcaveArcs()
{
    Profile p;
    p.segments = {
        Segment::line({0, 0}, {60, 0}),
        Segment::line({60, 0}, {60, 40}),
        Segment::arc({60, 40}, {30, 30}, {25, 95}, false),
        Segment::arc({30, 30}, {0, 40}, {35, 95}, false),
        Segment::line({0, 40}, {0, 0}),
    };
    return p;
}

std::vector<Case> cases()
{
    std::vector<Case> out;
    std::mt19937 rng(20240611);
    for (int i = 0; i < 12; ++i)
        out.push_back({"convex" + std::to_string(i), randomConvexPolygon(rng)});
    std::uniform_real_distribution<double> size(20, 120);
    for (int i = 0; i < 6; ++i) {
        const double w = size(rng), h = size(rng);
        const double r = std::uniform_real_distribution<double>(0.5, std::min(w, h) / 2 - 0.1)(rng);
        out.push_back({"rounded" + std::to_string(i), roundedRectangle(-w / 3, 7, w, h, r)});
    }
    out.push_back({"filletedL", filletedL()});
    out.push_back({"filletedL-cw", filletedL().reversed()});
    out.push_back({"T", tShape()});
    out.push_back({"U", uShape()});
    out.push_back({"U-cw", uShape().reversed()});
    out.push_back({"twoConcaveArcs", twoConcaveArcs()});
    return out;
}

}  // namespace

TEST(OffsetProperty, AgreesWithClipperAndKeepsDistance)
{
    const double tol = 0.002;
    int checked = 0;
    for (const Case& c : cases()) {
        ASSERT_TRUE(c.profile.isContinuous()) << c.name;
        for (double d : {0.5, 1.0, 3.0, 3.9}) {
            SCOPED_TRACE(c.name + " d=" + std::to_string(d));
            auto result = offsetOutside(c.profile, d);
            ASSERT_TRUE(result.ok()) << result.error().message;
            const Profile& off = result.value();
            EXPECT_TRUE(off.isContinuous(1e-9));
            // Orientation is kept.
            EXPECT_EQ(off.signedArea() > 0, c.profile.signedArea() > 0);

            double clipperArea = 0;
            for (const auto& poly : clipperOffset(discretize(c.profile, tol), d, tol))
                clipperArea += polygonArea(poly);
            const double ours = std::abs(off.signedArea());
            EXPECT_NEAR(ours, clipperArea, 0.005 * clipperArea);

            for (const Vec2& p : discretize(off, 0.05)) {
                const double dist = distanceToProfile(p, c.profile);
                EXPECT_GE(dist, d - 1e-6);
                EXPECT_NEAR(dist, d, 1e-6);
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 24 * 4);
}

TEST(ClipperAdapter, SquareOffsetAndArea)
{
    const std::vector<Vec2> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    EXPECT_DOUBLE_EQ(polygonArea(square), 100);
    EXPECT_DOUBLE_EQ(polygonArea({{0, 0}, {0, 10}, {10, 10}, {10, 0}}), -100);
    // Either input orientation grows with a positive delta; output is counter-clockwise.
    for (const auto& input : {square, std::vector<Vec2>(square.rbegin(), square.rend())}) {
        const auto out = clipperOffset(input, 2, 0.0001);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_NEAR(polygonArea(out[0]), 100 + 40 * 2 + kPi * 4, 1e-3);
    }
    const auto shrunk = clipperOffset(square, -2, 0.001);
    ASSERT_EQ(shrunk.size(), 1u);
    EXPECT_NEAR(polygonArea(shrunk[0]), 36, 1e-6);
    EXPECT_TRUE(clipperOffset(square, -6, 0.001).empty());
}
