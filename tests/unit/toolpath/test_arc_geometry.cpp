// The CL arc geometry: splitting, linearising within the tolerance and exact extents,
// checked against dense sampling of the arc rather than against hand-picked numbers only.
#include "toolpath/ArcGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace camwb::toolpath {
namespace {

// A point on the arc at fraction t of its sweep, from the pieces of a 1-degree split.
std::vector<Vec3> sample(const Vec3& start, const Arc& arc)
{
    std::vector<Vec3> points{start};
    for (const ArcPiece& piece : splitArc(start, arc, 1))
        points.push_back(piece.end);
    return points;
}

struct Random {
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    double next(double low, double high)
    {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return low + (high - low) * static_cast<double>(state % 1000003) / 1000003.0;
    }
};

TEST(ArcGeometry, PlanesAndSweeps)
{
    EXPECT_EQ(arcPlane({0, 0, -1}), "XY");
    EXPECT_EQ(arcPlane({0, 2, 0}), "ZX");
    EXPECT_EQ(arcPlane({1, 0, 0}), "YZ");
    EXPECT_EQ(arcPlane({0.6, 0.8, 0}), "");
    const Arc quarter{{0, 10, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 100};
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, quarter), 90, 1e-9);
    Arc longWay = quarter;
    longWay.clockwise = true;
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, longWay), 270, 1e-9);
    const Arc circle{{10, 0, -3}, {0, 0, 0}, {0, 0, 1}, true, 2, 100};
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, circle), 1080, 1e-9);
    EXPECT_EQ(arcSweepDeg({0, 0, 0}, quarter), 0);  // start on the axis: degenerate
}

TEST(ArcGeometry, SplitPiecesAreEqualAndEndExactly)
{
    const Arc helix{{10, 0, -6}, {0, 0, 0}, {0, 0, 1}, false, 1, 100};  // two turns down 6 mm
    const std::vector<ArcPiece> pieces = splitArc({10, 0, 0}, helix, 100);
    ASSERT_EQ(pieces.size(), 8u);  // 720 / 100 -> 8 pieces of 90
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        EXPECT_NEAR(pieces[i].sweepDeg, 90, 1e-9);
        EXPECT_TRUE(pieces[i].helical);
        EXPECT_NEAR(pieces[i].end.z, -0.75 * static_cast<double>(i + 1), 1e-9);
        EXPECT_NEAR(std::hypot(pieces[i].end.x, pieces[i].end.y), 10, 1e-9);
        if (i > 0)
            EXPECT_EQ(pieces[i].start, pieces[i - 1].end);
    }
    EXPECT_EQ(pieces.back().end, helix.to);
}

TEST(ArcGeometry, LinearisedPointsStayWithinTheTolerance)
{
    Random random;
    for (int n = 0; n < 200; ++n) {
        const double radius = random.next(0.5, 50);
        const double tolerance = random.next(0.001, 0.1);
        const double endAngle = random.next(0.1, 6.2);
        const Vec3 start{radius, 0, 0};
        const Arc arc{{radius * std::cos(endAngle), radius * std::sin(endAngle), random.next(-2, 2)},
                      {0, 0, 0},
                      {0, 0, 1},
                      false,
                      0,
                      100};
        const std::vector<Vec3> points = linearizeArc(start, arc, tolerance);
        ASSERT_FALSE(points.empty());
        EXPECT_EQ(linearizedPointCount(start, arc, tolerance), int(points.size()));
        EXPECT_EQ(linearizedPointCount(start, arc, tolerance, 10, 7),
                  int(linearizeArc(start, arc, tolerance, 10, 7).size()));
        EXPECT_EQ(points.back(), arc.to);
        Vec3 previous = start;
        for (const Vec3& p : points) {
            // Every point lies on the helix, and the chord's midpoint strays at most the tolerance.
            EXPECT_NEAR(std::hypot(p.x, p.y), radius, 1e-9);
            const Vec3 mid = (previous + p) * 0.5;
            EXPECT_LE(radius - std::hypot(mid.x, mid.y), tolerance + 1e-9);
            previous = p;
        }
    }
}

TEST(ArcGeometry, ExtentsMatchDenseSampling)
{
    Random random;
    const Vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {1, 0, 0}, {0.6, 0, 0.8}};
    for (int n = 0; n < 400; ++n) {
        const Vec3 normal = normals[n % 5];
        const Vec3 center{random.next(-50, 50), random.next(-50, 50), random.next(-50, 50)};
        // In-plane start and end directions from the plane's own axes.
        const Vec3 a = std::abs(normal.z) > 0.5 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
        const Vec3 u = a - normal * a.dot(normal);
        const Vec3 v = normal.cross(u);
        const double radius = random.next(0.5, 30);
        const double t0 = random.next(0, 6.28), t1 = random.next(0, 6.28);
        const Vec3 start = center + (u * std::cos(t0) + v * std::sin(t0)) * radius;
        Arc arc{center + (u * std::cos(t1) + v * std::sin(t1)) * radius + normal * random.next(-3, 3),
                center,
                normal,
                n % 2 == 0,
                n % 7 == 0 ? 1 : 0,
                100};
        Vec3 min = start, max = start, sampledMin = start, sampledMax = start;
        extendByArc(min, max, start, arc);
        for (const Vec3& p : sample(start, arc)) {
            sampledMin = {std::min(sampledMin.x, p.x), std::min(sampledMin.y, p.y), std::min(sampledMin.z, p.z)};
            sampledMax = {std::max(sampledMax.x, p.x), std::max(sampledMax.y, p.y), std::max(sampledMax.z, p.z)};
        }
        // The extents hold every sample (exactly in principal planes, within the 1e-5 r of their own
        // sampling in oblique ones) and exceed them by at most a 1-degree chord's sag.
        const double sag = radius * (1 - std::cos(std::numbers::pi / 360)) + 1e-9;
        const double slack = arcPlane(normal).empty() ? 1e-5 * radius : 1e-9;
        for (auto [exact, sampled, low] : {std::tuple{min.x, sampledMin.x, true},
                                           {min.y, sampledMin.y, true},
                                           {min.z, sampledMin.z, true},
                                           {max.x, sampledMax.x, false},
                                           {max.y, sampledMax.y, false},
                                           {max.z, sampledMax.z, false}}) {
            if (low) {
                EXPECT_LE(exact, sampled + slack) << n;
                EXPECT_GE(exact, sampled - sag) << n;
            } else {
                EXPECT_GE(exact, sampled - slack) << n;
                EXPECT_LE(exact, sampled + sag) << n;
            }
        }
    }
}

}  // namespace
}  // namespace camwb::toolpath
