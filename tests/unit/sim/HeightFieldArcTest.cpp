// The height field's sweep of a flat tool along a level arc (HeightFieldArc.cpp): every column
// within the tool's radius of the true arc is cut and no other, for arcs wider and narrower than
// the tool, either way round and over more than a quarter turn; the arc's pieces cut one by one
// leave exactly what the run cut in one pass leaves; a run that starts where the tool stands
// leaves what it leaves after a move elsewhere; a helix cut in one pass (last piece first) leaves
// what its pieces cut in turn leave, holder findings too; the bound a span's fast skip compares with.
#include "StockTestUtil.h"
#include "sim/HeightField.h"
#include "sim/detail/HeightFieldRows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace camwb;
using namespace camwb::sim;
using namespace camwb::sim::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct LevelArc {
    base::Vec2 centre;
    double radius, fromAngle, toAngle, z;  // angles in radians; toAngle < fromAngle: clockwise
    double drop = 0;                       // a helix: how far it descends from z over the arc
};

// The arc's pieces as the move list makes them: ends on the circle, each from where the last ended.
std::vector<Move> pieces(const LevelArc& arc, int count)
{
    std::vector<Move> out;
    auto at = [&](int k) {
        const double a = arc.fromAngle + (arc.toAngle - arc.fromAngle) * k / count;
        return Vec3{arc.centre.x + arc.radius * std::cos(a), arc.centre.y + arc.radius * std::sin(a),
                    arc.z - arc.drop * k / count};
    };
    Vec3 from = at(0);
    for (int k = 1; k <= count; ++k) {
        Move m = makeMove(from, at(k));
        m.fromArc = true;
        m.arcCentre = arc.centre;
        m.arcRadius = arc.radius;
        m.record = 1;
        out.push_back(m);
        from = m.to;
    }
    return out;
}

// The distance of p from the arc: radial where its angle lies within the arc's, else to an end.
double distanceToArc(const LevelArc& arc, base::Vec2 p)
{
    const base::Vec2 w = p - arc.centre;
    const double lo = std::min(arc.fromAngle, arc.toAngle), hi = std::max(arc.fromAngle, arc.toAngle);
    double angle = std::atan2(w.y, w.x);
    while (angle < lo)
        angle += 2 * kPi;
    if (angle <= hi)
        return std::abs(w.length() - arc.radius);
    double best = 1e300;
    for (double a : {arc.fromAngle, arc.toAngle}) {
        const base::Vec2 end{arc.centre.x + arc.radius * std::cos(a), arc.centre.y + arc.radius * std::sin(a)};
        best = std::min(best, (p - end).length());
    }
    return best;
}

// Every column whose centre lies clearly within r of the arc is at the arc's height and marked as
// cut by move `moveIndex`, every one clearly beyond it untouched.
void expectSweptExactly(const HeightField& stock, const LevelArc& arc, double r, double top, std::int64_t moveIndex)
{
    int inside = 0;
    for (int j = 0; j < stock.columnsY(); ++j)
        for (int i = 0; i < stock.columnsX(); ++i) {
            const double d = distanceToArc(arc, {stock.columnX(i), stock.columnY(j)});
            if (d < r - 1e-6) {
                ++inside;
                ASSERT_EQ(stock.top(i, j), float(arc.z)) << "column " << i << ", " << j << " at " << d;
                ASSERT_EQ(stock.lastCut(i, j), moveIndex) << "column " << i << ", " << j;
            } else if (d > r + 1e-6) {
                ASSERT_EQ(stock.top(i, j), float(top)) << "column " << i << ", " << j << " at " << d;
            }
        }
    EXPECT_GT(inside, 1000);
}

}  // namespace

TEST(SimHeightFieldArc, ALevelArcCutsEveryColumnWithinTheToolOfTheArcAndNoOther)
{
    const base::Box3 b = box({0, 0, 0}, {40, 40, 10});
    const ToolShape tool(makeTool("flat", 6));
    const LevelArc arcs[] = {
        {{20.02, 19.97}, 8, 0.3, 0.3 + 200 * kPi / 180, 5},  // wider than the tool, anticlockwise, over a half turn
        {{20.02, 19.97}, 2, 0.5, 0.5 - 130 * kPi / 180, 5},  // narrower than the tool, clockwise
        {{20.02, 19.97}, 8, 0, kPi / 2, 5},                  // from an axis to an axis
    };
    for (const LevelArc& arc : arcs) {
        const std::vector<Move> run = pieces(arc, 47);
        HeightField together(b, 0.1), oneByOne(b, 0.1);
        keepLastCuts(together), keepLastCuts(oneByOne);
        const double removed = together.cutArcRun(run.data(), run.size(), 3, tool).removedMm3;
        double sum = 0;
        for (const Move& m : run)
            sum += oneByOne.cut(m, 3, tool).removedMm3;
        SCOPED_TRACE("arc of radius " + std::to_string(arc.radius));
        expectSweptExactly(together, arc, 3, 10, 3);
        expectSweptExactly(oneByOne, arc, 3, 10, 3);
        for (int j = 0; j < together.columnsY(); ++j)
            for (int i = 0; i < together.columnsX(); ++i)
                ASSERT_EQ(together.top(i, j), oneByOne.top(i, j)) << i << ", " << j;
        EXPECT_NEAR(removed, sum, 1e-9 * sum);
        EXPECT_NEAR(removed, 40 * 40 * 10 - together.volumeMm3(), 1e-6 * removed);
    }
}

// A run that starts where the last cut left the tool skips its start disc (already cut): it must
// leave what it leaves after a move elsewhere, which sweeps that disc itself.
TEST(SimHeightFieldArc, ARunFromWhereTheToolStandsLeavesWhatAFreshRunLeaves)
{
    const base::Box3 b = box({0, 0, 0}, {40, 40, 10});
    const ToolShape tool(makeTool("flat", 6));
    const LevelArc arc{{20, 20}, 7, -0.2, 2.5, 6};
    const std::vector<Move> run = pieces(arc, 30);
    const Move away = makeMove({100, 100, 50}, {101, 100, 50}, MoveKind::Rapid);
    HeightField chained(b, 0.1), separate(b, 0.1);
    for (HeightField* stock : {&chained, &separate}) {
        keepLastCuts(*stock);
        stock->cut(makeMove(run.front().from + Vec3{0, 0, 5}, run.front().from), 0, tool);  // down to the start
        if (stock == &separate)
            stock->cut(away, 1, tool);
        stock->cutArcRun(run.data(), run.size(), 2, tool);
    }
    for (int j = 0; j < chained.columnsY(); ++j)
        for (int i = 0; i < chained.columnsX(); ++i)
            ASSERT_EQ(chained.top(i, j), separate.top(i, j)) << i << ", " << j;
    for (int j = 0; j < chained.columnsY(); ++j)  // the plunge's disc stays its own
        for (int i = 0; i < chained.columnsX(); ++i)
            if ((base::Vec2{chained.columnX(i), chained.columnY(j)} - run.front().from.xy()).length() < 3 - 1e-6)
                ASSERT_EQ(chained.lastCut(i, j), 0);
}

// A helix's pieces each lower the disc under the tool a little deeper; the run cuts them from the
// last back and a flat tool's discs once (cutHelixRun). The stock (to the heights the field tells
// apart), each column's move and the holder's finding must be those of the pieces cut in turn,
// for helices narrower and wider than the tool, both ways round, up and down, over more than a
// turn, a level arc going on into a helix, with flat and ball tools, and with a holder that meets
// the stock.
TEST(SimHeightFieldArc, AHelixCutInOnePassLeavesWhatItsPiecesCutInTurnLeave)
{
    const base::Box3 b = box({0, 0, 0}, {40, 40, 10});
    const LevelArc helices[] = {
        {{20.02, 19.97}, 2, 0.3, 0.3 + 4 * kPi, 9, 4},  // narrower than the tool, two turns
        {{20.02, 19.97}, 8, 0.5, 0.5 - 3 * kPi, 8, 3},  // wider, clockwise, a turn and a half
        {{20.02, 19.97}, 8, 0.5, 0.5 + kPi, 6, -3},     // up
    };
    const toolpath::Tool tools[] = {makeTool("flat", 6), makeTool("ball", 6),
                                    makeTool("flat", 6, 0, 3, 4)};  // the holder 4 mm over the tip
    struct Run {
        std::string name;
        std::vector<Move> moves;
        bool descends = false;  // the holder meets the stock on the way down
    };
    std::vector<Run> runs;
    for (const LevelArc& helix : helices)
        runs.push_back({"helix of radius " + std::to_string(helix.radius) + " from z " + std::to_string(helix.z),
                        pieces(helix, 90), helix.drop > 0});
    // A level half turn going on into a helix down: one run whose pieces are not all level.
    Run mixed{"a level arc going on into a helix", pieces({{20.02, 19.97}, 8, 0.5, 0.5 + kPi, 6}, 40), true};
    for (const Move& m : pieces({{20.02, 19.97}, 8, 0.5 + kPi, 0.5 + 3 * kPi, 6, 3}, 90))
        mixed.moves.push_back(m);
    ASSERT_EQ(mixed.moves[39].to, mixed.moves[40].from);
    runs.push_back(std::move(mixed));
    for (const toolpath::Tool& t : tools)
        for (const Run& r : runs) {
            const ToolShape tool(t);
            const std::vector<Move>& run = r.moves;
            HeightField together(b, 0.1), inTurn(b, 0.1);
            keepLastCuts(together), keepLastCuts(inTurn);
            const CutResult once = together.cutArcRun(run.data(), run.size(), 3, tool);
            CutResult sum;
            for (const Move& m : run)
                sum.add(inTurn.cut(m, 3, tool));
            SCOPED_TRACE(t.kind + " flute " + std::to_string(t.fluteLengthMm) + ", " + r.name);
            int cut = 0;
            for (int j = 0; j < together.columnsY(); ++j)
                for (int i = 0; i < together.columnsX(); ++i) {
                    // A column two cuts bring within kEps of each other keeps the one that came first.
                    ASSERT_NEAR(together.top(i, j), inTurn.top(i, j), detail::kEps) << i << ", " << j;
                    ASSERT_EQ(together.lastCut(i, j), inTurn.lastCut(i, j)) << i << ", " << j;
                    cut += together.lastCut(i, j) == 3;
                }
            EXPECT_GT(cut, 1000);
            EXPECT_NEAR(once.removedMm3, sum.removedMm3, 1e-9 * sum.removedMm3 + cut * 0.01 * detail::kEps);
            EXPECT_NEAR(once.holderInterferenceMm, sum.holderInterferenceMm, detail::kEps);
            if (t.fluteLengthMm < 5 && r.descends)
                EXPECT_GT(once.holderInterferenceMm, 0.5);
        }
}

// The height field passes columns whose float top lies at or below this bound four at a time: it
// must be the highest float at or below the double, or a column just above would be left uncut.
TEST(SimHeightFieldArc, TheSkipBoundIsTheHighestFloatAtOrBelow)
{
    for (const double x : {0.0, 1e-30, -1e-30, 0.1, -0.1, 5.000001, -5.000001, 12.3456789, 1e6 + 0.3, -7.0}) {
        const float f = detail::floatAtOrBelow(x);
        EXPECT_LE(double(f), x) << x;
        EXPECT_GT(double(std::nextafter(f, std::numeric_limits<float>::infinity())), x) << x;
    }
}
