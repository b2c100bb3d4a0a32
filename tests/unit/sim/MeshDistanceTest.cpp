// The exact point-to-mesh distance the gouge checks confirm a depth with: the nearest point of a
// triangle against a dense sampling of it, and a box's distance inside and out against the
// formula, including the cap `within`.
#include "sim/MeshDistance.h"
#include "StockTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace camwb;
using namespace camwb::sim;
using namespace camwb::sim::test;

TEST(SimMeshDistance, ClosestPointOfATriangleIsTheNearestOfItsPoints)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coord(-2, 2);
    auto point = [&] { return Vec3{coord(random), coord(random), coord(random)}; };
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 a = point(), b = point(), c = point(), p = point() * 2;
        const double found = (p - closestOnTriangle(p, a, b, c)).length();
        double sampled = 1e9;
        constexpr int n = 200;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const Vec3 q = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
                sampled = std::min(sampled, (p - q).length());
            }
        EXPECT_LE(found, sampled + 1e-9) << "trial " << trial;
        EXPECT_NEAR(found, sampled, 0.02 * ((b - a).length() + (c - a).length())) << "trial " << trial;
    }
}

TEST(SimMeshDistance, ABoxInsideAndOut)
{
    const MeshDistance box(boxMesh({0, 0, 0}, {40, 20, 10}));
    EXPECT_NEAR(box.distance({20, 10, 9.3}, 100), 0.7, 1e-9);  // under the top
    EXPECT_NEAR(box.distance({1, 10, 5}, 100), 1, 1e-9);       // inside, by the -x side
    EXPECT_NEAR(box.distance({20, 10, 5}, 100), 5, 1e-9);      // the middle: 5 from top and bottom
    EXPECT_NEAR(box.distance({43, 24, 10}, 100), 5, 1e-9);     // outside, off an edge
    EXPECT_NEAR(box.distance({-3, -4, 22}, 100), 13, 1e-9);    // outside, off a corner
    EXPECT_NEAR(box.distance({20, 10, 5}, 2.5), 2.5, 1e-12);   // nothing within 2.5: the cap
    EXPECT_NEAR(box.distance({200, 10, 5}, 50), 50, 1e-12);    // the search box misses the mesh
    EXPECT_TRUE(MeshDistance().empty());
    EXPECT_EQ(MeshDistance().distance({0, 0, 0}, 3), 3);
}
