// The waterline's contours from the drop-cutter (ops/surface/DropContours.h), judged against exact
// answers: round a sphere a ball's contour is the sphere grown by the ball, each point on the clear
// side within a tenth of the tolerance (and the mesh's facets); material lies on the loops' left
// (counter-clockwise round a boss, clockwise round a pit); a saddle cell is joined or split as the
// drop at its centre says; the grid step for each cutter.
#include "ops/surface/DropContours.h"
#include "TestMeshes.h"
#include "ops/surface/DropCutter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace camwb::ops::surface {
namespace {

using base::Vec2;
using test::tool;

double signedArea(const std::vector<Vec2>& loop)
{
    double a = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        a += loop[i].cross(loop[(i + 1) % loop.size()]);
    return a / 2;
}

bool within(const std::vector<Vec2>& loop, Vec2 lo, Vec2 hi)
{
    for (const Vec2& p : loop)
        if (p.x < lo.x || p.y < lo.y || p.x > hi.x || p.y > hi.y)
            return false;
    return true;
}

TEST(DropContours, RoundASphereTheLoopIsTheGrownSphereOnTheClearSide)
{
    // A sphere R15 of 400 x 200 facets (sagitta 0.0005 mm), a D6 ball: the ball's centre touches at
    // distance 18 from the sphere's centre.
    const sim::TriangleMesh sphere = test::sphereMesh(15, 400);
    const DropCutter cutter(sphere, tool("ball", 6));
    const double tol = 0.01, step = DropContours::step(tool("ball", 6), 0, tol);
    const DropContours contours(cutter, {-25, -25}, {25, 25}, step, tol / 4, tol, {}, 0, 1);
    ASSERT_TRUE(contours.complete());
    for (const double z : {-1.0, 4.0, 9.0, 13.0}) {
        const std::vector<std::vector<Vec2>> loops = contours.loopsAt(z);
        ASSERT_EQ(loops.size(), 1u) << "level " << z;
        EXPECT_GT(signedArea(loops[0]), 0) << "material on the left: counter-clockwise round the boss";
        const double exact = std::sqrt(18.0 * 18.0 - (z + 3) * (z + 3));
        for (const Vec2& p : loops[0]) {
            // The ball's centre from the sphere's: at most a tenth of the tolerance sideways off it;
            // in by the ignored quarter tolerance (the tool may stand that much lower) and the
            // facets (within 0.001 of the sphere).
            const double centre = std::hypot(p.length(), z + 3);
            EXPECT_GE(centre, 18 - tol / 4 - 0.001) << "into the sphere at level " << z;
            EXPECT_LE(centre, 18 + tol / 10 + 1e-6) << "off the sphere at level " << z;
            EXPECT_FALSE(contours.touches(p, z));
        }
        // Points a hair inside touch, a hair outside do not.
        EXPECT_TRUE(contours.touches({exact - 0.01, 0}, z));
        EXPECT_FALSE(contours.touches({exact + 0.01, 0}, z));
    }
    // Above the sphere nothing touches.
    EXPECT_TRUE(contours.loopsAt(15.1).empty());
}

TEST(DropContours, RoundAPitTheLoopIsClockwiseAndTheOuterOneClosesOutsideTheArea)
{
    // A plate at Z 0 with a round pit R10 down to Z -5 (walls over one cell of the grid mesh).
    const sim::TriangleMesh mesh = test::gridMesh(
        [](double x, double y) { return std::hypot(x - 20, y - 20) < 10 ? -5.0 : 0.0; }, 0, 40, 0, 40, 200);
    const DropCutter cutter(mesh, tool("flat", 4));
    const double tol = 0.01;
    const Vec2 lo{5, 5}, hi{35, 35};
    const DropContours contours(cutter, lo, hi, DropContours::step(tool("flat", 4), 0, tol), tol / 4, tol, {}, 0, 1);
    const std::vector<std::vector<Vec2>> loops = contours.loopsAt(-2);
    ASSERT_EQ(loops.size(), 2u);
    int pits = 0, rings = 0;
    for (const std::vector<Vec2>& loop : loops) {
        if (within(loop, lo, hi)) {
            ++pits;
            EXPECT_LT(signedArea(loop), 0) << "material on the left: clockwise round the pit";
            for (const Vec2& p : loop)
                EXPECT_NEAR(std::hypot(p.x - 20, p.y - 20), 10 - 2, 0.2 + tol);  // the wall spans a cell
        } else {
            ++rings;
            EXPECT_GT(signedArea(loop), 0);
        }
    }
    EXPECT_EQ(pits, 1);
    EXPECT_EQ(rings, 1);
}

// Two needles, each a flat D2 tool's disc of reach round it, set so that in one cell of the grid
// two facing corners touch (one needle each) and the other two do not: a saddle. Whether the two
// discs join there is the drop at the cell's centre: one loop when they overlap across it, two when
// they pass each other.
TEST(DropContours, ASaddleCellJoinsOrSplitsAsItsCentreSays)
{
    const toolpath::Tool flat = tool("flat", 2);
    const double tol = 0.01, s = DropContours::step(flat, 0, tol);
    const Vec2 lo{0, 0}, hi{4, 4};
    // Grid node (i, j) stands at lo - 2 s + (i, j) s; the cell from node (10, 10).
    const Vec2 centre = lo + Vec2{8.5 * s, 8.5 * s};
    const auto needles = [](Vec2 a, Vec2 b) {
        sim::TriangleMesh mesh;
        for (const Vec2& c : {a, b}) {
            const auto base = std::uint32_t(mesh.vertexCount());
            const double w = 0.001;
            for (const Vec2& corner : {Vec2{-w, -w}, Vec2{w, -w}, Vec2{w, w}, Vec2{-w, w}})
                mesh.positions.insert(mesh.positions.end(), {float(c.x + corner.x), float(c.y + corner.y), 0.f});
            mesh.positions.insert(mesh.positions.end(), {float(c.x), float(c.y), 10.f});
            for (std::uint32_t k = 0; k < 4; ++k)
                mesh.triangles.insert(mesh.triangles.end(), {base + k, base + (k + 1) % 4, base + 4});
        }
        return mesh;
    };
    // Corner (10, 10) is within 1 of the lower needle and (11, 11) of the upper, (11, 10) and (10, 11)
    // of neither, for k in (0.704, 0.778); the centre within 1 of both for k < 1 / sqrt(2).
    for (const double k : {0.705, 0.74}) {
        const sim::TriangleMesh mesh = needles(centre - Vec2{k, k}, centre + Vec2{k, k});
        const DropCutter cutter(mesh, flat);
        const DropContours contours(cutter, lo, hi, s, tol / 4, tol, {}, 0, 1);
        const bool joined = k < 1 / std::sqrt(2.0);
        EXPECT_EQ(contours.touches(centre, 5), joined);
        EXPECT_EQ(contours.loopsAt(5).size(), joined ? 1u : 2u) << "k " << k;
    }
}

TEST(DropContours, GridStepFromTheCuttersSmallestCurvature)
{
    EXPECT_NEAR(DropContours::step(tool("ball", 6), 0, 0.01), std::sqrt(2 * 3 * 0.01), 1e-12);
    EXPECT_NEAR(DropContours::step(tool("ball", 6), 0.5, 0.01), std::sqrt(2 * 3.5 * 0.01), 1e-12);
    EXPECT_NEAR(DropContours::step(tool("bull", 10, 1), 0, 0.01), std::sqrt(2 * 1 * 0.01), 1e-12);
    EXPECT_NEAR(DropContours::step(tool("flat", 8), 0, 0.02), std::sqrt(2 * 4 * 0.02), 1e-12);
    EXPECT_EQ(DropContours::step(tool("drill", 6, 0, 118), 0, 0.01), 0);
}

}  // namespace
}  // namespace camwb::ops::surface
