// Parallel finishing: on random drafted pockets with fillets and bumps, no point of the tool at
// any CL point or along any feed move between them reaches into the model by more than the
// tolerance (the tool's shape against a dense point cloud of the model), the lines cover the area;
// on a dome, the slope limit keeps the cut off the steep part and on the shallow part; the
// parameters' errors.
#include "ops/ParallelOp.h"
#include "PathCheck.h"
#include "geom/Region.h"
#include "sim/HeightField.h"
#include "sim/Moves.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <numbers>
#include <random>

namespace camwb::ops {
namespace {

using test::tool;

ToolController controller(const toolpath::Tool& t)
{
    ToolController tc;
    tc.tool = t;
    tc.spindleRpm = 10000;
    tc.cuttingFeedMmPerMin = 1500;
    tc.plungeFeedMmPerMin = 500;
    return tc;
}

SurfaceInput inputFor(const sim::TriangleMesh& mesh, double x0, double x1, double y0, double y1)
{
    SurfaceInput in;
    in.model = &mesh;
    in.stock.add({x0, y0, -20});
    in.stock.add({x1, y1, 10});
    return in;
}

ParallelParams paramsFor(double stepover)
{
    ParallelParams p;
    p.heights = {30, 15, 10, -20};
    p.stepoverMm = stepover;
    return p;
}

// The deepest the tool reaches into the cloud at the CL points and every 0.2 mm along the feeds.
double worstPenetration(const toolpath::Toolpath& path, const test::PointCloud& cloud, const test::ProfileTable& h)
{
    double worst = -1e9;
    for (const test::Segment& s : test::feedMoves(path)) {
        const int n = std::max(1, int(std::ceil(distance(s.a, s.b) / 0.2)));
        for (int i = 0; i <= n; ++i)
            worst = std::max(worst, cloud.penetration(s.a + (s.b - s.a) * (double(i) / n), h, h.radius));
    }
    return worst;
}

TEST(ParallelOp, NoGougeAndCoverageOnRandomParts)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const toolpath::Tool tools[] = {tool("ball", 6), tool("bull", 6, 1), tool("flat", 6)};
    for (int trial = 0; trial < 6; ++trial) {
        const test::RandomPart part = test::randomPart(rng);
        const sim::TriangleMesh mesh = test::gridMesh(part, 0, 40, 0, 40, 60);
        const test::PointCloud cloud(mesh, 0.12, 1.0);
        const toolpath::Tool& t = tools[trial % 3];
        ParallelParams p = paramsFor(1.5);
        p.angleDeg = 180 * u(rng);
        p.zigZag = trial % 2 == 0;
        p.stockMm = trial >= 3 ? 0.3 : 0;
        p.toleranceMm = 0.01;
        const auto result = computeParallel(inputFor(mesh, 0, 40, 0, 40), p, controller(t), 0);
        ASSERT_TRUE(result) << result.error().message;
        const toolpath::Toolpath& path = result.value().toolpath;
        const sim::ToolShape shape(t);
        const test::ProfileTable h(test::GrownProfile{shape, p.stockMm});
        EXPECT_LE(worstPenetration(path, cloud, h), p.toleranceMm) << "trial " << trial << " " << t.kind;
        // Coverage (no slope limit): every point of the area lies within half a line spacing
        // (at most half the stepover) of a feed move; near the area's edges, where the nearest
        // line may end before it (the edges are oblique to the lines), within a line spacing.
        const std::vector<test::Segment> feeds = test::feedMoves(path);
        double farthest = 0, fx = 0, fy = 0;
        for (double x = 1; x < 40; x += 1.3)
            for (double y = 1; y < 40; y += 1.3) {
                double nearest = 1e9;
                for (const test::Segment& s : feeds)
                    nearest = std::min(nearest, test::distanceToSegmentXY({x, y}, s));
                const double edge = std::min({x, y, 40 - x, 40 - y});
                if (edge < p.stepoverMm)
                    EXPECT_LE(nearest, p.stepoverMm + 1e-6) << x << ", " << y;
                else if (nearest > farthest)
                    farthest = nearest, fx = x, fy = y;
            }
        EXPECT_LE(farthest, p.stepoverMm / 2 + 1e-6) << "trial " << trial << " at " << fx << ", " << fy;
    }
}

// The simulator's z-map as a second, independent oracle: the whole toolpath cut into a block
// at 0.1 mm and compared with the model (its gouge and the material left over the model).
TEST(ParallelOp, SimulatedStockNeitherGougesNorLeavesMoreThanTheScallop)
{
    std::mt19937 rng(5);
    const test::RandomPart part = test::randomPart(rng);
    const sim::TriangleMesh mesh = test::gridMesh(part, 0, 40, 0, 40, 60);
    for (const char* kind : {"ball", "flat"}) {
        ParallelParams p = paramsFor(0.5);
        p.angleDeg = 30;
        const toolpath::Tool t = tool(kind, 6);
        const auto result = computeParallel(inputFor(mesh, 0, 40, 0, 40), p, controller(t), 0);
        ASSERT_TRUE(result) << result.error().message;
        base::Box3 block;
        block.add({0, 0, -20});
        block.add({40, 40, 10});
        sim::HeightField stock(block, 0.1);
        stock.setDesign(mesh, p.toleranceMm);
        const sim::ToolShape shape(t);
        base::Vec3 at{};
        std::size_t index = 0;
        for (const toolpath::Record& r : result.value().toolpath.records()) {
            const bool rapid = std::holds_alternative<toolpath::Rapid>(r);
            if (!rapid && !std::holds_alternative<toolpath::Linear>(r))
                continue;
            const base::Vec3 to = rapid ? std::get<toolpath::Rapid>(r).to : std::get<toolpath::Linear>(r).to;
            if (index > 0) {
                sim::Move m;
                m.from = at, m.to = to, m.kind = rapid ? sim::MoveKind::Rapid : sim::MoveKind::Feed;
                stock.cut(m, index, shape);
            }
            at = to, ++index;
        }
        const sim::Deviation dev = stock.compare();
        EXPECT_LE(dev.maxGougeMm, p.toleranceMm) << kind << " at " << dev.gougeAt.x << ", " << dev.gougeAt.y;
        // Left over the model: the scallops between lines 0.5 apart, more in the pocket's corners
        // the tool cannot reach
        // (0.7 mm measured: the pocket's fillet is tighter than the tool; lines missing leave mm.)
        EXPECT_LT(dev.maxLeftoverMm, 2) << kind;
    }
}

TEST(ParallelOp, SlopeLimitOnADome)
{
    // A hemisphere of radius 20 on a plane; a 6 mm ball's CL surface over it is the sphere of
    // radius 23, as steep at distance rho as asin(rho / 23).
    const sim::TriangleMesh mesh = test::gridMesh(
        [](double x, double y) { return std::sqrt(std::max(0.0, 400 - x * x - y * y)); }, -30, 30, -30, 30, 120);
    ParallelParams p = paramsFor(1.0);
    p.heights = {40, 25, 20, -20};
    p.maxSlopeDeg = 40;
    const auto result = computeParallel(inputFor(mesh, -30, 30, -30, 30), p, controller(tool("ball", 6)), 0);
    ASSERT_TRUE(result) << result.error().message;
    const double deg = 3.14159265358979323846 / 180;
    const std::vector<test::Segment> feeds = test::feedMoves(result.value().toolpath);
    // No cut where steeper than the limit + 3 degrees on the sphere's part (the ball rests on the
    // plane beyond rho = sqrt(23^2 - 3^2) = 22.8), but for one sample (0.25 mm) up from the plane:
    // a sample with a shallow side cuts, so the floor is finished right up to the foot.
    for (const test::Segment& s : feeds)
        for (double f = 0; f <= 1; f += 0.05) {
            const base::Vec3 q = s.a + (s.b - s.a) * f;
            const double rho = std::hypot(q.x, q.y);
            EXPECT_TRUE(rho <= 23 * std::sin(43 * deg) || rho >= 22.8 - 0.3) << q.x << ", " << q.y;
        }
    // Cut where shallower than the limit - 3 degrees, on the dome and on the plane around it.
    int checked = 0;
    for (double x = -28; x <= 28; x += 0.7)
        for (double y = -28; y <= 28; y += 0.7) {
            const double rho = std::hypot(x, y);
            if (rho > 23 * std::sin(37 * deg) && rho < 23.6)
                continue;
            double nearest = 1e9;
            for (const test::Segment& s : feeds)
                nearest = std::min(nearest, test::distanceToSegmentXY({x, y}, s));
            EXPECT_LE(nearest, 0.5 + 1e-6) << x << ", " << y;
            ++checked;
        }
    EXPECT_GT(checked, 3000);
}

TEST(ParallelOp, OneWayCutsAllGoTheSameWay)
{
    const sim::TriangleMesh mesh =
        test::gridMesh([](double x, double y) { return 0.1 * x + 0.05 * y; }, 0, 20, 0, 10, 10);
    ParallelParams p = paramsFor(2);
    p.zigZag = false;
    const auto result = computeParallel(inputFor(mesh, 0, 20, 0, 10), p, controller(tool("ball", 4)), 0);
    ASSERT_TRUE(result) << result.error().message;
    int cuts = 0;
    for (const test::Segment& s : test::feedMoves(result.value().toolpath))
        if (std::abs(s.b.y - s.a.y) < 1e-9 && std::abs(s.b.x - s.a.x) > 1e-9) {
            EXPECT_GT(s.b.x, s.a.x);
            ++cuts;
        }
    EXPECT_GE(cuts, 6);  // 6 lines (0, 2, ..., 10), each one straight move on the plane
    const toolpath::Toolpath& path = result.value().toolpath;
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionBegin>(path.records().front()));
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionEnd>(path.records().back()));
}

TEST(ParallelOp, AngledLinesEndAtTheAreasEdge)
{
    const sim::TriangleMesh mesh = test::gridMesh([](double x, double) { return 0.05 * x; }, -5, 25, -5, 15, 6);
    ParallelParams p = paramsFor(1);
    p.angleDeg = 30;
    const auto result = computeParallel(inputFor(mesh, 0, 20, 0, 10), p, controller(tool("ball", 4)), 0);
    ASSERT_TRUE(result) << result.error().message;
    const double a = 30 * std::numbers::pi / 180;
    const base::Vec2 u{std::cos(a), std::sin(a)}, v{-u.y, u.x};
    // The cut moves along the lines, grouped by line; each line's extent against the box's.
    std::map<long, std::pair<double, double>> lines;
    for (const test::Segment& s : test::feedMoves(result.value().toolpath)) {
        const base::Vec2 d{s.b.x - s.a.x, s.b.y - s.a.y};
        if (d.length() < 1e-6 || std::abs(d.x * u.y - d.y * u.x) > 1e-6 * d.length())
            continue;
        for (const base::Vec3& q : {s.a, s.b}) {
            const base::Vec2 xy{q.x, q.y};
            auto [it, added] = lines.try_emplace(std::lround(xy.dot(v) * 1e4), xy.dot(u), xy.dot(u));
            it->second = {std::min(it->second.first, xy.dot(u)), std::max(it->second.second, xy.dot(u))};
        }
    }
    int checked = 0;
    for (const auto& [key, extent] : lines) {
        // Where the line at this v enters and leaves [0, 20] x [0, 10].
        double lo = -1e9, hi = 1e9;
        const double vv = key / 1e4;
        for (int axis = 0; axis < 2; ++axis) {
            const double o = axis == 0 ? v.x * vv : v.y * vv, du = axis == 0 ? u.x : u.y, max = axis == 0 ? 20 : 10;
            const double t0 = (0 - o) / du, t1 = (max - o) / du;
            lo = std::max(lo, std::min(t0, t1)), hi = std::min(hi, std::max(t0, t1));
        }
        if (hi - lo < 1)
            continue;
        EXPECT_NEAR(extent.first, lo, 1e-4) << vv;
        EXPECT_NEAR(extent.second, hi, 1e-4) << vv;
        ++checked;
    }
    EXPECT_GE(checked, 8);
}

TEST(ParallelOp, StaysInTheBoundary)
{
    // A round boundary of radius 8 round (10, 10) on a tilted plane over a 20 x 20 stock.
    const sim::TriangleMesh mesh =
        test::gridMesh([](double x, double y) { return 0.1 * x - 0.05 * y; }, -5, 25, -5, 25, 6);
    SurfaceInput in = inputFor(mesh, 0, 20, 0, 20);
    geom::Region circle;
    circle.outer.segments = {geom::Segment::arc({18, 10}, {2, 10}, {10, 10}, true),
                             geom::Segment::arc({2, 10}, {18, 10}, {10, 10}, true)};
    in.boundary = {circle};
    ParallelParams p = paramsFor(1);
    p.angleDeg = 20;
    const auto result = computeParallel(in, p, controller(tool("ball", 4)), 0);
    ASSERT_TRUE(result) << result.error().message;
    const std::vector<test::Segment> feeds = test::feedMoves(result.value().toolpath);
    ASSERT_FALSE(feeds.empty());
    for (const test::Segment& s : feeds)
        for (const base::Vec3& q : {s.a, s.b})
            EXPECT_LE(std::hypot(q.x - 10, q.y - 10), 8 + 1e-5) << q.x << ", " << q.y;
    // and it covers the disc (the lines end on its edge)
    for (double x = 3; x <= 17; x += 0.9)
        for (double y = 3; y <= 17; y += 0.9) {
            if (std::hypot(x - 10, y - 10) > 7)
                continue;
            double nearest = 1e9;
            for (const test::Segment& s : feeds)
                nearest = std::min(nearest, test::distanceToSegmentXY({x, y}, s));
            EXPECT_LE(nearest, 0.5 + 1e-6) << x << ", " << y;
        }
}

TEST(ParallelOp, CancelledGivesNothing)
{
    const sim::TriangleMesh mesh = test::gridMesh([](double, double) { return 0.0; }, 0, 10, 0, 10, 2);
    std::atomic<bool> cancel{true};
    const auto result = computeParallel(inputFor(mesh, 0, 10, 0, 10), paramsFor(1), controller(tool("ball", 6)), 0,
                                        Progress{{}, &cancel});
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().message, "parallel \"Parallel\": cancelled");
}

TEST(ParallelOp, ParameterErrors)
{
    const sim::TriangleMesh mesh = test::gridMesh([](double, double) { return 0.0; }, 0, 10, 0, 10, 2);
    const SurfaceInput in = inputFor(mesh, 0, 10, 0, 10);
    const ToolController tc = controller(tool("ball", 6));
    auto error = [&](const ParallelParams& p, const SurfaceInput& input, const ToolController& c) {
        const auto r = computeParallel(input, p, c, 0);
        return r ? std::string("no error") : r.error().message;
    };
    ParallelParams p = paramsFor(1);
    p.name = "P";
    EXPECT_EQ(error(p, in, tc), "no error");
    ParallelParams bad = p;
    bad.stepoverMm = 0;
    EXPECT_EQ(error(bad, in, tc).find("parallel \"P\": "), 0u);
    EXPECT_NE(error(bad, in, tc).find("stepover must be above 0 and at most the tool diameter 6 mm, got 0 mm"),
              std::string::npos);
    bad = p, bad.stepoverMm = 7;
    EXPECT_NE(error(bad, in, tc).find("stepover"), std::string::npos);
    bad = p, bad.stepoverMm = 1e-7;  // a slip: millions of raster passes
    EXPECT_NE(error(bad, in, tc).find("stepover 0.0000001 mm makes "), std::string::npos) << error(bad, in, tc);
    bad = p, bad.maxSlopeDeg = 0;
    EXPECT_NE(error(bad, in, tc).find("slope limit must be above 0 and at most 90 degrees, got 0"), std::string::npos);
    bad = p, bad.stockMm = -0.1;
    EXPECT_NE(error(bad, in, tc).find("stock to leave must not be negative"), std::string::npos);
    bad = p, bad.toleranceMm = 0;
    EXPECT_NE(error(bad, in, tc).find("tolerance must be from 0.0001 to 1 mm"), std::string::npos);
    bad = p, bad.heights.clearanceZ = 5;
    EXPECT_NE(error(bad, in, tc).find("clearance height 5 is below the safe height 15"), std::string::npos);
    bad = p, bad.heights.safeZ = bad.heights.clearanceZ = -1;
    EXPECT_NE(error(bad, in, tc).find("the safe height -1 is below the top of the model 0"), std::string::npos);
    bad = p, bad.angleDeg = std::nan("");
    EXPECT_NE(error(bad, in, tc).find("raster angle"), std::string::npos);
    SurfaceInput none = in;
    none.model = nullptr;
    EXPECT_NE(error(p, none, tc).find("no model to finish"), std::string::npos);
    ToolController noTool = tc;
    noTool.tool.diameterMm = 0;
    EXPECT_NE(error(p, in, noTool).find("tool diameter must be positive"), std::string::npos);
}

}  // namespace
}  // namespace camwb::ops
