// Inward offsets of closed profiles (contours cut inside): the same exact line/arc rules as the
// outward offset with the sides swapped; checked against Clipper's shrinking offset.
#include "../GeomTestUtil.h"
#include "geom/ClipperAdapter.h"
#include "geom/Offset.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

using namespace camwb::geom;
using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

TEST(OffsetInside, RoundedRectangleArcsShrink)
{
    for (bool reversed : {false, true}) {
        const Profile plate =
            reversed ? roundedRectangle(0, 0, 90, 60, 8).reversed() : roundedRectangle(0, 0, 90, 60, 8);
        auto off = offsetInside(plate, 5);
        ASSERT_TRUE(off.ok()) << off.error().message;
        EXPECT_EQ(off.value().segments.size(), 8u);
        EXPECT_EQ(countArcs(off.value()), 4u);
        EXPECT_EQ(off.value().signedArea() > 0, !reversed);  // orientation kept
        for (const Segment& s : off.value().segments)
            if (s.isArc())
                EXPECT_NEAR(s.radius(), 3, 1e-12);
        for (const Vec2& p : discretize(off.value(), 0.01))
            EXPECT_NEAR(distanceToProfile(p, plate), 5, 1e-9);
    }
}

TEST(OffsetInside, SharpConcaveCornerOfAHoleGetsAnArc)
{
    // An L-shaped hole: its inner (reflex) corner at (20, 20) is convex seen from the hole.
    const Profile l = polygon({{0, 0}, {40, 0}, {40, 20}, {20, 20}, {20, 40}, {0, 40}});
    auto off = offsetInside(l, 2);
    ASSERT_TRUE(off.ok()) << off.error().message;
    ASSERT_EQ(countArcs(off.value()), 1u);
    for (const Segment& s : off.value().segments)
        if (s.isArc()) {
            EXPECT_NEAR(distance(s.center, {20, 20}), 0, 1e-12);
            EXPECT_NEAR(s.radius(), 2, 1e-12);
        }
}

TEST(OffsetInside, ToolTooLargeIsAnError)
{
    auto arc = offsetInside(roundedRectangle(0, 0, 90, 60, 4), 5);
    ASSERT_FALSE(arc.ok());
    EXPECT_NE(arc.error().message.find("concave arc of radius 4"), std::string::npos) << arc.error().message;
    auto narrow = offsetInside(rectangle(0, 0, 90, 8), 5);
    ASSERT_FALSE(narrow.ok());
    EXPECT_NE(narrow.error().message.find("tool too large"), std::string::npos) << narrow.error().message;
    auto circ = offsetInside(circle({0, 0}, 4), 4);
    ASSERT_FALSE(circ.ok());
    Profile open = rectangle(0, 0, 10, 10);
    open.closed = false;
    auto o = offsetInside(open, 1);
    ASSERT_FALSE(o.ok());
    EXPECT_NE(o.error().message.find("open profile inside"), std::string::npos) << o.error().message;
}

TEST(OffsetInsideProperty, AgreesWithClipperAndKeepsDistance)
{
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> size(30, 120), frac(0.2, 0.45);
    int checked = 0;
    for (int i = 0; i < 16; ++i) {
        const double w = size(rng), h = size(rng);
        const double r = frac(rng) * std::min(w, h);
        const Profile shape = i % 2 ? roundedRectangle(3, -5, w, h, r) : roundedRectangle(3, -5, w, h, r).reversed();
        for (double d : {0.5, 2.0, 0.9 * r}) {
            SCOPED_TRACE("case " + std::to_string(i) + " d=" + std::to_string(d));
            auto off = offsetInside(shape, d);
            ASSERT_TRUE(off.ok()) << off.error().message;
            double clipperArea = 0;
            for (const auto& poly : clipperOffset(discretize(shape, 0.002), -d, 0.002))
                clipperArea += polygonArea(poly);
            EXPECT_NEAR(std::abs(off.value().signedArea()), clipperArea, 0.005 * clipperArea);
            for (const Vec2& p : discretize(off.value(), 0.05))
                EXPECT_NEAR(distanceToProfile(p, shape), d, 1e-6);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 48);
    (void)kPi;
}
