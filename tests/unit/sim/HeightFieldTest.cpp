// The height field against analytic cuts: a flat slot's width, depth and volume, a ball's scallop,
// a bull-nose's corner, a pocket's volume, air moves, a gouge into a wall at its move, a holder
// too short for a deep pocket, the plunge flag, the mesh (closed, STL volume, rectangle update).
#include "sim/HeightField.h"
#include "StockTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace camwb;
using namespace camwb::sim;
using namespace camwb::sim::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The column nearest to (x, y).
std::pair<int, int> at(const HeightField& f, double x, double y)
{
    const double dx = (f.bounds().max.x - f.bounds().min.x) / f.columnsX();
    const double dy = (f.bounds().max.y - f.bounds().min.y) / f.columnsY();
    return {int((x - f.bounds().min.x) / dx), int((y - f.bounds().min.y) / dy)};
}

double topAt(const HeightField& f, double x, double y)
{
    const auto [i, j] = at(f, x, y);
    return f.top(i, j);
}

}  // namespace

TEST(SimHeightField, FlatSlotHasItsWidthDepthAndVolume)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    keepLastCuts(stock);
    const ToolShape tool(makeTool("flat", 10));
    const double before = stock.volumeMm3();
    EXPECT_NEAR(before, 60 * 40 * 20, 1e-6);
    double removed = stock.cut(makeMove({10, 20, 25}, {10, 20, 15}), 0, tool).removedMm3;
    removed += stock.cut(makeMove({10, 20, 15}, {50, 20, 15}), 1, tool).removedMm3;
    // 40 x 10 between the ends, two half discs of radius 5, 5 deep. Sampling the round ends at
    // column centres errs by far less than a cell times their length: 0.5 % is a stated bound.
    const double expected = (40 * 10 + kPi * 25) * 5;
    EXPECT_NEAR(removed, expected, 0.005 * expected);
    EXPECT_NEAR(before - stock.volumeMm3(), removed, 1e-6 * expected);
    // Width: the columns whose centres lie within 5 of the line y = 20 are cut, no others.
    EXPECT_DOUBLE_EQ(topAt(stock, 30, 15.05), 15);
    EXPECT_DOUBLE_EQ(topAt(stock, 30, 24.95), 15);
    EXPECT_DOUBLE_EQ(topAt(stock, 30, 14.95), 20);
    EXPECT_DOUBLE_EQ(topAt(stock, 30, 25.05), 20);
    EXPECT_DOUBLE_EQ(topAt(stock, 54.95, 20), 15);
    EXPECT_DOUBLE_EQ(topAt(stock, 55.05, 20), 20);
    EXPECT_EQ(stock.lastCut(at(stock, 30, 20).first, at(stock, 30, 20).second), 1);
}

TEST(SimHeightField, BallScallopBetweenTwoPassesIsTheFormula)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const double r = 5, p = 2;
    const ToolShape tool(makeTool("ball", 2 * r));
    // Passes at y = 20.05 and 22.05, so that y = 21.05 (between them) is a column centre.
    stock.cut(makeMove({5, 20.05, 15}, {55, 20.05, 15}), 0, tool);
    stock.cut(makeMove({55, 22.05, 15}, {5, 22.05, 15}), 1, tool);
    const double scallop = r - std::sqrt(r * r - p * p / 4);  // ~ p^2 / (8 R)
    EXPECT_NEAR(topAt(stock, 30, 21.05) - 15, scallop, 1e-4);
    EXPECT_NEAR(topAt(stock, 30, 20.05), 15, 1e-5);  // under each pass the ball's bottom
    // Beside a pass the ball's section: z = R - sqrt(R^2 - d^2) at d = 3 (a column centre).
    EXPECT_NEAR(topAt(stock, 30, 17.05) - 15, r - std::sqrt(r * r - 9), 1e-4);
}

TEST(SimHeightField, BullNoseLeavesItsCornerRadius)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const double r = 5, rc = 2;
    const ToolShape tool(makeTool("bull", 2 * r, rc));
    stock.cut(makeMove({5, 20.05, 15}, {55, 20.05, 15}), 0, tool);
    for (double d : {0.0, 2.9, 3.3, 3.9, 4.5, 4.9}) {  // flat to r - rc, then the corner's arc
        const double off = std::max(0.0, d - (r - rc));
        EXPECT_NEAR(topAt(stock, 30, 20.05 + d) - 15, rc - std::sqrt(rc * rc - off * off), 1e-4) << "d = " << d;
    }
    EXPECT_DOUBLE_EQ(topAt(stock, 30, 20.05 + 5.1), 20);
}

TEST(SimHeightField, RampingBallFollowsItsLowestPoint)
{
    // A ball ramping down along x: the column under the end point sees the ball's bottom there,
    // a column off the path the lowest of the ball's sections over the move (golden section).
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const ToolShape tool(makeTool("ball", 10));
    stock.cut(makeMove({10.05, 20.05, 20}, {50.05, 20.05, 16}), 0, tool);
    EXPECT_NEAR(topAt(stock, 50.05, 20.05), 16, 1e-5);
    // Off the path by 3 at x = 30: f(x) = z(x) + R - sqrt(R^2 - 9 - (x - x')^2) minimised over x.
    double best = 1e9;
    for (double x = 10.05; x <= 50.05; x += 1e-4) {
        const double dx = x - 30.05, d2 = 9 + dx * dx;
        if (d2 < 25)
            best = std::min(best, 20 - 4 * (x - 10.05) / 40 + 5 - std::sqrt(25 - d2));
    }
    EXPECT_NEAR(topAt(stock, 30.05, 23.05), best, 1e-4);
}

TEST(SimHeightField, FlatRampCutsToWhereTheColumnLastLiesUnderTheTool)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const ToolShape tool(makeTool("flat", 10));
    stock.cut(makeMove({10.05, 20.05, 20}, {50.05, 20.05, 16}), 0, tool);
    EXPECT_NEAR(topAt(stock, 50.05, 20.05), 16, 1e-5);
    // 3 off the path the column leaves the tool when the centre is 4 past it: x = 34.05.
    EXPECT_NEAR(topAt(stock, 30.05, 23.05), 20 - 4 * (34.05 - 10.05) / 40, 1e-5);
}

// The shortcuts for a flat tool that continues from where the last cut left it (start disc
// already cut) must change nothing: the same moves, each after a far-away move that breaks the
// chain, leave exactly the same tops.
TEST(SimHeightField, ContinuingMovesLeaveWhatSeparateMovesLeave)
{
    const base::Box3 b = box({0, 0, 0}, {40, 30, 10});
    HeightField chained(b, 0.1), separate(b, 0.1);
    const ToolShape tool(makeTool("flat", 6));
    std::vector<Vec3> path{{5, 5, 12}, {5, 5, 8}};
    for (int k = 0; k < 60; ++k) {  // a helix-like ramp down, then level arc pieces, then up
        const double a = 0.2 * k;
        path.push_back({20 + 6 * std::cos(a), 15 + 6 * std::sin(a),
                        k < 20   ? 8 - 0.1 * k
                        : k < 45 ? 6
                                 : 6 + 0.1 * (k - 45)});
    }
    const Move away = makeMove({100, 100, 50}, {101, 100, 50}, MoveKind::Rapid);
    for (std::size_t k = 1; k < path.size(); ++k) {
        chained.cut(makeMove(path[k - 1], path[k]), k, tool);
        separate.cut(away, 0, tool);
        separate.cut(makeMove(path[k - 1], path[k]), k, tool);
    }
    for (int j = 0; j < chained.columnsY(); ++j)
        for (int i = 0; i < chained.columnsX(); ++i)
            ASSERT_EQ(chained.top(i, j), separate.top(i, j)) << i << ", " << j;
    EXPECT_LT(chained.volumeMm3(), 40 * 30 * 10 - 100);
    // A wider tool starting where a narrow one stopped finds its start disc uncut: level and
    // going up, it must sweep the disc as a separate move does.
    const ToolShape narrow(makeTool("flat", 2)), wide(makeTool("flat", 8));
    for (const Vec3& end : {Vec3{30, 15, 6}, Vec3{30, 15, 7}}) {
        HeightField a(b, 0.1), c(b, 0.1);
        for (HeightField* s : {&a, &c}) {
            s->cut(makeMove({10, 15, 12}, {10, 15, 6}), 0, narrow);
            if (s == &c)
                s->cut(away, 1, narrow);
            s->cut(makeMove({10, 15, 6}, end), 2, wide);
        }
        EXPECT_NEAR(a.volumeMm3(), c.volumeMm3(), 1e-6) << "end z " << end.z;
        EXPECT_NEAR(topAt(a, 7.05, 15.05), 6, 1e-5) << "end z " << end.z;  // behind the start, in the disc
    }
}

TEST(SimHeightField, PocketRemovesAreaTimesDepth)
{
    // A 30 x 20 pocket 4 deep with a 6 mm flat tool: zig-zag at stepover 3 inside the tool-centre
    // rectangle and a last pass around it. The pocket keeps the tool's radius in its corners.
    HeightField stock(box({0, 0, 0}, {50, 40, 20}), 0.1);
    const ToolShape tool(makeTool("flat", 6));
    const double x0 = 10 + 3, x1 = 40 - 3, y0 = 10 + 3, y1 = 30 - 3, z = 16;
    std::vector<Move> moves{makeMove({x0, y0, 25}, {x0, y0, z})};
    bool right = true;
    for (double y = y0; y <= y1 + 1e-9; y += 3.5) {
        moves.push_back(makeMove(moves.back().to, {right ? x1 : x0, y, z}));
        if (y + 3.5 <= y1 + 1e-9)
            moves.push_back(makeMove(moves.back().to, {right ? x1 : x0, y + 3.5, z}));
        right = !right;
    }
    for (const Vec3& c : {Vec3{x0, y0, z}, Vec3{x1, y0, z}, Vec3{x1, y1, z}, Vec3{x0, y1, z}, Vec3{x0, y0, z}})
        moves.push_back(makeMove(moves.back().to, c));
    double removed = 0;
    for (std::size_t k = 0; k < moves.size(); ++k)
        removed += stock.cut(moves[k], k, tool).removedMm3;
    const double area = 30 * 20 - (4 - kPi) * 9;
    // Tolerance: the pocket's outline (~100 mm) times the depth times a fifth of a cell.
    EXPECT_NEAR(removed, area * 4, 100 * 4 * 0.1 / 5);
}

TEST(SimHeightField, MovesThroughAirRemoveNothing)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const ToolShape tool(makeTool("ball", 10));
    EXPECT_EQ(stock.cut(makeMove({-10, -10, 30}, {70, 50, 30}, MoveKind::Rapid), 0, tool).removedMm3, 0);
    EXPECT_EQ(stock.cut(makeMove({-10, -10, 10}, {70, -10, 10}), 1, tool).removedMm3, 0);  // beside it
    EXPECT_EQ(stock.cut(makeMove({30, 20, 20}, {40, 20, 20}), 2, tool).removedMm3, 0);     // on its top
    const double rapidIn = stock.cut(makeMove({30, 20, 30}, {30, 20, 19}, MoveKind::Rapid), 3, tool).removedMm3;
    EXPECT_NEAR(rapidIn, kPi / 3 * (3 * 5 - 1), 0.2);  // the ball's cap 1 deep: pi h^2 (3R - h) / 3
    EXPECT_NEAR(stock.volumeMm3(), 60 * 40 * 20 - rapidIn, 1e-6);
}

// A level move keeps its end disc's chords for the next move that starts there: a bigger tool
// starting at the same point must sweep its own disc there, not the last tool's.
TEST(SimHeightField, ABiggerToolStartingWhereTheLastEndedSweepsItsOwnDisc)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const ToolShape small(makeTool("flat", 6)), big(makeTool("flat", 12));
    stock.cut(makeMove({20, 10, 15}, {20, 20, 15}), 0, small);  // a slot up to (20, 20)
    EXPECT_EQ(topAt(stock, 15.05, 21.05), 20);                  // beside it
    stock.cut(makeMove({20, 20, 15}, {30, 20, 15}), 1, big);    // on to the right
    // The D12's round start on the rows the D6 crossed: 5.1 mm from its centre, and 6.05 mm.
    EXPECT_EQ(topAt(stock, 15.05, 21.05), 15);
    EXPECT_EQ(topAt(stock, 13.95, 20.05), 20);
}

// Beside the stock's edge the capsule can end between the edge and the first column's centre:
// that column is not under the tool (its index rounds down to -1, not towards zero to 0).
TEST(SimHeightField, ACutBesideTheStockLeavesTheColumnsItMisses)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    keepLastCuts(stock);
    const ToolShape tool(makeTool("flat", 10));
    // The tool's edge at x = 0.02 and y = 39.97; the first column's centre at 0.05, the last
    // row's at 39.95.
    EXPECT_EQ(stock.cut(makeMove({-4.98, 10, 15}, {-4.98, 30, 15}), 0, tool).removedMm3, 0);
    EXPECT_EQ(stock.cut(makeMove({20, 44.97, 15}, {40, 44.97, 15}), 1, tool).removedMm3, 0);
    EXPECT_EQ(stock.top(0, 200), 20);
    EXPECT_EQ(stock.lastCut(0, 200), -1);
    // A hair further in, the column is cut.
    EXPECT_GT(stock.cut(makeMove({-4.94, 10, 15}, {-4.94, 30, 15}), 2, tool).removedMm3, 0);
    EXPECT_EQ(stock.top(0, 200), 15);
}

// A long move over cleared ground is passed over by the tiles' bounds, but not one that meets the
// material left between the cleared ends, however little of its length does.
TEST(SimHeightField, LongMoveOverClearedGroundCutsOnlyWhereMaterialIsLeft)
{
    HeightField stock(box({0, 0, 0}, {100, 20, 10}), 0.1);
    keepLastCuts(stock);
    const ToolShape tool(makeTool("flat", 10));
    for (double y = 0; y <= 20; y += 5) {  // clears both ends down to z 5, leaving a web at x 45..55
        stock.cut(makeMove({-5, y, 5}, {40, y, 5}), 0, tool);
        stock.cut(makeMove({60, y, 5}, {105, y, 5}), 1, tool);
    }
    const double before = stock.volumeMm3();
    EXPECT_EQ(stock.cut(makeMove({-5, 10, 6}, {39, 10, 6}, MoveKind::Rapid), 2, tool).removedMm3, 0);
    EXPECT_EQ(stock.cut(makeMove({61, 10, 6}, {105, 10, 6}, MoveKind::Rapid), 3, tool).removedMm3, 0);
    const CutResult through = stock.cut(makeMove({-5, 10, 6}, {105, 10, 6}, MoveKind::Rapid), 4, tool);
    // 4 mm off the web under the 10 mm band: 20 mm long less the passes' end discs on each side.
    const double discs = 8 * (1.25 * std::sqrt(18.75) + 12.5 * kPi / 6);  // 2 x 4 quarter-pitch pieces
    EXPECT_NEAR(through.removedMm3, 4 * (20 * 10 - discs), 6);
    EXPECT_NEAR(stock.volumeMm3(), before - through.removedMm3, 1e-6);
    EXPECT_NEAR(topAt(stock, 50, 10), 6, 1e-6);
    EXPECT_EQ(stock.lastCut(at(stock, 50, 10).first, at(stock, 50, 10).second), 4);
}

TEST(SimHeightField, GougeIntoAWallIsReportedAtItsMove)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    TriangleMesh design = boxMesh({0, 0, 0}, {60, 40, 10});
    append(design, boxMesh({0, 30, 0}, {60, 40, 20}));  // a wall along the far side
    stock.setDesign(design, 0.01);
    const ToolShape tool(makeTool("flat", 10));
    const CutResult touching = stock.cut(makeMove({5, 25, 10}, {55, 25, 10}), 0, tool);
    EXPECT_GT(touching.removedMm3, 0);
    EXPECT_EQ(touching.gougeMm, 0);
    const CutResult into = stock.cut(makeMove({55, 25.5, 10}, {5, 25.5, 10}), 1, tool);
    EXPECT_NEAR(into.gougeMm, 0.5, 0.1);
    EXPECT_GT(into.gougeAt.y, 30);
    const Deviation dev = stock.compare();
    EXPECT_NEAR(dev.maxGougeMm, 0.5, 0.1);
    EXPECT_EQ(dev.gougeMove, 1);
    EXPECT_EQ(dev.perVertex.size(), stock.mesh().vertexCount());
    EXPECT_GT(dev.maxLeftoverMm, 5);  // the rest of the block above the floor was never cut
}

TEST(SimHeightField, HolderTooShortForADeepPocketIsReported)
{
    // A 20 x 20 pocket cleared in 5 mm steps down to 55 deep; the ER32 nut (radius 25) sits 50
    // above the tip, so it reaches the pocket's rim (at z 60) once the tip is below z 10.
    auto run = [](double stickOut) {
        HeightField stock(box({0, 0, 0}, {100, 100, 60}), 0.2);
        const ToolShape tool(makeTool("flat", 10, 0, 45, stickOut, "ER32"));
        double worst = 0, worstAbove10 = 0;
        std::size_t index = 0;
        for (double z = 55; z >= 5; z -= 5) {
            Vec3 at{45, 45, z};
            for (const Vec3& next : {Vec3{55, 45, z}, Vec3{55, 55, z}, Vec3{45, 55, z}, Vec3{45, 45, z}}) {
                const CutResult r = stock.cut(makeMove(at, next), index++, tool);
                (z >= 10 ? worstAbove10 : worst) = std::max(z >= 10 ? worstAbove10 : worst, r.holderInterferenceMm);
                at = next;
            }
        }
        return std::pair{worstAbove10, worst};
    };
    const auto [shortAbove, shortWorst] = run(50);
    EXPECT_EQ(shortAbove, 0);
    EXPECT_NEAR(shortWorst, 5, 1e-5);  // the rim at 60, the holder's face at 5 + 50
    EXPECT_EQ(run(80).second, 0);
}

TEST(SimHeightField, PlungingRemovesOnTheAxisAndCuttingAsideDoesNot)
{
    HeightField stock(box({0, 0, 0}, {60, 40, 20}), 0.1);
    const ToolShape tool(makeTool("flat", 10));
    EXPECT_TRUE(stock.cut(makeMove({20, 20, 25}, {20, 20, 15}), 0, tool).removedOnAxis);
    EXPECT_FALSE(stock.cut(makeMove({20, 20, 15}, {40, 20, 15}), 1, tool).removedOnAxis);
    EXPECT_FALSE(stock.cut(makeMove({40, 20, 15}, {50, 20, 14}), 2, tool).removedOnAxis);  // a ramp
    EXPECT_FALSE(stock.cut(makeMove({20, 20, 25}, {20, 20, 15}), 3, tool).removedOnAxis);  // air now
}

TEST(SimHeightField, MeshIsClosedItsStlHoldsTheVolumeAndUpdatesInPlace)
{
    HeightField stock(box({0, 0, 0}, {30, 20, 10}), 0.2);
    const ToolShape tool(makeTool("ball", 6));
    TriangleMesh shown = stock.mesh();
    stock.takeChanged();
    stock.cut(makeMove({-5, 10, 12}, {5, 10, 7}), 0, tool);
    stock.cut(makeMove({5, 10, 7}, {25, 13, 7}), 1, tool);
    const TriangleMesh m = stock.mesh();
    EXPECT_TRUE(closedAndOriented(m));
    const auto path = (std::filesystem::temp_directory_path() / "camwb_heightfield_test.stl").string();
    ASSERT_TRUE(writeStl(m, path).ok());
    std::size_t triangles = 0;
    // The mesh joins column centres linearly: its volume differs from the columns' by well under
    // the cut's outline (~60 mm) x its depth (3) x a cell.
    EXPECT_NEAR(stlVolume(path, triangles), stock.volumeMm3(), 60 * 3 * 0.2 / 4);
    EXPECT_EQ(triangles, m.triangleCount());
    std::filesystem::remove(path);
    const ColumnRect changed = stock.takeChanged();
    EXPECT_FALSE(changed.empty());
    stock.updateMesh(shown, changed);
    EXPECT_EQ(shown.positions, m.positions);
    EXPECT_TRUE(stock.takeChanged().empty());
}

// The file's mesh is the same closed surface with the flat areas merged: a pocket in a block
// (499 x 399 cells, an odd count) with floors at several depths, and a blank whose bottom is not flat.
TEST(SimHeightField, FileMeshIsTheSameSurfaceInFewerTriangles)
{
    HeightField pocket(box({0, 0, 0}, {49.9, 39.9, 20}), 0.1);
    const ToolShape tool(makeTool("flat", 6));
    pocket.cut(makeMove({13, 13, 25}, {13, 13, 16}), 0, tool);
    pocket.cut(makeMove({13, 13, 16}, {37, 27, 16}), 1, tool);
    pocket.cut(makeMove({37, 27, 16}, {20, 30, 12.5}), 2, ToolShape(makeTool("ball", 4)));
    // Flat floors at three depths with ragged, overlapping rims: rectangles of every shape meet
    // each other's corners along their edges.
    const ToolShape small(makeTool("flat", 3));
    for (int k = 0; k < 24; ++k) {
        const double x = 4 + (k * 7) % 41, y = 4 + (k * 11) % 31, z = 17 + k % 3;
        pocket.cut(makeMove({x, y, z}, {x + 3 + k % 5, y + 2 - k % 4, z}), 3 + k, small);
    }
    TriangleMesh blank = boxMesh({0, 0, 0}, {40, 30, 10});
    append(blank, boxMesh({0, 0, -5}, {10, 10, 0}));  // a foot under one corner
    const auto footed = HeightField::fromMesh(blank, 0.25);
    for (const Stock* stock : {static_cast<const Stock*>(&pocket), static_cast<const Stock*>(footed.get())}) {
        const TriangleMesh full = stock->mesh(), file = stock->fileMesh();
        EXPECT_TRUE(closedAndOriented(file));
        EXPECT_NEAR(file.volumeMm3(), full.volumeMm3(), 1e-6 * full.volumeMm3());
        EXPECT_NEAR(file.bounds().min.z, full.bounds().min.z, 1e-9);
        EXPECT_NEAR(file.bounds().max.z, full.bounds().max.z, 1e-9);
        EXPECT_LT(file.triangleCount() * 8, full.triangleCount())
            << file.triangleCount() << " of " << full.triangleCount();
    }
}

// An uncut block's top is one flat rectangle: a fan through the vertices its side walls use, and
// nothing inside (the top, the walls' two triangles per edge and the bottom: four per ring edge).
TEST(SimHeightField, FileMeshOfAnUncutBlockIsItsRingAndTwoFans)
{
    const HeightField stock(box({0, 0, 0}, {30, 20, 10}), 0.5);
    const TriangleMesh file = stock.fileMesh();
    const std::size_t ring = 2 * std::size_t(stock.columnsX() - 1 + stock.columnsY() - 1);
    EXPECT_TRUE(closedAndOriented(file));
    EXPECT_EQ(file.triangleCount(), 4 * ring);
    EXPECT_EQ(file.vertexCount(), 2 * ring + 2);  // only what the triangles use: two rings, two centres
    EXPECT_NEAR(file.volumeMm3(), 30 * 20 * 10, 1e-6);
}

TEST(SimHeightField, BlankFromAMeshFillsItsInside)
{
    TriangleMesh blank = boxMesh({0, 0, 0}, {40, 30, 10});
    append(blank, boxMesh({10, 10, 10}, {20, 20, 25}));  // a boss on top (overlapping union)
    const auto stock = HeightField::fromMesh(blank, 0.1);
    EXPECT_NEAR(stock->volumeMm3(), 40 * 30 * 10 + 10 * 10 * 15, 1e-3);
    EXPECT_TRUE(closedAndOriented(stock->mesh()));
    // The file's mesh makes the blank's bottom grid's vertices on use, as the top's.
    const TriangleMesh file = stock->fileMesh();
    EXPECT_TRUE(closedAndOriented(file));
    EXPECT_NEAR(file.volumeMm3(), 40 * 30 * 10 + 10 * 10 * 15, 1e-3);
    EXPECT_LT(file.vertexCount(), stock->mesh().vertexCount() / 10);
    auto copy = stock->clone();
    const ToolShape tool(makeTool("flat", 4));
    EXPECT_GT(copy->cut(makeMove({0, 0, 30}, {40, 30, 5}), 0, tool).removedMm3, 0);
    EXPECT_NEAR(stock->volumeMm3(), 40 * 30 * 10 + 10 * 10 * 15, 1e-3);  // the clone is a copy
}
