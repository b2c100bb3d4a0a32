#include "GeomTestUtil.h"
#include "geom/Profile.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace camwb::geom;
using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

TEST(Segment, SweepSignFollowsDirection)
{
    const Segment quarterCcw = Segment::arc({1, 0}, {0, 1}, {0, 0}, true);
    EXPECT_NEAR(quarterCcw.sweep(), kPi / 2, 1e-12);
    const Segment threeQuartersCw = Segment::arc({1, 0}, {0, 1}, {0, 0}, false);
    EXPECT_NEAR(threeQuartersCw.sweep(), -3 * kPi / 2, 1e-12);
    const Segment halfCw = Segment::arc({1, 0}, {-1, 0}, {0, 0}, false);
    EXPECT_NEAR(halfCw.sweep(), -kPi, 1e-12);
    EXPECT_NEAR(Segment::arc({2, 0}, {2, 0}, {0, 0}, true).sweep(), 2 * kPi, 1e-12);
    EXPECT_NEAR(Segment::arc({2, 0}, {2, 0}, {0, 0}, false).sweep(), -2 * kPi, 1e-12);
    EXPECT_EQ(Segment::line({0, 0}, {3, 4}).sweep(), 0);
}

TEST(Segment, LengthTangentsAndPoints)
{
    const Segment arc = Segment::arc({2, 0}, {0, 2}, {0, 0}, true);
    EXPECT_NEAR(arc.length(), kPi, 1e-12);
    EXPECT_NEAR(arc.startTangent().x, 0, 1e-12);
    EXPECT_NEAR(arc.startTangent().y, 1, 1e-12);
    EXPECT_NEAR(arc.endTangent().x, -1, 1e-12);
    const Vec2 mid = arc.pointAt(0.5);
    EXPECT_NEAR(mid.x, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(mid.y, std::sqrt(2.0), 1e-12);
    const Segment rev = arc.reversed();
    EXPECT_FALSE(rev.ccw);
    EXPECT_NEAR(rev.sweep(), -kPi / 2, 1e-12);
    EXPECT_EQ(Segment::line({0, 0}, {3, 4}).length(), 5);
}

TEST(Profile, SignedAreaOfCircleIsExact)
{
    EXPECT_NEAR(circle({3, -2}, 7).signedArea(), kPi * 49, 1e-9);
    EXPECT_NEAR(circle({3, -2}, 7).reversed().signedArea(), -kPi * 49, 1e-9);
    EXPECT_NEAR(circle({0, 0}, 7).length(), 14 * kPi, 1e-9);
}

TEST(Profile, SignedAreaOfRoundedRectangleIsExact)
{
    const Profile p = roundedRectangle(0, 0, 90, 60, 8);
    EXPECT_NEAR(p.signedArea(), 90 * 60 - (4 - kPi) * 64, 1e-9);
    EXPECT_NEAR(p.reversed().signedArea(), -(90 * 60 - (4 - kPi) * 64), 1e-9);
    EXPECT_NEAR(p.length(), 2 * (74 + 44) + 16 * kPi, 1e-9);
    EXPECT_TRUE(p.isContinuous());
    EXPECT_TRUE(p.reversed().isContinuous());
}

TEST(Profile, ContinuityDetectsGaps)
{
    Profile p = rectangle(0, 0, 10, 5);
    EXPECT_TRUE(p.isContinuous());
    p.segments[2].start.x += 0.01;
    EXPECT_FALSE(p.isContinuous());
}

TEST(Profile, DiscretizeKeepsChordErrorWithinTolerance)
{
    const Profile p = roundedRectangle(0, 0, 90, 60, 8);
    for (double tol : {0.1, 0.01, 0.001}) {
        const std::vector<Vec2> pts = discretize(p, tol);
        ASSERT_GT(pts.size(), 8u);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const Vec2 a = pts[i];
            const Vec2 b = pts[(i + 1) % pts.size()];
            // Every point lies on the profile, every chord midpoint within tol of it.
            EXPECT_LT(distanceToProfile(a, p), 1e-9);
            EXPECT_LE(distanceToProfile((a + b) * 0.5, p), tol + 1e-12);
        }
    }
}

TEST(Profile, DiscretizeOpenProfileEndsAtItsEnd)
{
    Profile p;
    p.closed = false;
    p.segments = {Segment::line({0, 0}, {10, 0}), Segment::arc({10, 0}, {10, 10}, {10, 5}, true)};
    const std::vector<Vec2> pts = discretize(p, 0.01);
    EXPECT_EQ(pts.front(), (Vec2{0, 0}));
    EXPECT_EQ(pts.back(), (Vec2{10, 10}));
}
