// The 3D pocket on generated parts, judged by oracles that do not share its geometry: the z-map
// simulator (gouge; material left), the tool's true shape against the mesh at CL points, and a
// leftover check that looks for a flat tool position the roughing missed (material more than a
// step above a place where the tool fits). Also: levels on the flat floors, rest roughing after a
// big tool, and the parameter errors.
#include "ops/Pocket3dOp.h"

#include "RoughingTestUtil.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <set>

namespace camwb::ops {
namespace {

using namespace test;

constexpr double kTol = 0.01;

struct Part {
    sim::TriangleMesh mesh;
    SurfaceInput input;
};

Part makePart(const HeightFn& f, std::vector<double> floors, int n = 100)
{
    Part part;
    part.mesh = heightMesh(f, 0, 0, 60, 50, n, 0);
    part.input.stock = box3({0, 0, 0}, {60, 50, 21});
    part.input.flatLevels = std::move(floors);
    return part;
}

Pocket3dParams roughParams(double finalZ = 7)
{
    Pocket3dParams p;
    p.heights = {30, 25, 21, finalZ};
    p.stepDownMm = 2;
    p.sideStockMm = 0.3;
    p.bottomStockMm = 0.2;
    p.toleranceMm = kTol;
    return p;
}

OpResult rough(const Part& part, const Pocket3dParams& p, const ToolController& tc)
{
    SurfaceInput input = part.input;
    input.model = &part.mesh;
    base::Result<OpResult> r = computePocket3d(input, p, tc, 0);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? std::move(r.value()) : OpResult{};
}

// Whether a flat tool of radius r with its tip at z over (cx, cy) stays `margin` clear of the
// design (as the z-map samples it) grown by the stocks.
bool flatFits(const sim::HeightField& s, double cx, double cy, double z, double r, const Pocket3dParams& p,
              double margin)
{
    const double reach = r + p.sideStockMm + margin;
    const double dx = s.columnX(1) - s.columnX(0), dy = s.columnY(1) - s.columnY(0);
    const int i0 = std::max(0, int((cx - reach - s.columnX(0)) / dx)),
              i1 = std::min(s.columnsX() - 1, int((cx + reach - s.columnX(0)) / dx) + 1);
    const int j0 = std::max(0, int((cy - reach - s.columnY(0)) / dy)),
              j1 = std::min(s.columnsY() - 1, int((cy + reach - s.columnY(0)) / dy) + 1);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            if (std::hypot(s.columnX(i) - cx, s.columnY(j) - cy) <= reach &&
                s.designTop(i, j) + p.bottomStockMm + margin > z)
                return false;
    return true;
}

// Columns whose material stands more than a step (plus the bottom stock and tolerance) above a
// height where a flat tool over them would have fitted: material the roughing should have cut.
int missedColumns(const sim::HeightField& s, double radius, const Pocket3dParams& p, const base::Box3& stock)
{
    constexpr double kMargin = 0.5;  // the z-map's sampling of steep walls
    int missed = 0;
    for (int j = 0; j < s.columnsY(); ++j)
        for (int i = 0; i < s.columnsX(); ++i) {
            const double t = s.top(i, j);
            const double z = t - p.toleranceMm - p.stepDownMm;
            if (t <= s.designTop(i, j) + p.bottomStockMm + p.toleranceMm || z < p.heights.finalZ)
                continue;
            bool fits = false;
            for (int k = 0; k < 8 && !fits; ++k)
                for (double f : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) {
                    const double a = k * std::numbers::pi / 4, d = f * (radius - kMargin);
                    const double cx = s.columnX(i) + d * std::cos(a), cy = s.columnY(j) + d * std::sin(a);
                    if (cx >= stock.min.x && cx <= stock.max.x && cy >= stock.min.y && cy <= stock.max.y &&
                        flatFits(s, cx, cy, z, radius, p, kMargin)) {
                        fits = true;
                        break;
                    }
                }
            missed += fits;
        }
    return missed;
}

TEST(Pocket3d, FlatRoughingOfRandomPartsNeitherGougesNorLeavesWhatTheToolReaches)
{
    std::mt19937 rng(7);
    for (int trial = 0; trial < 3; ++trial) {
        SCOPED_TRACE("part " + std::to_string(trial));
        const Part part = makePart(randomPart(rng), {20});
        // Offset rings at half the diameter, zig-zag at 70 % and rings at 90 % (clean-up needed).
        Pocket3dParams p = roughParams();
        p.pattern = trial == 1 ? PocketPattern::ZigZag : PocketPattern::Offset;
        p.zigZagAngleDeg = 30;
        p.stepoverPercent = trial == 0 ? 50 : trial == 1 ? 70 : 90;
        const ToolController tc = toolController("flat", 8);
        const OpResult r = rough(part, p, tc);
        ASSERT_FALSE(r.toolpath.empty());
        EXPECT_LE(deepestPenetration(r.toolpath, tc.tool, part.mesh, p.sideStockMm, p.bottomStockMm), kTol);
        const StockCheck cut = cutThrough(r.toolpath, tc.tool, part.mesh, part.input.stock, 0.25);
        EXPECT_LE(cut.maxGougeMm, 0.02);
        EXPECT_EQ(cut.rapidsInStock, 0);
        EXPECT_EQ(missedColumns(*cut.stock, 4, p, part.input.stock), 0);
    }
}

TEST(Pocket3d, ALevelJustBelowAnUnlistedFloorKeepsTheBallOnIt)
{
    // The floor at 12.05 is not among the flat levels; the 1 mm steps put a level at 12, 0.05 mm
    // below it: the ball must stay on the floor, not sink 0.05 mm into it (the bands near the tip).
    const Part part = makePart(draftedCavity(7.95, 10, 4, 0), {20});
    Pocket3dParams p = roughParams(12);
    p.stepDownMm = 1;
    p.sideStockMm = 0;
    p.bottomStockMm = 0;
    for (const auto& [kind, corner] : {std::pair{std::string("ball"), 0.0}, {std::string("bull"), 1.0}}) {
        SCOPED_TRACE(kind);
        const ToolController tc = toolController(kind, 6, corner);
        const OpResult r = rough(part, p, tc);
        EXPECT_LE(deepestPenetration(r.toolpath, tc.tool, part.mesh, 0, 0), kTol);
    }
}

TEST(Pocket3d, BallAndBullNoseRoughingNeverGougesTheModel)
{
    std::mt19937 rng(11);
    for (const auto& [kind, corner] : {std::pair{std::string("ball"), 0.0}, {std::string("bull"), 1.5}}) {
        SCOPED_TRACE(kind);
        const Part part = makePart(randomPart(rng), {20});
        const Pocket3dParams p = roughParams();
        const ToolController tc = toolController(kind, 6, corner);
        const OpResult r = rough(part, p, tc);
        ASSERT_FALSE(r.toolpath.empty());
        EXPECT_LE(deepestPenetration(r.toolpath, tc.tool, part.mesh, p.sideStockMm, p.bottomStockMm), kTol);
        EXPECT_LE(deepestPenetration(r.toolpath, tc.tool, part.mesh, 0, 0), kTol - 0.2);  // the stock is left
        const StockCheck cut = cutThrough(r.toolpath, tc.tool, part.mesh, part.input.stock, 0.25);
        EXPECT_LE(cut.maxGougeMm, 0.02);
        EXPECT_EQ(cut.rapidsInStock, 0);
    }
}

TEST(Pocket3d, ASphereIsRoughedWithoutGougeAndCloseToItsShape)
{
    const Part part = makePart(sphereOnPlate(5, 15, 3), {5});
    Pocket3dParams p = roughParams(4);
    p.stepDownMm = 1;
    p.sideStockMm = 0;
    p.bottomStockMm = 0.1;
    const ToolController tc = toolController("bull", 10, 2);
    const OpResult r = rough(part, p, tc);
    EXPECT_LE(deepestPenetration(r.toolpath, tc.tool, part.mesh, 0, p.bottomStockMm), kTol);
    const StockCheck cut = cutThrough(r.toolpath, tc.tool, part.mesh, part.input.stock, 0.25);
    EXPECT_LE(cut.maxGougeMm, 0.02);
    EXPECT_EQ(cut.rapidsInStock, 0);
}

TEST(Pocket3d, LevelsLandExactlyOnTheFlatFloors)
{
    // Cavity floor at 20 - 7.3 = 12.7 and a boss top at 12.7 + 3.15 = 15.85: off the 2 mm grid.
    const HeightFn cavity = draftedCavity(7.3, 10, 4, 1);
    const HeightFn boss = draftedBoss(12.7, 3.15, 15, 2);
    const Part part =
        makePart([&](double x, double y) { return std::max(cavity(x, y), boss(x, y)); }, {20, 15.85, 12.7});
    const Pocket3dParams p = roughParams(12);
    const ToolController tc = toolController("flat", 6);
    const OpResult r = rough(part, p, tc);
    std::set<double> levels;
    for (const toolpath::Record& rec : r.toolpath.records())
        if (const auto* l = std::get_if<toolpath::Linear>(&rec))
            levels.insert(std::round(l->to.z * 1e6) / 1e6);
    for (double floor : {20.0, 15.85, 12.7})
        EXPECT_TRUE(levels.count(std::round((floor + p.bottomStockMm) * 1e6) / 1e6))
            << "no level on the floor " << floor;
    // The cavity floor between the walls and the boss is left at the bottom stock.
    const StockCheck cut = cutThrough(r.toolpath, tc.tool, part.mesh, part.input.stock, 0.25);
    const sim::HeightField& s = *cut.stock;
    for (int j = 0; j < s.columnsY(); ++j)
        for (int i = 0; i < s.columnsX(); ++i) {
            const double x = s.columnX(i), y = s.columnY(j);
            if (std::abs(x - 30) < 5 && y > 12 && y < 16)  // between the boss (y < 19) and the wall (y > 9)
                ASSERT_NEAR(s.top(i, j), 12.7 + p.bottomStockMm, 2 * kTol) << x << " " << y;
        }
}

TEST(Pocket3d, RestRoughingAfterABigToolCutsLittleAirAndReachesTheCorners)
{
    const Part part = makePart(draftedCavity(8, 5, 3, 0), {20, 12});
    const Pocket3dParams p = roughParams(11);
    const ToolController big = toolController("flat", 16);
    const OpResult first = rough(part, p, big);
    const StockCheck afterBig = cutThrough(first.toolpath, big.tool, part.mesh, part.input.stock, 0.25);
    const ToolController small = toolController("flat", 4);
    EXPECT_GT(missedColumns(*afterBig.stock, 2, p, part.input.stock), 0);  // corners the big tool left

    Part restPart = part;
    restPart.input.restStock = afterBig.stock.get();
    Pocket3dParams restParams = p;
    restParams.restMachining = true;
    const OpResult rest = rough(restPart, restParams, small);
    Pocket3dParams fullParams = p;
    const OpResult full = rough(restPart, fullParams, small);  // the same tool over everything

    ASSERT_FALSE(rest.warnings.empty());
    EXPECT_NE(rest.warnings.back().message.find("cut air"), std::string::npos) << rest.warnings.back().message;
    const StockCheck afterRest = cutThrough(rest.toolpath, small.tool, part.mesh, {}, 0.25, afterBig.stock.get());
    const StockCheck afterFull = cutThrough(full.toolpath, small.tool, part.mesh, {}, 0.25, afterBig.stock.get());
    EXPECT_LE(afterRest.maxGougeMm, 0.02);
    EXPECT_EQ(afterRest.rapidsInStock, 0);
    EXPECT_EQ(missedColumns(*afterRest.stock, 2, p, part.input.stock), 0);
    EXPECT_LT(afterRest.airMm, 0.25 * afterFull.airMm) << afterRest.airMm << " vs " << afterFull.airMm;
    EXPECT_LT(afterRest.cuttingMm + afterRest.airMm, 0.5 * (afterFull.cuttingMm + afterFull.airMm));
}

TEST(Pocket3d, TheToolCentreStaysInTheBoundaryAndCancellingGivesNothing)
{
    Part part = makePart(draftedCavity(6, 10, 3, 1), {20, 14});
    geom::Region box;
    const geom::Vec2 a{15, 12}, b{45, 12}, c{45, 38}, d{15, 38};
    box.outer.segments = {geom::Segment::line(a, b), geom::Segment::line(b, c), geom::Segment::line(c, d),
                          geom::Segment::line(d, a)};
    part.input.boundary = {box};
    const Pocket3dParams p = roughParams(13);
    const ToolController tc = toolController("flat", 6);
    const OpResult r = rough(part, p, tc);
    int points = 0;
    for (const toolpath::Record& rec : r.toolpath.records())
        if (const auto* l = std::get_if<toolpath::Linear>(&rec)) {
            EXPECT_TRUE(box.contains(l->to.xy()) || box.distanceToBoundary(l->to.xy()) < 1e-6)
                << l->to.x << " " << l->to.y;
            ++points;
        }
    EXPECT_GT(points, 20);

    std::atomic<bool> cancel{true};
    SurfaceInput input = part.input;
    input.model = &part.mesh;
    base::Result<OpResult> cancelled = computePocket3d(input, p, tc, 0, Progress{{}, &cancel});
    ASSERT_FALSE(cancelled.ok());
    EXPECT_NE(cancelled.error().message.find("cancelled"), std::string::npos);
}

TEST(Pocket3d, ParameterErrorsAreClear)
{
    const Part part = makePart(draftedCavity(6, 10, 3, 1), {20});
    const ToolController tc = toolController("flat", 6);
    const auto error = [&](const std::function<void(Pocket3dParams&, SurfaceInput&)>& change) {
        Pocket3dParams p = roughParams();
        SurfaceInput input = part.input;
        input.model = &part.mesh;
        change(p, input);
        base::Result<OpResult> r = computePocket3d(input, p, tc, 0);
        return r.ok() ? std::string("(no error)") : r.error().message;
    };
    EXPECT_NE(error([](auto& p, auto&) { p.stepDownMm = 0; }).find("step-down must be positive"), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.sideStockMm = -1; }).find("must not be negative"), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.toleranceMm = 0; }).find("tolerance"), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.stepoverPercent = 150; }).find("stepover"), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.restMachining = true; }).find("rest machining needs"), std::string::npos);
    EXPECT_NE(error([](auto&, auto& in) { in.model = nullptr; }).find("no model"), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.heights.finalZ = 22; }).find("3D pocket \"3D Pocket\""), std::string::npos);
    EXPECT_NE(error([](auto& p, auto&) { p.helixPitchMm = 0; }).find("helix pitch"), std::string::npos);
}

}  // namespace
}  // namespace camwb::ops
