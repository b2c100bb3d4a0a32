// The silhouette of selected faces: overlapping and touching triangles unite, vertical ones add
// nothing, a ring of triangles keeps its hole.
#include "ops/surface/Silhouette.h"

#include <gtest/gtest.h>

#include <cmath>

using camwb::ops::surface::silhouette;
using camwb::sim::TriangleMesh;

namespace {

void addTriangle(TriangleMesh& m, float ax, float ay, float bx, float by, float cx, float cy, float z = 0)
{
    const auto base = static_cast<std::uint32_t>(m.vertexCount());
    m.positions.insert(m.positions.end(), {ax, ay, z, bx, by, z, cx, cy, z});
    m.triangles.insert(m.triangles.end(), {base, base + 1, base + 2});
}

// A square of side `outer` with a square hole of side `inner`, both centred at the origin, as
// eight triangles (each ring side a trapezoid of two), at a height varying per triangle.
TriangleMesh squareRing(float outer, float inner)
{
    TriangleMesh m;
    const float o = outer / 2, i = inner / 2;
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
        const float* a = corners[k];
        const float* b = corners[(k + 1) % 4];
        addTriangle(m, a[0] * o, a[1] * o, b[0] * o, b[1] * o, b[0] * i, b[1] * i, float(k));
        addTriangle(m, a[0] * o, a[1] * o, b[0] * i, b[1] * i, a[0] * i, a[1] * i, float(k) + 0.5f);
    }
    return m;
}

}  // namespace

TEST(Silhouette, UnitesTrianglesAndKeepsHoles)
{
    const auto regions = silhouette(squareRing(10, 4), 0.001);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_EQ(regions[0].holes.size(), 1u);
    EXPECT_NEAR(regions[0].area(), 100 - 16, 1e-3);
    EXPECT_FALSE(regions[0].contains({0, 0}));
    EXPECT_TRUE(regions[0].contains({4, 4}));
}

TEST(Silhouette, OverlapsCountOnceAndVerticalTrianglesAddNothing)
{
    TriangleMesh m;
    addTriangle(m, 0, 0, 4, 0, 0, 4);
    addTriangle(m, 0, 0, 4, 0, 0, 4, 3);  // the same seen from above, higher up: once
    addTriangle(m, 0, 4, 0, 0, 4, 0);     // clockwise: still its area
    // A vertical triangle (x = 10, spanning y and z): no area from above.
    const auto base = static_cast<std::uint32_t>(m.vertexCount());
    m.positions.insert(m.positions.end(), {10, 0, 0, 10, 5, 0, 10, 0, 5});
    m.triangles.insert(m.triangles.end(), {base, base + 1, base + 2});
    const auto regions = silhouette(m, 0.001);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_NEAR(regions[0].area(), 8, 1e-3);
}

TEST(Silhouette, NothingFromNoTriangles) { EXPECT_TRUE(silhouette(TriangleMesh{}, 0.01).empty()); }
