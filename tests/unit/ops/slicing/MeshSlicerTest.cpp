// The mesh slicer on analytic meshes whose sections are known: a sphere (as an indexed mesh and as
// a triangle soup), a drafted frustum with flat floor and top, a torus (a loop with a hole); levels
// through vertices and along horizontal faces, outside the mesh, in any order; open and broken
// meshes; the flat levels of a stepped mesh.
#include "SliceTestUtil.h"

#include "ops/surface/MeshSlicer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::ops::surface {
namespace {

using test::Loops;
constexpr double kPi = std::numbers::pi;

// The largest and smallest distance of the loops' points from the Z axis through `centre`.
std::pair<double, double> radiusRange(const Loops& loops, base::Vec2 centre = {})
{
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& loop : loops)
        for (const base::Vec2 p : loop) {
            lo = std::min(lo, distance(p, centre));
            hi = std::max(hi, distance(p, centre));
        }
    return {lo, hi};
}

TEST(MeshSlicer, SphereSectionsAreInscribedCirclesOfTheExactRadius)
{
    const double radius = 10;
    const int segments = 96;
    for (const bool soup : {false, true}) {
        // A soup (every triangle with its own vertices, as an STL) slices once welded.
        const sim::TriangleMesh mesh = test::sphereMesh({1, 2, 3}, radius, 48, segments, soup);
        if (soup) {
            const std::vector<MeshSection> unwelded = sliceMesh(mesh, {3.5});
            EXPECT_TRUE(unwelded[0].loops.empty());
            EXPECT_EQ(unwelded[0].openChains, 2u * segments) << "every crossing a chain of its own";
        }
        std::vector<double> levels;
        for (double z = -9.5; z < 9.6; z += 0.73)
            levels.push_back(3 + z);
        const std::vector<MeshSection> sections = sliceMesh(soup ? sim::weldVertices(mesh) : mesh, levels);
        ASSERT_EQ(sections.size(), levels.size());
        for (const MeshSection& s : sections) {
            ASSERT_EQ(s.loops.size(), 1u) << "z " << s.z << (soup ? " (soup)" : "");
            const double r = std::sqrt(radius * radius - (s.z - 3) * (s.z - 3));
            // The mesh lies inside the sphere, its facets at most the sagitta of a band in.
            const double sag = radius * (1 - std::cos(kPi / 48)) + radius * (1 - std::cos(kPi / segments));
            const auto [lo, hi] = radiusRange(s.loops, {1, 2});
            EXPECT_LE(hi, r + 1e-5) << "z " << s.z;
            EXPECT_GE(lo, r - sag / std::max(r / radius, 0.3) - 1e-5) << "z " << s.z;
            EXPECT_GT(test::signedArea(s.loops[0]), 0) << "outer loops run counter-clockwise";
            EXPECT_NEAR(test::signedArea(s.loops), kPi * r * r, kPi * r * r * 0.01) << "z " << s.z;
        }
    }
}

TEST(MeshSlicer, LevelsInAnyOrderAndRepeatedGiveTheSameSections)
{
    const sim::TriangleMesh mesh = test::sphereMesh({}, 5, 20, 40);
    const std::vector<MeshSection> up = sliceMesh(mesh, {-2, 0.5, 3});
    const std::vector<MeshSection> mixed = sliceMesh(mesh, {3, -2, 0.5, 3});
    ASSERT_EQ(mixed.size(), 4u);
    EXPECT_EQ(mixed[0].z, 3);
    EXPECT_EQ(mixed[0].loops, up[2].loops);
    EXPECT_EQ(mixed[1].loops, up[0].loops);
    EXPECT_EQ(mixed[2].loops, up[1].loops);
    EXPECT_EQ(mixed[3].loops, up[2].loops);
}

TEST(MeshSlicer, DraftedFrustumRadiusFollowsTheDraft)
{
    // Radius 20 at Z 0 to 15 at Z 10: a 26.6 degree draft.
    const sim::TriangleMesh mesh = test::frustumMesh(20, 0, 15, 10, 256, 7);
    for (double z = 0.25; z < 10; z += 0.5) {
        const std::vector<MeshSection> s = sliceMesh(mesh, {z});
        ASSERT_EQ(s[0].loops.size(), 1u) << "z " << z;
        const double r = 20 - 0.5 * z;
        const auto [lo, hi] = radiusRange(s[0].loops);
        EXPECT_NEAR(hi, r, 1e-5) << "z " << z;  // the ring vertices' meridians lie on the cone
        EXPECT_GE(lo, r * std::cos(kPi / 256) - 1e-5) << "z " << z;
    }
}

TEST(MeshSlicer, LevelOnAHorizontalFaceIsTakenJustAboveIt)
{
    const sim::TriangleMesh mesh = test::frustumMesh(20, 0, 15, 10, 64, 4);
    const std::vector<MeshSection> s = sliceMesh(mesh, {0, 10, 2.5, 5});
    // On the floor (Z 0): the section just above it, the floor's outline at radius 20.
    ASSERT_EQ(s[0].loops.size(), 1u);
    EXPECT_NEAR(radiusRange(s[0].loops).second, 20, 1e-5);
    EXPECT_EQ(s[0].loops[0].size(), 64u) << "each ring vertex once, no repeated points";
    // On the top (Z 10): nothing above it.
    EXPECT_TRUE(s[1].loops.empty());
    // Through the wall's ring vertices (bands of 2.5 mm): one loop through exactly those vertices.
    for (int i : {2, 3}) {
        ASSERT_EQ(s[i].loops.size(), 1u) << "z " << s[i].z;
        EXPECT_EQ(s[i].loops[0].size(), 64u) << "z " << s[i].z;
        const auto [lo, hi] = radiusRange(s[i].loops);
        EXPECT_NEAR(lo, 20 - 0.5 * s[i].z, 1e-5);
        EXPECT_NEAR(hi, 20 - 0.5 * s[i].z, 1e-5);
    }
}

TEST(MeshSlicer, LevelThroughASpheresRingVertices)
{
    const sim::TriangleMesh mesh = test::sphereMesh({}, 10, 16, 32);
    // The exact float Z of a ring (vertex 1 is the first vertex of the lowest ring).
    const double ringZ = mesh.positions[3 * 1 + 2];
    const double poleZ = mesh.positions[2];
    const std::vector<MeshSection> s = sliceMesh(mesh, {ringZ, poleZ, -poleZ});
    ASSERT_EQ(s[0].loops.size(), 1u);
    EXPECT_EQ(s[0].loops[0].size(), 32u);
    EXPECT_GT(test::signedArea(s[0].loops[0]), 0);
    // The bottom pole: just above it a point's worth of section, dropped; above the top: nothing.
    EXPECT_TRUE(s[1].loops.empty());
    EXPECT_TRUE(s[2].loops.empty());
}

TEST(MeshSlicer, TorusGivesAnOuterLoopAndAHole)
{
    const sim::TriangleMesh mesh = test::torusMesh(20, 5, 128, 64);
    for (const double z : {-4.3, -1.1, 0.7, 3.9}) {
        const std::vector<MeshSection> s = sliceMesh(mesh, {z});
        ASSERT_EQ(s[0].loops.size(), 2u) << "z " << z;
        const double half = std::sqrt(25 - z * z);
        double outer = 0, hole = 0;
        for (const auto& loop : s[0].loops)
            (test::signedArea(loop) > 0 ? outer : hole) += test::signedArea(loop);
        EXPECT_NEAR(outer, kPi * (20 + half) * (20 + half), 0.01 * outer) << "z " << z;
        EXPECT_NEAR(hole, -kPi * (20 - half) * (20 - half), 0.01 * -hole) << "hole runs clockwise, z " << z;
        const std::vector<geom::Region> regions = sectionRegions(s[0], 0.01);
        ASSERT_EQ(regions.size(), 1u);
        EXPECT_EQ(regions[0].holes.size(), 1u);
        EXPECT_NEAR(regions[0].area(), test::signedArea(s[0].loops), 1e-6 * outer);
    }
}

TEST(MeshSlicer, LevelsOutsideTheMeshAndNonFiniteLevelsAreEmpty)
{
    const sim::TriangleMesh mesh = test::sphereMesh({}, 5, 12, 24);
    const std::vector<MeshSection> s = sliceMesh(mesh, {-6, 6, std::nan(""), 1e300, -1e300});
    ASSERT_EQ(s.size(), 5u);
    for (const MeshSection& section : s)
        EXPECT_TRUE(section.loops.empty()) << section.z;
    EXPECT_TRUE(sliceMesh(sim::TriangleMesh{}, {0, 1})[1].loops.empty());
    EXPECT_TRUE(sliceMesh(mesh, {}).empty());
}

TEST(MeshSlicer, OpenMeshDropsOnlyTheLoopsThroughItsGap)
{
    const sim::TriangleMesh closed = test::sphereMesh({}, 10, 20, 40);
    // Leave out one band's triangles in the upper half (80 triangles per band, band 14 of 20).
    const sim::TriangleMesh open = test::withoutTriangles(closed, 40 + 80 * 13, 3);
    const double bandLow = -10 * std::cos(kPi * 14 / 20), bandHigh = -10 * std::cos(kPi * 15 / 20);
    const std::vector<MeshSection> s = sliceMesh(open, {-5, (bandLow + bandHigh) / 2, 9});
    EXPECT_EQ(s[0].loops.size(), 1u);
    EXPECT_TRUE(s[1].loops.empty()) << "the loop through the gap does not close: dropped";
    EXPECT_GE(s[1].openChains, 1u) << "and counted (a broken loop may count as two pieces)";
    EXPECT_EQ(s[2].loops.size(), 1u);
    EXPECT_EQ(s[0].openChains + s[2].openChains, 0u);
    EXPECT_EQ(s[0].loops, sliceMesh(closed, {-5})[0].loops);
}

TEST(MeshSlicer, BrokenTrianglesAreIgnored)
{
    sim::TriangleMesh mesh = test::sphereMesh({}, 10, 20, 40);
    const std::vector<MeshSection> before = sliceMesh(mesh, {1.5});
    const auto n = static_cast<std::uint32_t>(mesh.vertexCount());
    // An index out of range, a triangle with a repeated vertex, a non-finite vertex.
    mesh.triangles.insert(mesh.triangles.end(), {0, 1, n + 5, 3, 3, 4});
    mesh.positions.insert(mesh.positions.end(), {0, 0, std::numeric_limits<float>::quiet_NaN()});
    mesh.triangles.insert(mesh.triangles.end(), {1, 2, n});
    const std::vector<MeshSection> after = sliceMesh(mesh, {1.5, -3});
    ASSERT_EQ(after[0].loops.size(), 1u);
    EXPECT_NEAR(test::signedArea(after[0].loops), test::signedArea(before[0].loops), 1e-9);
    // A fin: a triangle hanging off an edge that the level crosses (three triangles at one edge,
    // band 10 spans Z 0 to 1.56) down to the bottom pole. The section stays finite, whatever it is.
    mesh.triangles.insert(mesh.triangles.end(), {mesh.triangles[3 * 760 + 1], mesh.triangles[3 * 760 + 2], 0});
    const std::vector<MeshSection> withFin = sliceMesh(mesh, {1.5});
    for (const auto& loop : withFin[0].loops)
        for (const base::Vec2 p : loop)
            EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
}

TEST(MeshSlicer, FlatLevelsAreTheUpwardFloors)
{
    // A stepped stack: frustums with flat tops at 10 and 25, the lower one wider.
    sim::TriangleMesh mesh = test::frustumMesh(30, 0, 28, 10, 64, 2);
    const sim::TriangleMesh upper = test::frustumMesh(12, 10, 10, 25, 64, 2);
    const auto offset = static_cast<std::uint32_t>(mesh.vertexCount());
    mesh.positions.insert(mesh.positions.end(), upper.positions.begin(), upper.positions.end());
    for (const std::uint32_t v : upper.triangles)
        mesh.triangles.push_back(v + offset);
    EXPECT_EQ(flatLevels(mesh), (std::vector<double>{10, 25}));
    // Tiny floors are left out; a sphere (no flat area) has none; the drafted wall is no floor.
    EXPECT_EQ(flatLevels(mesh, 0.5, 400), (std::vector<double>{10}));
    EXPECT_TRUE(flatLevels(test::sphereMesh({}, 10, 40, 80)).empty());
    EXPECT_EQ(flatLevels(mesh, 80), (std::vector<double>{10, 25})) << "a steep wall spans more than the tolerance";
    // A sliver tilted 2 degrees: within the Z tolerance (87 nm high) but not horizontal.
    sim::TriangleMesh sliver;
    sliver.positions = {0, 0, 5, 10, 0, 5, 0, 0.0025f, float(5 + 0.0025 * std::tan(2 * kPi / 180))};
    sliver.triangles = {0, 1, 2};
    EXPECT_TRUE(flatLevels(sliver).empty());
    ASSERT_EQ(flatLevels(sliver, 3).size(), 1u);
    EXPECT_NEAR(flatLevels(sliver, 3)[0], 5, 1e-4);
}

}  // namespace
}  // namespace camwb::ops::surface
