// Welding a mesh whose faces were meshed apart (as OCCT does): shared points become one vertex,
// distinct points stay apart, slivers whose corners merge are dropped.
#include "sim/TriangleMesh.h"

#include <gtest/gtest.h>

using camwb::sim::TriangleMesh;
using camwb::sim::weldVertices;

namespace {

// Two triangles of a unit square, each with its own three vertices; the second's copies of the
// shared edge off by `jitter`.
TriangleMesh splitSquare(float jitter)
{
    TriangleMesh m;
    m.positions = {0, 0, 0,          1, 0,          0, 1, 1, 0,   // first
                   0, 0, 0 + jitter, 1, 1 + jitter, 0, 0, 1, 0};  // second: shares (0,0) and (1,1)
    m.triangles = {0, 1, 2, 3, 4, 5};
    return m;
}

}  // namespace

TEST(WeldVertices, JoinsCopiesWithinTheTolerance)
{
    const TriangleMesh welded = weldVertices(splitSquare(2e-6f), 1e-5);
    EXPECT_EQ(welded.vertexCount(), 4u);
    ASSERT_EQ(welded.triangleCount(), 2u);
    EXPECT_EQ(welded.triangles[3], welded.triangles[0]);
    EXPECT_EQ(welded.triangles[4], welded.triangles[2]);
    EXPECT_NEAR(welded.volumeMm3(), 0.0, 1e-9);
}

TEST(WeldVertices, KeepsPointsFartherApartThanTheTolerance)
{
    EXPECT_EQ(weldVertices(splitSquare(1e-3f), 1e-5).vertexCount(), 6u);
}

TEST(WeldVertices, JoinsCopiesOnEitherSideOfAGridCell)
{
    // 0.5e-5 and 0.5e-5 + 1e-7 round to different cells of a 1e-5 grid; they must still join.
    TriangleMesh m;
    m.positions = {5e-6f, 0, 0, 1, 0, 0, 0, 1, 0, 5.1e-6f, 0, 0, 0, 1, 0, -1, 0, 0};
    m.triangles = {0, 1, 2, 3, 4, 5};
    EXPECT_EQ(weldVertices(m, 1e-5).vertexCount(), 4u);
}

TEST(WeldVertices, DropsTrianglesWhoseCornersMerge)
{
    TriangleMesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1e-7f, 0, 0};
    m.triangles = {0, 1, 2, 0, 3, 2};
    const TriangleMesh welded = weldVertices(m, 1e-5);
    EXPECT_EQ(welded.triangleCount(), 1u);
}
