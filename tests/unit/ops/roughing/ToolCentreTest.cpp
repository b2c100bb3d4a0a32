// A ball's obstacle (ToolCentreRegions::obstacle) against the plain way of making it: every
// piece's reach (BallReach) and the grown shadow above the equator united in one Clipper call.
// Whatever the regions do to be quick (grouping the reaches, leaving out those others cover) must
// give the same set within the fit: a reach left out that shapes the boundary shows as a dent
// wider than the tolerance. On random parts, their triangles in random order (an STL soup
// keeps no order), with and without stock.
#include "ops/surface/ToolCentre.h"
#include "ops/surface/BallReach.h"
#include "ops/surface/MeshShadow.h"

#include "RoughingTestUtil.h"

#include "geom/ClipperAdapter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace camwb::ops {
namespace {

using namespace test;

// The obstacle as ToolCentre.cpp's header comment defines it, united at once.
ClipperLib::Paths plainObstacle(const sim::TriangleMesh& model, double radius, double side, double bottom, double tol,
                                double z)
{
    const surface::MeshShadow shadow(model);
    const double tip = z - bottom, ignore = tol / 4, chord = tol / 4, grow = side + tol / 2;
    ClipperLib::Paths all = surface::growPaths(shadow.above(tip + radius), radius + grow, chord);
    shadow.pieces(tip + ignore, tip + radius, [&](const std::vector<base::Vec3>& piece) {
        ClipperLib::Path path;
        for (const base::Vec2& p : surface::ballReach(piece, tip + radius, radius, grow, chord))
            path.push_back(surface::toClipper(p));
        if (path.size() >= 3)
            all.push_back(std::move(path));
    });
    return surface::unitePaths(all);
}

// The area of a minus b grown by `by` (mm^2): 0 when a lies within `by` of b.
double areaOutside(const ClipperLib::Paths& a, const ClipperLib::Paths& b, double by)
{
    double area = 0;
    for (const ClipperLib::Path& p : surface::clipPaths(a, surface::growPaths(b, by, by / 4), ClipperLib::ctDifference))
        area += ClipperLib::Area(p);
    return std::abs(area) / (geom::kClipperScale * geom::kClipperScale);
}

sim::TriangleMesh shuffled(const sim::TriangleMesh& mesh, std::mt19937& rng)
{
    std::vector<std::size_t> order(mesh.triangleCount());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    sim::TriangleMesh out;
    out.positions = mesh.positions;
    for (std::size_t t : order)
        out.triangles.insert(out.triangles.end(), mesh.triangles.begin() + long(3 * t),
                             mesh.triangles.begin() + long(3 * t + 3));
    return out;
}

TEST(ToolCentre, BallObstacleIsTheUnionOfEveryPiecesReach)
{
    std::mt19937 rng(16);
    const double tol = 0.01, radius = 3;
    int levels = 0;
    for (int trial = 0; trial < 3; ++trial) {
        const sim::TriangleMesh model = shuffled(heightMesh(randomPart(rng), 0, 0, 60, 50, 70, 0), rng);
        const double side = trial % 2 ? 0.3 : 0, bottom = trial % 2 ? 0.2 : 0;
        const surface::ToolCentreRegions centres(model, toolController("ball", 2 * radius).tool, {side, bottom, tol});
        for (int k = 0; k < 4; ++k, ++levels) {
            const double z = 19 - 3.5 * k;
            const ClipperLib::Paths plain = plainObstacle(model, radius, side, bottom, tol, z);
            const ClipperLib::Paths ours = surface::toPaths(centres.obstacle(z), tol / 8);
            ASSERT_FALSE(plain.empty());
            // The regions are fitted within half the tolerance; discretised within an eighth.
            EXPECT_LT(areaOutside(plain, ours, 0.7 * tol), 1e-6) << "trial " << trial << " z " << z;
            EXPECT_LT(areaOutside(ours, plain, 0.7 * tol), 1e-6) << "trial " << trial << " z " << z;
        }
    }
    EXPECT_EQ(levels, 12);
}

// The shadow above a height, built from the slabs' shadows united near with near, is the plain
// union of every upward triangle's part above it; a union in groups is the union at once.
TEST(MeshShadow, ShadowsAndGroupedUnionsAreTheOneUnion)
{
    std::mt19937 rng(61);
    for (int trial = 0; trial < 3; ++trial) {
        const sim::TriangleMesh model = shuffled(heightMesh(randomPart(rng), 0, 0, 60, 50, 90, 0), rng);
        const surface::MeshShadow shadow(model);
        for (double h : {19.0, 15.3, 11.1, 7.4, 2.0}) {
            const ClipperLib::Paths plain = surface::unitePaths(shadow.band(h, INFINITY));
            const ClipperLib::Paths grouped = surface::uniteNear(shadow.band(h, INFINITY));
            const ClipperLib::Paths above = shadow.above(h);
            // 10 nm: Clipper's rounding of the crossings, which depends on the order of the unions.
            EXPECT_LT(areaOutside(plain, above, 1e-5), 1e-6) << "trial " << trial << " h " << h;
            EXPECT_LT(areaOutside(above, plain, 1e-5), 1e-6) << "trial " << trial << " h " << h;
            EXPECT_LT(areaOutside(plain, grouped, 1e-5), 1e-6) << "trial " << trial << " h " << h;
            EXPECT_LT(areaOutside(grouped, plain, 1e-5), 1e-6) << "trial " << trial << " h " << h;
        }
    }
}

}  // namespace
}  // namespace camwb::ops
