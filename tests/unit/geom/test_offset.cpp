#include "GeomTestUtil.h"
#include "geom/Offset.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace camwb::geom;
using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

void expectOffsetPointsAtDistance(const Profile& input, const Profile& offset, double d)
{
    for (const Vec2& p : discretize(offset, 0.01))
        EXPECT_NEAR(distanceToProfile(p, input), d, 1e-9) << "at (" << p.x << ", " << p.y << ")";
}

// The L shape: concave corner at (20, 20).
Profile lShape() { return polygon({{0, 0}, {60, 0}, {60, 20}, {20, 20}, {20, 50}, {0, 50}}); }

// 80 x 50 rectangle with a semicircular notch of radius 10 (a concave arc) in its top edge.
Profile notchedRectangle()
{
    Profile p;
    p.segments = {
        Segment::line({0, 0}, {80, 0}),    Segment::line({80, 0}, {80, 50}),
        Segment::line({80, 50}, {50, 50}), Segment::arc({50, 50}, {30, 50}, {40, 50}, false),
        Segment::line({30, 50}, {0, 50}),  Segment::line({0, 50}, {0, 0}),
    };
    return p;
}

}  // namespace

TEST(OffsetOutside, RectangleGetsCornerArcsAndSteinerArea)
{
    const Profile rect = rectangle(0, 0, 90, 60);
    const double d = 5;
    auto result = offsetOutside(rect, d);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Profile& off = result.value();
    ASSERT_EQ(off.segments.size(), 8u);
    EXPECT_EQ(countArcs(off), 4u);
    for (const Segment& s : off.segments) {
        if (!s.isArc())
            continue;
        EXPECT_NEAR(s.radius(), d, 1e-12);
        EXPECT_TRUE(s.ccw);
        EXPECT_NEAR(std::abs(s.sweep()), kPi / 2, 1e-12);
    }
    EXPECT_TRUE(off.isContinuous(1e-12));
    EXPECT_NEAR(off.signedArea(), 90 * 60 + 300 * d + kPi * d * d, 1e-9);
    expectOffsetPointsAtDistance(rect, off, d);
}

TEST(OffsetOutside, RoundedRectangleArcsGrowWithoutExtraArcs)
{
    const Profile rr = roundedRectangle(0, 0, 90, 60, 8);
    auto result = offsetOutside(rr, 5);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Profile& off = result.value();
    ASSERT_EQ(off.segments.size(), 8u);
    EXPECT_EQ(countArcs(off), 4u);
    for (std::size_t i = 0; i < off.segments.size(); ++i) {
        EXPECT_EQ(off.segments[i].kind, rr.segments[i].kind);
        if (off.segments[i].isArc()) {
            EXPECT_NEAR(off.segments[i].radius(), 13, 1e-12);
            EXPECT_EQ(off.segments[i].center, rr.segments[i].center);
        }
    }
    const double area = rr.signedArea();
    EXPECT_NEAR(off.signedArea(), area + rr.length() * 5 + kPi * 25, 1e-9);
    EXPECT_TRUE(off.isContinuous(1e-12));
    expectOffsetPointsAtDistance(rr, off, 5);
}

TEST(OffsetOutside, CircleGrows)
{
    auto result = offsetOutside(circle({1, 2}, 10), 2.5);
    ASSERT_TRUE(result.ok()) << result.error().message;
    ASSERT_EQ(result->segments.size(), 1u);
    EXPECT_NEAR(result->segments[0].radius(), 12.5, 1e-12);
    EXPECT_NEAR(result->signedArea(), kPi * 12.5 * 12.5, 1e-9);
}

TEST(OffsetOutside, LShapeConcaveCornerIsTrimmed)
{
    const Profile l = lShape();
    auto result = offsetOutside(l, 5);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Profile& off = result.value();
    // Five convex corners get arcs, the concave one none.
    EXPECT_EQ(countArcs(off), 5u);
    EXPECT_EQ(off.segments.size(), 11u);
    bool foundTrimmedCorner = false;
    for (const Segment& s : off.segments)
        if (s.end == Vec2{25, 25})
            foundTrimmedCorner = true;
    EXPECT_TRUE(foundTrimmedCorner);
    EXPECT_TRUE(off.isContinuous(1e-12));
    EXPECT_GT(off.signedArea(), 0);
    expectOffsetPointsAtDistance(l, off, 5);
}

TEST(OffsetOutside, ConcaveArcRadiusShrinks)
{
    const Profile p = notchedRectangle();
    auto result = offsetOutside(p, 4);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Profile& off = result.value();
    int notchArcs = 0;
    for (const Segment& s : off.segments)
        if (s.isArc() && s.center == Vec2{40, 50}) {
            ++notchArcs;
            EXPECT_NEAR(s.radius(), 6, 1e-12);
            EXPECT_FALSE(s.ccw);
        }
    EXPECT_EQ(notchArcs, 1);
    // Four rectangle corners and the two convex notch edges get corner arcs.
    EXPECT_EQ(countArcs(off), 7u);
    EXPECT_TRUE(off.isContinuous(1e-12));
    expectOffsetPointsAtDistance(p, off, 4);
}

TEST(OffsetOutside, ConcaveArcSmallerThanToolIsAnError)
{
    auto result = offsetOutside(notchedRectangle(), 10);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("tool too large for the concave arc of radius 10 at (40, 50)"),
              std::string::npos)
        << result.error().message;
}

TEST(OffsetOutside, SlotNarrowerThanToolIsAnError)
{
    // U shape with a 10 mm slot: a 12 mm tool does not fit, the slot bottom reverses.
    const Profile u = polygon({{0, 0}, {50, 0}, {50, 40}, {30, 40}, {30, 20}, {20, 20}, {20, 40}, {0, 40}});
    ASSERT_TRUE(offsetOutside(u, 4.9).ok());
    auto result = offsetOutside(u, 6);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("tool too large for the feature"), std::string::npos)
        << result.error().message;
}

TEST(OffsetOutside, ClockwiseInputKeepsClockwiseOrientation)
{
    const Profile cw = roundedRectangle(0, 0, 90, 60, 8).reversed();
    ASSERT_LT(cw.signedArea(), 0);
    auto result = offsetOutside(cw, 5);
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_LT(result->signedArea(), 0);
    EXPECT_NEAR(result->signedArea(), cw.signedArea() - cw.length() * 5 - kPi * 25, 1e-9);
    for (const Segment& s : result->segments)
        if (s.isArc()) {
            EXPECT_FALSE(s.ccw);
            EXPECT_NEAR(s.radius(), 13, 1e-12);
        }

    const Profile lcw = lShape().reversed();
    auto l = offsetOutside(lcw, 5);
    ASSERT_TRUE(l.ok()) << l.error().message;
    auto lccw = offsetOutside(lShape(), 5);
    EXPECT_NEAR(l->signedArea(), -lccw->signedArea(), 1e-9);
    expectOffsetPointsAtDistance(lcw, l.value(), 5);
}

TEST(OffsetOutside, InvalidInputsAreErrors)
{
    Profile open = rectangle(0, 0, 10, 10);
    open.closed = false;
    auto r1 = offsetOutside(open, 1);
    ASSERT_FALSE(r1.ok());
    EXPECT_NE(r1.error().message.find("open"), std::string::npos);

    Profile gap = rectangle(0, 0, 10, 10);
    gap.segments[1].end = {10, 9};
    auto r2 = offsetOutside(gap, 1);
    ASSERT_FALSE(r2.ok());
    EXPECT_NE(r2.error().message.find("discontinuous"), std::string::npos);

    EXPECT_FALSE(offsetOutside(rectangle(0, 0, 10, 10), 0).ok());
    EXPECT_FALSE(offsetOutside(rectangle(0, 0, 10, 10), -1).ok());
    EXPECT_FALSE(offsetOutside(Profile{}, 1).ok());
}

TEST(OffsetOutside, NearlyTangentConcaveJointIsJoined)
{
    // A line meets a convex arc with a concave kink of ~1e-7 rad, as CAD data often has.
    for (double kink : {1e-7, 1e-9, 1e-11}) {
        SCOPED_TRACE(kink);
        Profile p;
        p.segments = {
            Segment::line({10 + 20 * kink, -20}, {10, 0}),
            Segment::arc({10, 0}, {0, 10}, {0, 0}, true),
            Segment::line({0, 10}, {-20, 10}),
            Segment::line({-20, 10}, {-20, -20}),
            Segment::line({-20, -20}, {10 + 20 * kink, -20}),
        };
        auto result = offsetOutside(p, 5);
        ASSERT_TRUE(result.ok()) << result.error().message;
        EXPECT_TRUE(result->isContinuous(1e-9));
        for (const Vec2& q : discretize(result.value(), 0.01))
            EXPECT_NEAR(distanceToProfile(q, p), 5, 1e-6);
    }
}
