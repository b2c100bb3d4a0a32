// The drop-cutter against analytic answers (a ball on a sphere, a flat on a tilted plane, a
// bull-nose and a cone at a step's edge, the stock to leave) and against an independent brute
// force: the triangles sampled densely and the tool's lower surface from sim::ToolShape alone.
#include "ops/surface/DropCutter.h"
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <random>

namespace camwb::ops {
namespace {

using surface::DropCutter;
using test::tool;

TEST(DropCutter, BallOnSphere)
{
    const sim::TriangleMesh sphere = test::sphereMesh(20, 256);
    for (double stock : {0.0, 0.5}) {
        const DropCutter cutter(sphere, tool("ball", 6), stock);
        for (double rho : {0.0, 3.0, 10.0, 17.0, 21.0}) {
            // The ball's centre at (20 + 3 + stock) from the sphere's, the tip 3 below it; the
            // faceted sphere lies inside the true one (by at most 20 (1 - cos(pi / 256)) = 1.5 um).
            const double expected = std::sqrt(std::pow(23 + stock, 2) - rho * rho) - 3;
            EXPECT_NEAR(cutter.dropZ({rho * 0.6, rho * 0.8}), expected, 0.004) << rho << " stock " << stock;
        }
        EXPECT_EQ(cutter.dropZ({30, 0}, -100), -100);  // beyond the sphere: the floor
    }
}

TEST(DropCutter, FlatOnTiltedPlane)
{
    const double g = 0.3;
    const sim::TriangleMesh plane =
        test::gridMesh([&](double x, double y) { return g * x + 0.1 * y; }, -20, 20, -20, 20, 7);
    const DropCutter cutter(plane, tool("flat", 8));
    // The rim touches uphill: the plane's height at 4 mm along its steepest rise.
    const double rise = std::hypot(g, 0.1);
    for (base::Vec2 p : {base::Vec2{0, 0}, base::Vec2{3.3, -5.1}, base::Vec2{-7, 9}})
        EXPECT_NEAR(cutter.dropZ(p), g * p.x + 0.1 * p.y + 4 * rise, 1e-5);
}

TEST(DropCutter, BullNoseAndConeAtAnEdge)
{
    // A plateau z = 0 for x <= 0, falling at 10 in 1 beyond its edge x = 0 (steeper than any
    // profile's slope where these tools reach it, so the edge gives the contact).
    const sim::TriangleMesh edge = test::gridMesh(
        [](double x, double) { return x <= 1e-9 ? 0.0 : -10.0 * std::min(x, 1.0); }, -20, 20, -10, 10, 40);
    const DropCutter bull(edge, tool("bull", 10, 2)), cone(edge, tool("chamfer", 10, 0, 90));
    const DropCutter flatStock(edge, tool("flat", 10), 0.5);
    for (double e : {0.5, 2.0, 4.0}) {
        EXPECT_NEAR(bull.dropZ({e, 0}), e <= 3 ? 0 : -(2 - std::sqrt(4 - (e - 3) * (e - 3))), 1e-6) << e;
        EXPECT_NEAR(cone.dropZ({e, 0}), -e, 1e-6) << e;  // 90 degrees: the point rises 1 mm a mm
    }
    // A flat tool grown by 0.5: the bottom 0.5 above the plateau, the grown rim round the edge.
    EXPECT_NEAR(flatStock.dropZ({-3, 0}), 0.5, 1e-9);
    EXPECT_NEAR(flatStock.dropZ({5.3, 0}), 0.5 - 0.5 + std::sqrt(0.25 - 0.09), 1e-6);
}

// The highest the tool may stand at c: the brute force of the test, from dense samples of every
// triangle (and its edges) and the profile from sim::ToolShape. Returns the lowest clearance
// (tool surface minus sample height) over the samples under the tool at tip height z.
double clearance(const sim::TriangleMesh& mesh, const test::GrownProfile& h, base::Vec2 c, double z, int n)
{
    double lowest = std::numeric_limits<double>::infinity();
    const double R = h.shape.radiusMm() + h.stock;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const base::Vec3 a = mesh.vertex(mesh.triangles[3 * t]), b = mesh.vertex(mesh.triangles[3 * t + 1]),
                         d = mesh.vertex(mesh.triangles[3 * t + 2]);
        if (std::min({a.x, b.x, d.x}) > c.x + R || std::max({a.x, b.x, d.x}) < c.x - R ||
            std::min({a.y, b.y, d.y}) > c.y + R || std::max({a.y, b.y, d.y}) < c.y - R)
            continue;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n - i; ++j) {
                const double u = double(i) / n, v = double(j) / n;
                const base::Vec3 p = a + (b - a) * u + (d - a) * v;
                const double dist = std::hypot(p.x - c.x, p.y - c.y);
                if (dist <= R)
                    lowest = std::min(lowest, z + h(dist) - p.z);
            }
    }
    return lowest;
}

TEST(DropCutter, AgreesWithBruteForce)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const test::RandomPart part = test::randomPart(rng);
    const sim::TriangleMesh bumps = test::gridMesh(part, 0, 40, 0, 40, 20);
    // A triangle soup: random triangles at random tilts over each other.
    sim::TriangleMesh soup;
    for (int t = 0; t < 30; ++t) {
        const double cx = 10 * u(rng), cy = 10 * u(rng), cz = 3 * u(rng);
        for (int v = 0; v < 3; ++v)
            soup.positions.insert(soup.positions.end(),
                                  {float(cx + 6 * u(rng) - 3), float(cy + 6 * u(rng) - 3), float(cz + 4 * u(rng) - 2)});
        soup.triangles.insert(soup.triangles.end(),
                              {std::uint32_t(3 * t), std::uint32_t(3 * t + 1), std::uint32_t(3 * t + 2)});
    }
    const toolpath::Tool tools[] = {tool("flat", 6), tool("ball", 6), tool("bull", 8, 1.5), tool("chamfer", 6, 0, 90),
                                    tool("drill", 5, 0, 118)};
    int touched = 0, queries = 0;
    for (const sim::TriangleMesh* mesh : std::initializer_list<const sim::TriangleMesh*>{&bumps, &soup})
        for (const toolpath::Tool& t : tools)
            for (double stock : {0.0, 0.4}) {
                const sim::ToolShape shape(t);
                const test::GrownProfile h{shape, stock};
                const DropCutter cutter(*mesh, t, stock);
                const double span = mesh == &soup ? 10 : 40;
                for (int q = 0; q < 4; ++q) {
                    const base::Vec2 c{span * u(rng), span * u(rng)};
                    const double z = cutter.dropZ(c, -1e9);
                    if (z == -1e9)
                        continue;
                    ++queries;
                    const double low = clearance(*mesh, h, c, z, 40);
                    EXPECT_GE(low, -1e-6) << t.kind << " stock " << stock << " at " << c.x << ", " << c.y;
                    // Touching: a sample within the sampling's reach of the tool.
                    EXPECT_LE(low, 0.02) << t.kind << " stock " << stock << " at " << c.x << ", " << c.y;
                    touched += low <= 0.02;
                }
            }
    EXPECT_GT(queries, 50);
}

TEST(DropCutter, BatchEqualsOneByOne)
{
    std::mt19937 rng(3);
    const sim::TriangleMesh mesh = test::gridMesh(test::randomPart(rng), 0, 40, 0, 40, 40);
    const DropCutter cutter(mesh, tool("bull", 6, 1), 0.2);
    std::vector<base::Vec2> points;
    for (int i = 0; i < 2000; ++i)
        points.push_back({(i % 50) * 0.8, (i / 50) * 1.0});
    const std::vector<double> batch = cutter.dropZ(points, -50, 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        ASSERT_EQ(batch[i], cutter.dropZ(points[i], -50));
}

}  // namespace
}  // namespace camwb::ops
