// Waterline on a sphere standing out of a plate, judged against the analytic answer: every
// contour's ball centre lies on the sphere grown by the tool radius (within the tolerance), the
// scallop between neighbouring contours (the two balls' crossing nearest the sphere's centre)
// stays below the requested height, contours run only where the sphere is steeper than the slope
// limit and cover all of it; the tool's shape (ball, bull-nose, flat) against the mesh; the
// parameter errors.
#include "ops/WaterlineOp.h"

#include "RoughingTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace camwb::ops {
namespace {

using namespace test;

constexpr double kSphereR = 15, kCentreZ = 3, kPlate = 5;

struct Contours {
    std::map<double, std::vector<base::Vec3>> byLevel;  // finishing moves' end points by Z
};

Contours contoursOf(const OpResult& r)
{
    Contours c;
    for (const toolpath::Record& rec : r.toolpath.records())
        if (const auto* l = std::get_if<toolpath::Linear>(&rec); l && l->feedKind == toolpath::FeedKind::Finishing)
            c.byLevel[std::round(l->to.z * 1e6) / 1e6].push_back(l->to);
    return c;
}

WaterlineParams sphereParams()
{
    WaterlineParams p;
    p.heights = {30, 25, 17.5, kPlate + 0.5};
    p.scallopMm = 0.02;
    p.maxStepDownMm = 1;
    p.minSlopeDeg = 30;
    p.toleranceMm = 0.02;
    return p;
}

TEST(Waterline, SphereContoursTouchItLeaveAtMostTheScallopAndOnlyOnSteepWalls)
{
    // Fine facets (0.2 mm: within 0.0004 mm of the sphere), so that the slope limit can be judged.
    const sim::TriangleMesh mesh = heightMesh(sphereOnPlate(kPlate, kSphereR, kCentreZ), 0, 0, 60, 50, 300, 0);
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 20});
    const ToolController tc = toolController("ball", 6);
    const double R = 3;
    const WaterlineParams p = sphereParams();
    base::Result<OpResult> r = computeWaterline(input, p, tc, 0);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_LE(deepestPenetration(r.value().toolpath, tc.tool, mesh, 0, 0), p.toleranceMm);

    // The slope of the secant from a level's exact contour to the one 0.25 mm higher.
    const auto secantSlopeDeg = [&](double z) {
        const auto rhoAt = [&](double h) {
            return std::sqrt(std::pow(kSphereR + R, 2) - std::pow(h + R - kCentreZ, 2));
        };
        return std::atan2(0.25, rhoAt(z) - rhoAt(z + 0.25)) * 180 / std::numbers::pi;
    };
    // Per level: the contour's distance from the axis (mean), its spread, and the secant's slope.
    struct Level {
        double z, rho;
    };
    std::vector<Level> levels;
    for (const auto& [z, pts] : contoursOf(r.value()).byLevel) {
        double lo = 1e9, hi = 0, sum = 0;
        for (const base::Vec3& q : pts) {
            const double rho = std::hypot(q.x - 30, q.y - 25);
            lo = std::min(lo, rho), hi = std::max(hi, rho), sum += rho;
        }
        const double rho = sum / pts.size();
        // The ball's centre on the grown sphere: rho^2 + (z + R - centre)^2 = (15 + 3)^2, within the
        // tolerance and the margins kept for fitting (1.75 tolerance along the normal, more across
        // on shallower walls) and the facets' sagitta.
        const double expected = std::sqrt(std::pow(kSphereR + R, 2) - std::pow(z + R - kCentreZ, 2));
        const double slope = std::acos((z + R - kCentreZ) / (kSphereR + R));
        EXPECT_NEAR(rho, expected, 1.75 * p.toleranceMm / std::sin(slope) + 0.005) << "level " << z;
        EXPECT_LT(hi - lo, 0.12) << "level " << z;
        // Steep or shallow is told from the contour dz = 0.25 mm higher: steep where it lies within
        // dz / tan(minSlope) inward, where the secant's slope is at least the limit (to a tenth of a
        // degree on these facets).
        const double secantDeg = secantSlopeDeg(z);
        EXPECT_GE(secantDeg, p.minSlopeDeg - 0.1) << "a contour on a shallow part, level " << z;
        levels.push_back({z, rho});
    }
    ASSERT_GE(levels.size(), 10u);
    // Climb milling round a boss: material on the right, so clockwise seen from above.
    double turning = 0;
    base::Vec2 prev{NAN, NAN};
    for (const toolpath::Record& rec : r.value().toolpath.records())
        if (const auto* l = std::get_if<toolpath::Linear>(&rec); l && l->feedKind == toolpath::FeedKind::Finishing) {
            const base::Vec2 at{l->to.x - 30, l->to.y - 25};
            if (!std::isnan(prev.x))
                turning += prev.cross(at);
            prev = at;
        }
    EXPECT_LT(turning, 0);
    // All of the steep band is covered: from the slope limit down to the lowest level. The level
    // above the highest contour is shallow (here 15.786: 28.0 degrees; the highest, 15.443, 30.1).
    const double next = 2 * levels.back().z - levels[levels.size() - 2].z;
    EXPECT_LT(secantSlopeDeg(next), p.minSlopeDeg + 0.1) << "no contour at " << next;
    EXPECT_LT(levels.front().z, p.heights.finalZ + 0.5);
    // Scallop between neighbours: the balls' centres c1, c2 lie on a circle round the sphere's
    // centre, so their crossing nearest to it is on the bisector through it.
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const base::Vec2 c1{levels[i - 1].rho, levels[i - 1].z + R - kCentreZ};
        const base::Vec2 c2{levels[i].rho, levels[i].z + R - kCentreZ};
        const double a = std::hypot(c1.x - c2.x, c1.y - c2.y) / 2;
        ASSERT_LT(a, R);
        const double mid = std::hypot((c1.x + c2.x) / 2, (c1.y + c2.y) / 2);
        // Above the sphere the two balls actually touch (the contours' own stand-off is judged
        // above, against the exact radius).
        const double touched = (std::hypot(c1.x, c1.y) + std::hypot(c2.x, c2.y)) / 2 - R;
        const double scallop = mid - std::sqrt(R * R - a * a) - touched;
        EXPECT_LE(scallop, p.scallopMm) << "between levels " << levels[i - 1].z << " and " << levels[i].z;
    }
}

// Waterline in a drafted cavity (floor at Z 12, fillets of `fillet` into it, a mesh of `cells`
// squares a side), with no stock and with `stock`: contours on five levels at least, and the tool
// grown by the stock (measured along the model's normal, as parallel finishing leaves it) never in
// the model by the tolerance.
void expectNoGougeInAFilletedCavity(const ToolController& tc, double fillet, int cells, double stock)
{
    const sim::TriangleMesh mesh = heightMesh(draftedCavity(8, 10, 4, fillet), 0, 0, 60, 50, cells, 0);
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 20});
    input.flatLevels = {12};
    for (const double s : {0.0, stock}) {
        WaterlineParams p;
        p.heights = {30, 25, 19.5, 12 + s};
        p.scallopMm = 0.05;
        p.maxStepDownMm = 1;
        p.minSlopeDeg = 30;
        p.stockMm = s;
        p.toleranceMm = 0.01;
        base::Result<OpResult> r = computeWaterline(input, p, tc, 0);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_GE(contoursOf(r.value()).byLevel.size(), 5u);
        EXPECT_LE(deepestPenetrationGrown(r.value().toolpath, tc.tool, mesh, s, 0.1), p.toleranceMm)
            << tc.tool.kind << ", stock " << s;
    }
}

// The floor fillet has the ball's radius: at the floor the ball fits the fillet exactly, where a
// small error in the drop heights moves the contour most.
TEST(Waterline, ABallInAFilletOfItsOwnRadiusNeverGouges)
{
    expectNoGougeInAFilletedCavity(toolController("ball", 6), 3, 120, 0.3);
}

// A bull-nose (D6, corner R1) in fillets of R2: its grid is finer (the corner, not the radius,
// sets it).
TEST(Waterline, ABullNoseNeverGouges) { expectNoGougeInAFilletedCavity(toolController("bull", 6, 1), 2, 150, 0.2); }

TEST(Waterline, FlatToolStepsDownByTheStairItLeaves)
{
    const sim::TriangleMesh mesh = heightMesh(draftedCavity(8, 20, 4, 0), 0, 0, 60, 50, 100, 0);
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 21});
    const ToolController tc = toolController("flat", 6);
    WaterlineParams p;
    p.heights = {30, 25, 19.5, 12.5};
    p.scallopMm = 0.05;
    p.minSlopeDeg = 45;
    base::Result<OpResult> r = computeWaterline(input, p, tc, 0);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_LE(deepestPenetration(r.value().toolpath, tc.tool, mesh, 0, 0), p.toleranceMm);
    const Contours c = contoursOf(r.value());
    ASSERT_GE(c.byLevel.size(), 2u);
    // On a wall 70 degrees from horizontal the stair is step * cos(45) at the slope limit.
    double prev = NAN;
    for (const auto& [z, pts] : c.byLevel) {
        if (!std::isnan(prev))
            EXPECT_LE((z - prev) * std::cos(std::numbers::pi / 4), p.scallopMm + 1e-6);
        prev = z;
    }
}

// A pocket with vertical walls and sharp corners (40 x 30 mm, 10 deep, in a 60 x 50 plate): a flat
// D6's contour is the pocket shrunk by its radius, sharp at the corners. Marching squares alone
// would cut each corner with a chord about a grid step short of it, leaving material in the corner.
TEST(Waterline, SharpInsideCornersAreFollowedIntoTheCorner)
{
    sim::TriangleMesh mesh;
    const auto vertex = [&](double x, double y, double z) {
        mesh.positions.insert(mesh.positions.end(), {float(x), float(y), float(z)});
        return std::uint32_t(mesh.vertexCount() - 1);
    };
    const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        mesh.triangles.insert(mesh.triangles.end(), {a, b, c, a, c, d});
    };
    const double outer[4][2] = {{0, 0}, {60, 0}, {60, 50}, {0, 50}},
                 inner[4][2] = {{10, 10}, {50, 10}, {50, 40}, {10, 40}};
    std::uint32_t o[4], top[4], floor[4];
    for (int k = 0; k < 4; ++k) {
        o[k] = vertex(outer[k][0], outer[k][1], 20);
        top[k] = vertex(inner[k][0], inner[k][1], 20);
        floor[k] = vertex(inner[k][0], inner[k][1], 10);
    }
    for (int k = 0; k < 4; ++k) {
        quad(o[k], o[(k + 1) % 4], top[(k + 1) % 4], top[k]);          // the plate round the pocket
        quad(top[k], top[(k + 1) % 4], floor[(k + 1) % 4], floor[k]);  // the wall
    }
    quad(floor[0], floor[1], floor[2], floor[3]);
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 20});
    input.flatLevels = {10};
    WaterlineParams p;
    p.heights = {30, 25, 19.5, 10};
    p.scallopMm = 0.05;
    p.maxStepDownMm = 2;
    p.minSlopeDeg = 45;
    p.toleranceMm = 0.01;
    base::Result<OpResult> r = computeWaterline(input, p, toolController("flat", 6), 0);
    ASSERT_TRUE(r.ok()) << r.error().message;
    // Per level, the finishing moves' nearest approach to each corner of the tool centre's rectangle.
    std::map<double, std::vector<std::pair<base::Vec2, base::Vec2>>> moves;
    base::Vec3 at{};
    for (const toolpath::Record& rec : r.value().toolpath.records()) {
        if (const auto* l = std::get_if<toolpath::Linear>(&rec)) {
            if (l->feedKind == toolpath::FeedKind::Finishing)
                moves[std::round(l->to.z * 1e6) / 1e6].push_back({{at.x, at.y}, {l->to.x, l->to.y}});
            at = l->to;
        } else if (const auto* rapid = std::get_if<toolpath::Rapid>(&rec)) {
            at = rapid->to;
        }
    }
    ASSERT_GE(moves.size(), 4u);
    for (const auto& [z, segments] : moves)
        for (const base::Vec2 corner :
             {base::Vec2{13, 13}, base::Vec2{47, 13}, base::Vec2{47, 37}, base::Vec2{13, 37}}) {
            double nearest = 1e9;
            for (const auto& [a, b] : segments) {
                const base::Vec2 ab = b - a;
                const double t = std::clamp((corner - a).dot(ab) / std::max(ab.dot(ab), 1e-18), 0.0, 1.0);
                nearest = std::min(nearest, (a + ab * t - corner).length());
            }
            // The contour stands its growth (a tolerance) off both walls, so sqrt(2) tolerances off
            // the corner, and the corner is found to half a tolerance more.
            EXPECT_LE(nearest, 2.5 * p.toleranceMm) << "corner " << corner.x << ", " << corner.y << " at level " << z;
        }
}

// A floor exactly at the lowest level, at a height a float cannot hold (12.1 is stored 0.4 um
// higher): the tool stands on it there, so the level still has its contour round the walls.
TEST(Waterline, AFloorAtTheLowestLevelIsTouchedNotCut)
{
    const sim::TriangleMesh mesh = heightMesh(draftedCavity(7.9, 20, 4, 0), 0, 0, 60, 50, 100, 0);
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 21});
    WaterlineParams p;
    p.heights = {30, 25, 19.5, 12.1};
    p.scallopMm = 0.05;
    p.minSlopeDeg = 45;
    base::Result<OpResult> r = computeWaterline(input, p, toolController("flat", 6), 0);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const Contours c = contoursOf(r.value());
    ASSERT_FALSE(c.byLevel.empty());
    EXPECT_NEAR(c.byLevel.begin()->first, 12.1, 1e-6);
    EXPECT_GT(c.byLevel.begin()->second.size(), 4u);
}

TEST(Waterline, ParameterErrorsAreClear)
{
    const sim::TriangleMesh mesh = heightMesh(sphereOnPlate(kPlate, 10, kCentreZ), 0, 0, 60, 50, 40, 0);
    const ToolController tc = toolController("ball", 6);
    const auto error = [&](const std::function<void(WaterlineParams&, SurfaceInput&)>& change) {
        WaterlineParams p = sphereParams();
        SurfaceInput input;
        input.model = &mesh;
        input.stock = box3({0, 0, 0}, {60, 50, 20});
        change(p, input);
        base::Result<OpResult> r = computeWaterline(input, p, tc, 0);
        return r.ok() ? std::string("(no error)") : r.error().message;
    };
    EXPECT_NE(error([](auto& p, auto&) { p.scallopMm = 0; }).find("scallop height must be positive"),
              std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.maxStepDownMm = -1; }).find("step-down"), std::string::npos);
    // A slip of the keyboard (a scallop of 1e-9 mm) is refused, not computed for hours.
    EXPECT_NE(error([](auto& p, auto&) {
                  p.scallopMm = 1e-9;
              }).find("step-down (from the scallop height) 0.00007746 mm makes 154920 levels over 12 mm"),
              std::string::npos)
        << error([](auto& p, auto&) { p.scallopMm = 1e-9; });
    EXPECT_NE(error([](auto& p, auto&) { p.minSlopeDeg = 90; }).find("slope limit"), std::string::npos);
    // The contours' grid follows the tolerance: one too fine for the area is refused before any drop.
    EXPECT_NE(error([](auto& p, auto&) {
                  p.toleranceMm = 1e-5;
              }).find("the tolerance 0.00001 mm needs 50 million drops over the area (at most 16 million)"),
              std::string::npos)
        << error([](auto& p, auto&) { p.toleranceMm = 1e-5; });
    EXPECT_NE(error([](auto& p, auto&) { p.stockMm = -0.1; }).find("must not be negative"), std::string::npos);
    EXPECT_NE(error([](auto&, auto& in) { in.model = nullptr; }).find("waterline \"Waterline\": no model"),
              std::string::npos);
    // A pointed tool has no radius for the grid's chords to keep within the tolerance.
    WaterlineParams p = sphereParams();
    SurfaceInput input;
    input.model = &mesh;
    input.stock = box3({0, 0, 0}, {60, 50, 20});
    ToolController pointed = toolController("drill", 6);
    pointed.tool.pointAngleDeg = 118;
    base::Result<OpResult> drill = computeWaterline(input, p, pointed, 0);
    ASSERT_FALSE(drill.ok());
    EXPECT_NE(drill.error().message.find("a pointed drill cannot follow a waterline"), std::string::npos)
        << drill.error().message;
}

}  // namespace
}  // namespace camwb::ops
