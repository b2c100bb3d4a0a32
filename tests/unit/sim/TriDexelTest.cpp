// The tri-dexel stock: it agrees with the height field on three-axis cuts, cuts an undercut a
// z-map cannot hold, reports a gouge and a short holder like the height field, fills a blank
// with a cavity, and its mesh holds its volume; the factory picks the representation.
#include "sim/TriDexel.h"
#include "StockTestUtil.h"
#include "sim/HeightField.h"
#include "sim/MakeStock.h"
#include "sim/Simulation.h"
#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace camwb;
using namespace camwb::sim;
using namespace camwb::sim::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

double zTop(const TriDexel& s, int i, int j) { return s.spans(2, i, j).empty() ? -1 : s.spans(2, i, j).back().hi; }

}  // namespace

TEST(SimTriDexel, AgreesWithTheHeightFieldOnThreeAxisCuts)
{
    const base::Box3 b = box({0, 0, 0}, {40, 30, 20});
    HeightField field(b, 0.2);
    TriDexel dexels(b, 0.2);
    const ToolShape ball(makeTool("ball", 6)), flat(makeTool("flat", 4));
    const std::vector<std::pair<Move, const ToolShape*>> cuts = {
        {makeMove({5, 10.05, 25}, {5, 10.05, 16}), &flat},
        {makeMove({5, 10.05, 16}, {35, 10.05, 16}), &flat},
        {makeMove({5, 20.1, 18}, {35, 22.1, 15}), &ball},
        {makeMove({35, 22.1, 15}, {20, 8.1, 17}), &ball},
    };
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        const double hf = field.cut(cuts[k].first, k, *cuts[k].second).removedMm3;
        const double dx = dexels.cut(cuts[k].first, k, *cuts[k].second).removedMm3;
        EXPECT_NEAR(dx, hf, 0.02 * hf + 1) << "move " << k;
    }
    EXPECT_NEAR(dexels.volumeMm3(), field.volumeMm3(), 0.002 * field.volumeMm3());
    EXPECT_NEAR(dexels.gridVolumeMm3(2), field.volumeMm3(), 0.001 * field.volumeMm3());
    // The Z rays and the columns share a grid: the same tops to within the poses' cusps, except
    // on steep walls, where a cusp a twentieth of a cell across (TriDexel::posesAlong) moves the
    // top by the wall's slope times that: there within the tops of the neighbouring columns, and
    // on few columns (the walls steeper than 63 degrees).
    double worst = 0;
    int onWalls = 0;
    const int nx = field.columnsX(), ny = field.columnsY();
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double z = zTop(dexels, i, j);
            if (std::abs(z - field.top(i, j)) < 0.02)
                continue;
            ++onWalls;
            double lo = INFINITY, hi = -INFINITY;
            for (int nj = std::max(0, j - 1); nj <= std::min(ny - 1, j + 1); ++nj)
                for (int ni = std::max(0, i - 1); ni <= std::min(nx - 1, i + 1); ++ni)
                    lo = std::min(lo, field.top(ni, nj)), hi = std::max(hi, field.top(ni, nj));
            worst = std::max({worst, lo - z, z - hi});
        }
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(onWalls, nx * ny / 100);  // 130 of 30,000 here
}

TEST(SimTriDexel, CutsAnUndercutAZMapCannot)
{
    // A flat tool lying along X (its tip towards -X) bores in from the side at z = 5: the
    // material above the bore stays, so a Z ray through it holds two spans.
    const base::Box3 b = box({0, 0, 0}, {40, 40, 20});
    TriDexel dexels(b, 0.2);
    HeightField field(b, 0.2);
    const ToolShape tool(makeTool("flat", 6, 0, 30, 40));
    Move bore = makeMove({45, 20.1, 5.1}, {20, 20.1, 5.1});
    bore.setAxis({1, 0, 0});
    const double removed = dexels.cut(bore, 0, tool).removedMm3;
    EXPECT_NEAR(removed, kPi * 9 * 20, 0.02 * kPi * 9 * 20);
    const auto& spans = dexels.spans(2, 150, 100);  // x = 30.1, y = 20.1
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].hi, 2.1, 0.05);
    EXPECT_NEAR(spans[1].lo, 8.1, 0.05);
    EXPECT_NEAR(spans[1].hi, 20, 1e-6);
    // The height field can only lower the column to the tool's lowest point: it loses the top.
    field.cut(bore, 0, tool);
    EXPECT_NEAR(field.top(150, 100), 2.1, 0.05);
    EXPECT_GT(b.max.z - b.min.z, 0);
}

TEST(SimTriDexel, GougeAndShortHolderAreReported)
{
    TriDexel stock(box({0, 0, 0}, {60, 40, 20}), 0.2);
    TriangleMesh design = boxMesh({0, 0, 0}, {60, 40, 10});
    append(design, boxMesh({0, 30, 0}, {60, 40, 20}));
    stock.setDesign(design, 0.01);
    const ToolShape tool(makeTool("flat", 10));
    EXPECT_EQ(stock.cut(makeMove({5, 25, 10}, {55, 25, 10}), 0, tool).gougeMm, 0);
    const CutResult into = stock.cut(makeMove({55, 25.5, 10}, {5, 25.5, 10}), 1, tool);
    EXPECT_NEAR(into.gougeMm, 0.5, 0.2);
    EXPECT_GT(stock.compare().maxGougeMm, 0.3);

    TriDexel deep(box({0, 0, 0}, {100, 100, 60}), 0.5);
    const ToolShape stubby(makeTool("flat", 10, 0, 45, 50, "ER32"));
    double worst = 0;
    std::size_t index = 0;
    for (double z = 55; z >= 5; z -= 5) {
        Vec3 at{45, 45, z};
        for (const Vec3& next : {Vec3{55, 45, z}, Vec3{55, 55, z}, Vec3{45, 55, z}, Vec3{45, 45, z}}) {
            const CutResult r = deep.cut(makeMove(at, next), index++, stubby);
            if (z >= 10)
                EXPECT_EQ(r.holderInterferenceMm, 0) << "z " << z;
            worst = std::max(worst, r.holderInterferenceMm);
            at = next;
        }
    }
    EXPECT_NEAR(worst, 5, 1e-3);
}

TEST(SimTriDexel, BlankWithACavityAndTheMeshVolume)
{
    TriangleMesh blank = boxMesh({0, 0, 0}, {20, 20, 20});
    TriangleMesh cavity = boxMesh({5, 5, 5}, {15, 15, 15});
    for (std::size_t t = 0; t < cavity.triangleCount(); ++t)  // inward-facing: a hollow
        std::swap(cavity.triangles[3 * t + 1], cavity.triangles[3 * t + 2]);
    append(blank, cavity);
    const auto stock = TriDexel::fromMesh(blank, 0.5);
    EXPECT_EQ(stock->spans(2, 20, 20).size(), 2u);
    EXPECT_NEAR(stock->volumeMm3(), 8000 - 1000, 1e-3);
    const ToolShape tool(makeTool("ball", 4));
    stock->cut(makeMove({-5, 10, 18}, {25, 12, 18}), 0, tool);
    const TriangleMesh m = stock->mesh();
    const auto path = (std::filesystem::temp_directory_path() / "camwb_tridexel_test.stl").string();
    ASSERT_TRUE(writeStl(m, path).ok());
    std::size_t triangles = 0;
    EXPECT_NEAR(stlVolume(path, triangles), stock->gridVolumeMm3(2), 1e-3 * stock->gridVolumeMm3(2));
    std::filesystem::remove(path);
}

// The size a stock is weighed by is the grid its constructor makes: columns of a height field,
// rays of the three tri-dexel grids.
TEST(SimMakeStock, SizeCountsTheCellsTheStockMakes)
{
    const base::Box3 b = box({-3, 0, 0}, {97, 50.2, 20});
    for (const double resolution : {0.5, 0.3, 1.7}) {
        const HeightField field(b, resolution);
        EXPECT_EQ(stockSize(b, resolution, false).cells, double(field.columnsX()) * field.columnsY()) << resolution;
        const TriDexel dexels(b, resolution);
        double rays = 0;
        for (int axis = 0; axis < 3; ++axis)
            rays += double(dexels.rays(axis).nu) * dexels.rays(axis).nv;
        EXPECT_EQ(stockSize(b, resolution, true).cells, rays) << resolution;
        EXPECT_GT(stockSize(b, resolution, true).bytes, stockSize(b, resolution, false).bytes);
    }
}

// What the size check weighs a stock by covers what the stock holds, its design model included
// (the rest of the estimate is its meshes); a copy holds as much as the original.
TEST(SimMakeStock, SizeCoversWhatTheStockHolds)
{
    const base::Box3 b = box({0, 0, 0}, {40, 30, 20});
    const TriangleMesh part = boxMesh({5, 5, 0}, {35, 25, 12});
    for (const bool tilts : {false, true}) {
        std::unique_ptr<Stock> stock = makeStock(b, 0.25, tilts);
        const std::size_t bare = stock->memoryBytes();
        stock->setDesign(part, 0.02);
        const std::size_t withDesign = stock->memoryBytes();
        EXPECT_GT(withDesign, bare);
        const StockSize size = stockSize(b, 0.25, tilts);
        EXPECT_GT(double(bare), size.cells * (tilts ? 56 : 4)) << tilts;  // the cells' own data, at least
        // A block's columns hold their tops only: its floor is one number, and the last cuts
        // come with the design (megabytes at 0.1 mm that a command spent faulting in).
        if (!tilts)
            EXPECT_LT(double(bare), size.cells * 5);
        EXPECT_LT(double(withDesign), 0.5 * size.bytes) << tilts;  // room left for the meshes
        EXPECT_EQ(stock->clone()->memoryBytes(), withDesign) << tilts;
    }
}

// A stock larger than the memory it may take is refused with the finest resolution that fits,
// and that resolution is the finest: a cell finer no longer fits.
TEST(SimMakeStock, TooLargeAStockNamesTheFinestResolutionThatFits)
{
    const base::Box3 b = box({0, 0, 0}, {300, 200, 50});
    const double budget = 1e9;
    EXPECT_FALSE(stockTooLarge(b, 0.5, false, budget));
    EXPECT_FALSE(stockTooLarge(b, 0.5, true, budget));
    for (const bool tilts : {false, true}) {
        const std::optional<std::string> why = stockTooLarge(b, 0.02, tilts, budget);
        ASSERT_TRUE(why);
        EXPECT_NE(why->find(tilts ? "tri-dexel stock of 300.0 x 200.0 x 50.0 mm at 0.0200 mm"
                                  : "height field stock of 300.0 x 200.0 x 50.0 mm at 0.0200 mm"),
                  std::string::npos)
            << *why;
        const std::string fits = "the finest resolution that fits is ";
        const std::size_t at = why->find(fits);
        ASSERT_NE(at, std::string::npos) << *why;
        const double finest = std::stod(why->substr(at + fits.size()));
        EXPECT_LE(stockSize(b, finest, tilts).bytes, budget) << finest;
        EXPECT_GT(stockSize(b, finest - kFinestCellMm, tilts).bytes, budget) << finest;
        EXPECT_FALSE(stockTooLarge(b, finest, tilts, budget));
    }
}

// A stock reaching 100 m or more from the origin is a typo or a unit mix-up: refused by name,
// not measured in columns with three hundred digits. A blank's mesh is held to the same.
TEST(SimMakeStock, StockBeyondAnyMachineIsRefusedNamingTheSide)
{
    EXPECT_FALSE(stockBeyondReach(box({-kStockReachMm, 0, 0}, {kStockReachMm, 10, 10})));
    const std::optional<std::string> far = stockBeyondReach(box({0, 0, 0}, {1e300, 10, 10}));
    ASSERT_TRUE(far);
    EXPECT_EQ(*far, "the stock reaches more than 100 m from the workpiece origin (its x maximum): no machine holds "
                    "such a workpiece; check the stock's numbers and units");
    EXPECT_NE(stockBeyondReach(box({0, -2e5, 0}, {10, 10, 10}))->find("(its y minimum)"), std::string::npos);
    StockSpec spec;
    spec.blank = boxMesh({0, 0, -1.5e5}, {10, 10, 10});
    const auto made = makeStock(spec, false);
    ASSERT_FALSE(made);
    EXPECT_NE(made.error().message.find("(its z minimum)"), std::string::npos) << made.error().message;
}

// Asked for a stock no computer holds, simulate() cuts nothing and says why, without trying to
// make it (which would take the process down).
TEST(SimMakeStock, SimulateRefusesAStockBeyondMemory)
{
    StockSpec spec;
    spec.box = box({0, 0, 0}, {5000, 5000, 100});
    spec.resolutionMm = 1e-9;  // a micrometre's cells: 2.5e13 columns
    const auto made = makeStock(spec, false);
    ASSERT_FALSE(made);
    EXPECT_NE(
        made.error().message.find("height field stock of 5000.0 x 5000.0 x 100.0 mm at 0.001 mm (no cell is finer)"),
        std::string::npos)
        << made.error().message;
    toolpath::Toolpath program;
    SimulationSetup setup;
    setup.stockSpec = &spec;
    const SimulationResult result = simulate(program, setup);
    EXPECT_FALSE(result.cut);
    EXPECT_FALSE(result.stock);
    EXPECT_EQ(result.stockError, made.error().message);
    spec.resolutionMm = 50;
    EXPECT_TRUE(makeStock(spec, true));
    EXPECT_TRUE(simulate(program, setup).cut);
}

TEST(SimTriDexel, FactoryPicksTheRepresentation)
{
    const base::Box3 b = box({0, 0, 0}, {10, 10, 10});
    EXPECT_NE(dynamic_cast<HeightField*>(makeStock(b, 0.5, false).get()), nullptr);
    EXPECT_NE(dynamic_cast<TriDexel*>(makeStock(b, 0.5, true).get()), nullptr);
    EXPECT_NE(dynamic_cast<TriDexel*>(makeStockFromMesh(boxMesh({0, 0, 0}, {5, 5, 5}), 0.5, true).get()), nullptr);
    MoveList list;
    list.moves.push_back(makeMove({0, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(anyToolTilts(list));
    list.moves.back().setToAxis(Vec3{1, 0, 1}.normalized());
    EXPECT_TRUE(anyToolTilts(list));
}

// A tool square to a floor tilted 30 degrees, its tip on the floor, touches the part and goes no
// deeper: no gouge. 0.5 mm deeper is a gouge of about 0.5 mm, not the part's length the Y rays
// (along the floor) see: each removed point's depth is the least of the three grids' rays.
TEST(SimTriDexel, AToolOnATiltedFloorIsNoGouge)
{
    const double s = std::sin(kPi / 6), c = std::cos(kPi / 6);
    TriangleMesh design = boxMesh({-20, -20, -20}, {20, 20, 0});
    for (std::size_t v = 0; v < design.vertexCount(); ++v) {  // turned 30 degrees about Y
        const float x = design.positions[3 * v], z = design.positions[3 * v + 2];
        design.positions[3 * v] = float(c * x + s * z);
        design.positions[3 * v + 2] = float(-s * x + c * z);
    }
    const Vec3 normal{s, 0, c};
    base::Box3 bounds = design.bounds();
    bounds.max = bounds.max + Vec3{0, 0, 10};
    const ToolShape drill(makeTool("flat", 6));
    for (const double deeper : {0.0, 0.5}) {
        TriDexel stock(bounds, 0.1);
        stock.setDesign(design, 0.02 + 0.05);
        const Vec3 onFloor{2 * c, 3, -2 * s};  // a point of the tilted floor off its centre
        Move plunge = makeMove(onFloor + normal * 8, onFloor + normal * -deeper);
        plunge.setAxis(normal);
        const CutResult cut = stock.cut(plunge, 0, drill);
        EXPECT_GT(cut.removedMm3, 0);
        if (deeper == 0)
            EXPECT_EQ(cut.gougeMm, 0) << "at " << cut.gougeAt.x << ", " << cut.gougeAt.y << ", " << cut.gougeAt.z;
        else
            EXPECT_NEAR(cut.gougeMm, 0.5, 0.2);
    }
}

// A tilted tool that retracts along the path it has just cut removes nothing: the spans' float
// ends, cut again, are not material (they once summed to 0.0005 mm³ "removed at rapid").
TEST(SimTriDexel, RetractingAlongItsOwnCutRemovesNothing)
{
    TriDexel stock(box({10, 10, 0}, {40, 40, 30}), 0.1);
    const double s = std::sin(kPi / 6), c = std::cos(kPi / 6);
    const Vec3 axis{-s, 0, c}, bottom{27, 25, 20};
    const ToolShape drill(makeTool("flat", 6));
    Move plunge = makeMove(bottom + axis * 12, bottom);
    plunge.setAxis(axis);
    EXPECT_GT(stock.cut(plunge, 0, drill).removedMm3, 50);
    Move retract = makeMove(bottom, bottom + axis * 12, MoveKind::Rapid);
    retract.setAxis(axis);
    EXPECT_EQ(stock.cut(retract, 1, drill).removedMm3, 0);
}

namespace {

// A 20 x 20 x 10 block with a flat-bottomed hole of radius 3, `depth` deep, down its top's
// centre, turned 30 degrees about Y: the five-axis example's holes, square to an inclined face.
// The hole's wall is a polygon of 128 sides through the circle (0.001 mm inside it).
TriangleMesh tiltedBlockWithHole(double depth)
{
    constexpr int n = 128;
    TriangleMesh m;
    auto add = [&m](double x, double y, double z) {
        m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
        return std::uint32_t(m.vertexCount() - 1);
    };
    auto tri = [&m](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.triangles.insert(m.triangles.end(), {a, b, c});
    };
    std::vector<std::uint32_t> rim, floor, edge;
    for (int k = 0; k < n; ++k) {
        const double t = kPi / 4 + 2 * kPi * k / n, cx = std::cos(t), sy = std::sin(t);
        const double square = 10 / std::max(std::abs(cx), std::abs(sy));  // the top's edge in this direction
        rim.push_back(add(3 * cx, 3 * sy, 0));
        floor.push_back(add(3 * cx, 3 * sy, -depth));
        edge.push_back(add(square * cx, square * sy, 0));
    }
    const std::uint32_t floorCentre = add(0, 0, -depth);
    for (int k = 0; k < n; ++k) {
        const int l = (k + 1) % n;
        tri(rim[k], edge[k], edge[l]);  // the top around the hole, facing +z
        tri(rim[k], edge[l], rim[l]);
        tri(rim[k], rim[l], floor[l]);  // the wall, facing the hole's axis
        tri(rim[k], floor[l], floor[k]);
        tri(floorCentre, floor[k], floor[l]);  // the hole's floor, facing +z
    }
    // The block's four sides and bottom; the top's edge points lie on the sides' upper edges.
    const std::uint32_t c[8] = {add(-10, -10, -10), add(10, -10, -10), add(10, 10, -10), add(-10, 10, -10),
                                add(-10, -10, 0),   add(10, -10, 0),   add(10, 10, 0),   add(-10, 10, 0)};
    tri(c[0], c[2], c[1]), tri(c[0], c[3], c[2]);
    for (int s = 0; s < 4; ++s) {
        const int t = (s + 1) % 4;
        tri(c[s], c[t], c[4 + t]), tri(c[s], c[4 + t], c[4 + s]);
    }
    const double sn = std::sin(kPi / 6), cs = std::cos(kPi / 6);
    for (std::size_t v = 0; v < m.vertexCount(); ++v) {
        const float x = m.positions[3 * v], z = m.positions[3 * v + 2];
        m.positions[3 * v] = float(cs * x + sn * z);
        m.positions[3 * v + 2] = float(-sn * x + cs * z);
    }
    return m;
}

}  // namespace

// A flat D6 tool square to the inclined face, plunged exactly to the floor of a D6 hole, fits the
// hole: no gouge, neither while it cuts nor in the finished stock. The stock's faces next to the
// hole stand up to half a cell off its wall, which the X rays grazing the floor read as 0.19 mm
// into the part (the five-axis example's read-back showed that "gouge" with no block): a point
// the rays put inside is as deep as its exact distance from the part. 0.4 mm deeper is a gouge,
// found at that move.
TEST(SimTriDexel, AToolThatFitsATiltedHoleIsNoGouge)
{
    const TriangleMesh design = tiltedBlockWithHole(8);
    EXPECT_NEAR(design.volumeMm3(), 4000 - kPi * 9 * 8, 0.5);
    const double sn = std::sin(kPi / 6), cs = std::cos(kPi / 6);
    const Vec3 axis{sn, 0, cs}, floorCentre = axis * -8;
    const ToolShape drill(makeTool("flat", 6));
    for (const double deeper : {0.0, 0.4}) {
        std::unique_ptr<TriDexel> stock = TriDexel::fromMesh(tiltedBlockWithHole(1e-3), 0.1);
        stock->setDesign(design, 0.02 + 0.05);
        Move plunge = makeMove(floorCentre + axis * 12, floorCentre - axis * deeper);
        plunge.setAxis(axis);
        const CutResult cut = stock->cut(plunge, 7, drill);
        EXPECT_GT(cut.removedMm3, 200);
        const Deviation deviation = stock->compare();
        if (deeper == 0) {
            EXPECT_EQ(cut.gougeMm, 0) << "at " << cut.gougeAt.x << ", " << cut.gougeAt.y << ", " << cut.gougeAt.z;
            EXPECT_EQ(deviation.maxGougeMm, 0)
                << "at " << deviation.gougeAt.x << ", " << deviation.gougeAt.y << ", " << deviation.gougeAt.z;
        } else {
            EXPECT_NEAR(cut.gougeMm, 0.4, 0.1);
            EXPECT_NEAR(deviation.maxGougeMm, 0.4, 0.1);
            EXPECT_EQ(deviation.gougeMove, 7);
        }
    }
}

namespace {

// `move` cut as pieces no longer than a quarter of a cell, their axes turned evenly as the move's:
// poses that close stand for the tool's continuous sweep.
std::vector<Move> finePieces(const Move& move, double cell, double flute)
{
    const double turn = move.fromAxis().angleTo(move.toAxis()) * flute;
    const int n = std::max(1, int(std::ceil(std::max(move.lengthMm(), turn) / (cell / 4))));
    std::vector<Move> pieces;
    for (int k = 0; k < n; ++k) {
        Move piece = move;
        piece.from = move.from + (move.to - move.from) * (double(k) / n);
        piece.to = move.from + (move.to - move.from) * (double(k + 1) / n);
        piece.setFromAxis(move.axisAt(double(k) / n));
        piece.setToAxis(move.axisAt(double(k + 1) / n));
        pieces.push_back(piece);
    }
    return pieces;
}

}  // namespace

// The length of `whole`'s material along a ray that `deep` has removed: 0 when every span of
// `whole` lies within `deep`'s spans.
double materialOutside(const std::vector<TriDexel::Span>& whole, const std::vector<TriDexel::Span>& deep)
{
    double outside = 0;
    for (const TriDexel::Span& w : whole) {
        double covered = 0;
        for (const TriDexel::Span& d : deep)
            covered += std::max(0.0, double(std::min(w.hi, d.hi)) - std::max(w.lo, d.lo));
        outside = std::max(outside, double(w.hi) - w.lo - covered);
    }
    return outside;
}

// A cut steps its poses farther apart than half a cell where the cutter's curvature allows
// (TriDexel::posesAlong), but what it leaves must stay within a twentieth of a cell of the
// tool's sweep, or where half a cell apart leaves more (a flat end's rim on a move that rises to
// it), within what half a cell leaves. Measured against the same moves cut in pieces a quarter of a
// cell long by the tool shrunk by that much (tip raised, radius and corner less): the long move
// must remove all that removes, on every ray of the three grids, for the round cutters along
// straight and ramping moves (one deeper than the flute), a turning five-axis move and a plunge
// along a tilted axis, for a drill along that plunge (elsewhere a pointed tool keeps half a cell).
TEST(SimTriDexel, ALongMoveRemovesItsSweepToATwentiethOfACell)
{
    const double cell = 0.3, shortfall = cell / 20, flute = 12;
    const base::Box3 b = box({0, 0, 0}, {40, 30, 20});
    struct Cutter {
        std::string kind;
        double diameter, corner, pointAngle = 0;
    };
    const std::vector<Cutter> cutters = {{"flat", 6, 0}, {"ball", 6, 3}, {"bull", 8, 1}, {"drill", 6, 0, 118}};
    // The cutter shrunk by `shrink` all round when its tip is raised by `rise`: its top stays
    // `shrink` below the whole cutter's.
    const auto toolOf = [&](const Cutter& k, double shrink, double rise) {
        toolpath::Tool tool =
            makeTool(k.kind, k.diameter - 2 * shrink, std::max(0.0, k.corner - shrink), flute - rise - shrink);
        tool.pointAngleDeg = k.pointAngle;
        return tool;
    };
    const double s = std::sin(kPi / 6), c = std::cos(kPi / 6);
    std::vector<Move> moves = {
        makeMove({4, 5, 17}, {36, 24, 17}),   // across the grid
        makeMove({4, 15, 20}, {36, 15, 12}),  // a ramp of 14 degrees
        makeMove({6, 6, 19}, {16, 16, 9}),    // down at 35 degrees to the radial plane
        makeMove({4, 25, 10}, {36, 25, 4}),   // deeper than the flute: its top rim cuts too
    };
    Move swarf = makeMove({8, 12, 15}, {32, 18, 14});  // the axis turns 40 degrees on the way
    swarf.setFromAxis({-s, 0, c});
    swarf.setToAxis(Vec3{s * 0.5, -s * 0.8, c}.normalized());
    swarf.fiveAxis = true;
    moves.push_back(swarf);
    Move plunge = makeMove(Vec3{20, 15, 6} + swarf.fromAxis() * 20, {20, 15, 6});  // along its tilted axis
    plunge.setAxis(swarf.fromAxis());
    moves.push_back(plunge);
    for (std::size_t t = 0; t < cutters.size(); ++t)
        for (std::size_t m = 0; m < moves.size(); ++m) {
            const Cutter& k = cutters[t];
            if (k.pointAngle > 0 && m + 1 < moves.size())
                continue;  // a pointed tool steps half a cell apart but along its axis
            // A rim (a flat end's, or the top's where it reaches into the stock) leaves
            // step * sin(a) * cos(a), the step at least half a cell.
            double e = shortfall;
            const double lowestTip = std::min(moves[m].from.z, moves[m].to.z);
            if (k.kind == "flat" || lowestTip + flute - k.diameter / 2 < 20) {
                const Vec3 d = moves[m].to - moves[m].from;
                for (const Vec3& axis : {moves[m].fromAxis(), moves[m].axisAt(0.5), moves[m].toAxis()}) {
                    const double sinA = std::abs(d.dot(axis)) / d.length();
                    e = std::max(e, cell / 2 * sinA * std::sqrt(1 - sinA * sinA));
                }
            }
            TriDexel whole(b, cell), deep(b, cell);
            whole.cut(moves[m], 0, ToolShape(toolOf(k, 0, 0)));
            // The point's cone shrunk by e: its tip rises e / sin(half its angle).
            const double rise = k.pointAngle > 0 ? e / std::sin(k.pointAngle / 2 * kPi / 180) : e;
            const ToolShape shrunk(toolOf(k, e, rise));
            for (Move piece : finePieces(moves[m], cell, flute)) {
                piece.from = piece.from + piece.fromAxis() * rise;
                piece.to = piece.to + piece.toAxis() * rise;
                deep.cut(piece, 0, shrunk);
            }
            ASSERT_GT(40 * 30 * 20 - deep.volumeMm3(), 50) << "tool " << t << " move " << m;
            for (int a = 0; a < 3; ++a) {
                double worst = 0;
                for (int j = 0; j < whole.rays(a).nv; ++j)
                    for (int i = 0; i < whole.rays(a).nu; ++i)
                        worst = std::max(worst, materialOutside(whole.spans(a, i, j), deep.spans(a, i, j)));
                EXPECT_LT(worst, 1e-4) << "tool " << t << " move " << m << " grid " << a;
            }
        }
}
