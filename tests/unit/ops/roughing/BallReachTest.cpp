// ballReach against a brute force: the distance from a ball centre on the plane to the piece,
// computed by sampling the piece densely. Every point within the radius must lie inside the
// polygon, and every corner of the polygon must stand within the radius plus the chord.
#include "ops/surface/BallReach.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace camwb::ops::surface {
namespace {

using base::Vec2;
using base::Vec3;

// Distance from c to the triangle a b d, by its barycentric samples (fine enough for the test's
// margins) and its edges.
double sampledDistance(const Vec3& c, const std::vector<Vec3>& tri)
{
    double best = INFINITY;
    const int n = 120;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const double s = double(i) / n, t = double(j) / n;
            const Vec3 p{tri[0].x + s * (tri[1].x - tri[0].x) + t * (tri[2].x - tri[0].x),
                         tri[0].y + s * (tri[1].y - tri[0].y) + t * (tri[2].y - tri[0].y),
                         tri[0].z + s * (tri[1].z - tri[0].z) + t * (tri[2].z - tri[0].z)};
            best = std::min(
                best, std::sqrt((p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y) + (p.z - c.z) * (p.z - c.z)));
        }
    return best;
}

bool insideConvex(const std::vector<Vec2>& poly, Vec2 q)
{
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        if ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) < -1e-9)
            return false;
    }
    return true;
}

TEST(BallReach, ContainsEveryCentreWithinTheRadiusAndNoCornerFarOutside)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> xy(-4, 4), z(-3, 0);
    const double r = 3, chord = 0.01, zc = 0;
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        // Pieces under the equator, within reach height-wise (as the tool-centre regions give them).
        const std::vector<Vec3> tri{{xy(rng), xy(rng), z(rng)}, {xy(rng), xy(rng), z(rng)}, {xy(rng), xy(rng), z(rng)}};
        const std::vector<Vec2> poly = ballReach(tri, zc, r, 0, chord);
        ASSERT_GE(poly.size(), 8u);
        for (const Vec2& corner : poly)
            EXPECT_LE(sampledDistance({corner.x, corner.y, zc}, tri), r + chord + 0.02) << "trial " << trial;
        for (double x = -8; x <= 8; x += 0.25)
            for (double y = -8; y <= 8; y += 0.25) {
                const double d = sampledDistance({x, y, zc}, tri);
                if (d <= r - 1e-6) {
                    EXPECT_TRUE(insideConvex(poly, {x, y})) << "trial " << trial << " at " << x << ", " << y;
                    ++checked;
                } else if (d > r + chord + 0.02) {
                    EXPECT_FALSE(insideConvex(poly, {x, y})) << "trial " << trial << " at " << x << ", " << y;
                }
            }
    }
    EXPECT_GT(checked, 1000);
}

TEST(BallReach, AFlatPieceAtTheCentresHeightGrowsByTheRadius)
{
    // A horizontal square at the plane: its reach is the square grown by r (rounded corners).
    const std::vector<Vec3> square{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
    const std::vector<Vec2> poly = ballReach(square, 0, 2, 0, 0.001);
    double xmin = INFINITY, xmax = -INFINITY;
    for (const Vec2& p : poly)
        xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    EXPECT_NEAR(xmin, -2, 1e-9);
    EXPECT_NEAR(xmax, 12, 1e-9);
    // A piece wholly out of reach gives nothing.
    EXPECT_TRUE(ballReach(square, 5, 2, 0, 0.001).empty());
}

TEST(BallReach, APieceBelowTheCentreReachesByTheSectionsRadius)
{
    // A point-like horizontal triangle 1.8 below a ball of radius 3: a disc of sqrt(9 - 3.24) = 2.4.
    const std::vector<Vec3> tiny{{0, 0, -1.8}, {1e-6, 0, -1.8}, {0, 1e-6, -1.8}};
    const std::vector<Vec2> poly = ballReach(tiny, 0, 3, 0, 0.001);
    double far = 0, near = INFINITY;
    for (const Vec2& p : poly)
        far = std::max(far, std::hypot(p.x, p.y)), near = std::min(near, std::hypot(p.x, p.y));
    EXPECT_NEAR(near, 2.4, 2e-3);  // the corners lie outside the circle by less than the chord
    EXPECT_LE(far, 2.4 + 0.001 + 1e-6);
    // Grown by 0.5 horizontally: a disc of 2.9.
    double grown = INFINITY;
    for (const Vec2& p : ballReach(tiny, 0, 3, 0.5, 0.001))
        grown = std::min(grown, std::hypot(p.x, p.y));
    EXPECT_NEAR(grown, 2.9, 2e-3);
}

}  // namespace
}  // namespace camwb::ops::surface
