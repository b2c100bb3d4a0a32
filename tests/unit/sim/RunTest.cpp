// The simulation's checks on small programs whose answer is known: a feed move 0.5 mm into a
// wall is a gouge at that record, a rapid through the stock is an error at its record, a holder
// that sticks out too little for a deep pocket hits the stock, a tool that does not cut at its
// centre may ramp but not plunge, cutting with the spindle off is an error, a feed move in air is
// a note with its length, the machine's limits name their record, a gouge only the finished
// stock shows is an error too, and a feed move from an unknown position is a warning. A level arc's pieces are one run:
// judged together, cut piece by piece where the holder could reach the stock, and the same when cutTo stops inside it.
#include "sim/HeightField.h"
#include "sim/Simulation.h"
#include "sim/StockRun.h"
#include "sim/detail/HeightFieldRows.h"

#include "StockTestUtil.h"

#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace camwb;
using namespace camwb::toolpath;
using sim::CheckKind;
using sim::test::boxMesh;

namespace {

constexpr double kPiRun = 3.14159265358979323846;

Tool flat10(double stickOut = 40, bool centreCutting = true)
{
    Tool t;
    t.number = 1;
    t.diameterMm = 10;
    t.fluteLengthMm = std::min(25.0, stickOut);
    t.lengthMm = stickOut;
    t.centreCutting = centreCutting;
    return t;
}

Toolpath start(const Tool& tool, double rpm = 3000)
{
    Toolpath p;
    p.add(ToolChange{tool});
    if (rpm > 0)
        p.add(Spindle{rpm, true});
    p.add(Rapid{{-10, -10, 30}});
    return p;
}

std::vector<sim::Check> of(const sim::SimulationResult& r, CheckKind kind)
{
    std::vector<sim::Check> out;
    std::copy_if(r.checks.begin(), r.checks.end(), std::back_inserter(out),
                 [kind](const sim::Check& c) { return c.kind == kind; });
    return out;
}

sim::SimulationResult run(const Toolpath& p, sim::Stock& stock, const kinematics::Machine* machine = nullptr)
{
    sim::SimulationSetup setup;
    setup.stock = &stock;
    setup.machine = machine;
    return sim::simulate(p, setup);
}

}  // namespace

TEST(SimRun, AFeedMoveHalfAMillimetreIntoAWallIsAGougeAtThatRecord)
{
    // Stock 60 x 40 x 20; the part is the block x >= 30: its wall at x = 30.
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.1);
    stock.setDesign(boxMesh({30, 0, 0}, {60, 40, 20}), 0.02);
    Toolpath p = start(flat10());
    p.add(Rapid{{25, -10, 30}});
    p.add(Rapid{{25, -10, 10}});
    p.add(Linear{{25, 20, 10}, 600});    // record 5: the cutter's edge on the wall
    p.add(Linear{{25.5, 30, 10}, 600});  // record 6: half a millimetre into it
    p.add(Linear{{25, 50, 10}, 600});
    const sim::SimulationResult r = run(p, stock);
    const auto gouges = of(r, CheckKind::Gouge);
    ASSERT_EQ(gouges.size(), 2u);  // the move in, and the move back out of the wall
    EXPECT_EQ(gouges[0].record, 6);
    EXPECT_NEAR(gouges[0].valueMm, 0.5, 0.1);
    EXPECT_EQ(gouges[0].severity, base::Severity::Error);
    EXPECT_EQ(gouges[1].record, 7);
    EXPECT_NEAR(r.deviation.maxGougeMm, 0.5, 0.1);
    EXPECT_TRUE(of(r, CheckKind::RapidInStock).empty());
}

TEST(SimRun, TheSameSlotAlongTheWallIsClean)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.1);
    stock.setDesign(boxMesh({30, 0, 0}, {60, 40, 20}), 0.02);
    Toolpath p = start(flat10());
    p.add(Rapid{{25, -10, 30}});
    p.add(Rapid{{25, -10, 10}});
    p.add(Linear{{25, 50, 10}, 600});
    const sim::SimulationResult r = run(p, stock);
    EXPECT_TRUE(of(r, CheckKind::Gouge).empty());
    EXPECT_EQ(r.count(base::Severity::Error), 0);
    EXPECT_NEAR(r.removedMm3, 10 * 40 * 10, 10 * 40 * 10 * 0.03);  // the slot: width x length x depth
}

// A gouge the finished stock shows and no cut reported is still an error: here the stock is
// 1 mm lower than the part's top (no move cuts it), which only the comparison can find.
TEST(SimRun, AStockInsideThePartIsAnErrorThoughNoMoveCutThere)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 19}, false}, 0.2);
    stock.setDesign(boxMesh({30, 0, 0}, {60, 40, 20}), 0.02);
    Toolpath p = start(flat10());
    p.add(Rapid{{10, -10, 30}});
    p.add(Rapid{{10, -10, 10}});
    p.add(Linear{{10, 50, 10}, 600});  // a slot well away from the part
    const sim::SimulationResult r = run(p, stock);
    const auto gouges = of(r, CheckKind::Gouge);
    ASSERT_EQ(gouges.size(), 1u);
    EXPECT_EQ(gouges[0].severity, base::Severity::Error);
    EXPECT_EQ(gouges[0].record, -1);
    EXPECT_NEAR(gouges[0].valueMm, 1, 0.15);
    EXPECT_NE(gouges[0].message.find("where no move cut"), std::string::npos) << gouges[0].message;
}

// The comparison's gouge beside the cuts' own is not reported twice.
TEST(SimRun, AGougeTheCutsReportedIsNotRepeatedByTheComparison)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.1);
    stock.setDesign(boxMesh({30, 0, 0}, {60, 40, 20}), 0.02);
    Toolpath p = start(flat10());
    p.add(Rapid{{25.5, -10, 30}});
    p.add(Rapid{{25.5, -10, 10}});
    p.add(Linear{{25.5, 50, 10}, 600});  // record 5: half a millimetre into the wall all along
    const sim::SimulationResult r = run(p, stock);
    EXPECT_GT(r.deviation.maxGougeMm, 0.3);
    const auto gouges = of(r, CheckKind::Gouge);
    ASSERT_EQ(gouges.size(), 1u);
    EXPECT_EQ(gouges[0].record, 5);
}

TEST(SimRun, ARapidThroughTheStockIsAnErrorAtItsRecord)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath p = start(flat10());
    p.add(Rapid{{-10, 20, 15}});
    p.add(Rapid{{70, 20, 15}});  // record 4: straight through the block
    const sim::SimulationResult r = run(p, stock);
    const auto rapids = of(r, CheckKind::RapidInStock);
    ASSERT_EQ(rapids.size(), 1u);
    EXPECT_EQ(rapids[0].record, 4);
    EXPECT_GT(rapids[0].removedMm3, 60 * 10 * 5 * 0.9);
}

// The same move across after an untraced retract (Z unknown) is no rapid through the stock: the
// tool was last seen at Z 15, but it went up to where the program does not say.
TEST(SimRun, NoRapidIsCutFromAnUnknownHeight)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath p = start(flat10());
    p.add(Rapid{{-10, 20, 15}});
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    p.add(Rapid{{70, 20, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
    p.add(Rapid{{0, 0, 30}, AxisMask{AxisMask::kZ}});
    const sim::SimulationResult r = run(p, stock);
    EXPECT_TRUE(of(r, CheckKind::RapidInStock).empty());
    EXPECT_EQ(r.removedMm3, 0);

    // But a rapid that ends in the stock is a crash wherever it came from: down to Z 15 there.
    sim::HeightField again({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath crash = start(flat10());
    crash.add(Rapid{{-10, 20, 30}});
    crash.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    crash.add(Rapid{{30, 20, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
    crash.add(Rapid{{0, 0, 15}, AxisMask{AxisMask::kZ}});  // record 6
    const auto rapids = of(run(crash, again), CheckKind::RapidInStock);
    ASSERT_EQ(rapids.size(), 1u);
    EXPECT_EQ(rapids[0].record, 6);
}

// The program's first move comes from where the machine happened to stand: unknown, so not cut,
// but where it ends the tool stands, and a rapid that ends in the stock there is a crash.
TEST(SimRun, TheFirstRapidEndingInTheStockIsACrash)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath crash;
    crash.add(ToolChange{flat10()});
    crash.add(Spindle{3000, true});
    crash.add(Rapid{{30, 20, 15}});  // record 2
    const auto rapids = of(run(crash, stock), CheckKind::RapidInStock);
    ASSERT_EQ(rapids.size(), 1u);
    EXPECT_EQ(rapids[0].record, 2);

    sim::HeightField clear({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath above;
    above.add(ToolChange{flat10()});
    above.add(Spindle{3000, true});
    above.add(Rapid{{30, 20, 25}});
    above.add(Rapid{{30, 20, 22}});
    EXPECT_TRUE(of(run(above, clear), CheckKind::RapidInStock).empty());
}

TEST(SimRun, AHolderTooShortForADeepPocketHitsTheStock)
{
    sim::HeightField stock({{0, 0, 0}, {60, 60, 40}, false}, 0.2);
    Toolpath shortTool = start(flat10(20));
    shortTool.add(Rapid{{30, 30, 45}});
    shortTool.add(Linear{{30, 30, 10}, 100});  // 30 deep with 20 sticking out
    const auto hits = of(run(shortTool, stock), CheckKind::HolderCollision);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].record, 4);
    EXPECT_NEAR(hits[0].valueMm, 10, 0.5);

    sim::HeightField fresh({{0, 0, 0}, {60, 60, 40}, false}, 0.2);
    Toolpath longTool = start(flat10(45));
    longTool.add(Rapid{{30, 30, 45}});
    longTool.add(Linear{{30, 30, 10}, 100});
    EXPECT_TRUE(of(run(longTool, fresh), CheckKind::HolderCollision).empty());
}

TEST(SimRun, AToolThatDoesNotCutAtItsCentreMayRampButNotPlunge)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath plunge = start(flat10(40, false));
    plunge.add(Rapid{{20, 20, 25}});
    plunge.add(Linear{{20, 20, 15}, 100});
    const auto plunges = of(run(plunge, stock), CheckKind::PlungeNotCentre);
    ASSERT_EQ(plunges.size(), 1u);
    EXPECT_EQ(plunges[0].record, 4);

    sim::HeightField fresh({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath ramp = start(flat10(40, false));
    ramp.add(Rapid{{10, 20, 21}});
    ramp.add(Linear{{50, 20, 17}, 300});  // about 6 degrees
    EXPECT_TRUE(of(run(ramp, fresh), CheckKind::PlungeNotCentre).empty());
}

TEST(SimRun, CuttingWithTheSpindleOffIsAnError)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath p = start(flat10(), 0);
    p.add(Rapid{{-10, 20, 18}});
    p.add(Linear{{70, 20, 18}, 300});
    const auto off = of(run(p, stock), CheckKind::SpindleOffCutting);
    ASSERT_EQ(off.size(), 1u);
    EXPECT_EQ(off[0].record, 3);
}

TEST(SimRun, AFeedMoveInAirIsANoteWithItsLength)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath p = start(flat10());
    p.add(Linear{{-10, 30, 30}, 300});  // above and beside the stock
    const sim::SimulationResult r = run(p, stock);
    const auto air = of(r, CheckKind::AirCutting);
    ASSERT_EQ(air.size(), 1u);
    EXPECT_EQ(air[0].severity, base::Severity::Note);
    EXPECT_NEAR(air[0].valueMm, 40, 1e-9);
    EXPECT_NEAR(r.airCuttingMm, 40, 1e-9);
    EXPECT_EQ(r.count(base::Severity::Error), 0);
}

TEST(SimRun, MachineLimitsNameTheirRecord)
{
    kinematics::Machine machine;
    machine.id = "small";
    machine.name = "Small mill";
    machine.axes = {{"X", false, 0, 50}, {"Y", false, 0, 50}, {"Z", false, -50, 50}};
    machine.spindleMaxRpm = 2000;
    Toolpath p = start(flat10(), 3000);  // record 1: above the machine's top speed
    p.add(Linear{{10, 10, 30}, 300});
    const sim::SimulationResult r = sim::simulate(p, sim::SimulationSetup{&machine});
    const auto limits = of(r, CheckKind::MachineLimit);
    ASSERT_FALSE(limits.empty());
    EXPECT_EQ(limits[0].record, 1);
    EXPECT_EQ(limits[0].severity, base::Severity::Error);
    EXPECT_NE(limits[0].message.find("3000"), std::string::npos) << limits[0].message;
}

// A program that plunges before it says where in X and Y: neither the plunge nor the move across
// can be followed, and the run says so at the first, with the count, rather than report a clean
// cut. The rapid to Z 25 before them is the program's approach from wherever the machine stands:
// not a finding. A later stretch (after UnknownAxes) is a finding of its own.
TEST(SimRun, AFeedMoveFromAnUnknownPositionIsAWarningAtItsRecord)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.5);
    Toolpath p;
    p.add(ToolChange{flat10()});
    p.add(Spindle{3000, true});
    p.add(Rapid{{0, 0, 25}, AxisMask{AxisMask::kZ}});
    p.add(Linear{{0, 0, 19}, 100, AxisMask{AxisMask::kZ}});                  // record 3
    p.add(Linear{{20, 10, 0}, 100, AxisMask{AxisMask::kX | AxisMask::kY}});  // record 4
    p.add(Linear{{30, 10, 19}, 100});
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    p.add(Linear{{40, 10, 19}, 100, AxisMask{AxisMask::kX}});  // record 7
    p.add(Rapid{{40, 10, 30}});
    const sim::SimulationResult r = run(p, stock);
    const auto unknown = of(r, CheckKind::UnknownPosition);
    ASSERT_EQ(unknown.size(), 2u);
    EXPECT_EQ(unknown[0].record, 3);
    EXPECT_EQ(unknown[0].moves, 2);
    EXPECT_EQ(unknown[0].severity, base::Severity::Warning);
    EXPECT_NE(unknown[0].message.find("X, Y not given"), std::string::npos) << unknown[0].message;
    EXPECT_NE(unknown[0].message.find("nor is the feed move after it, until the position is known"), std::string::npos)
        << unknown[0].message;
    EXPECT_EQ(unknown[1].record, 7);
    EXPECT_NE(unknown[1].message.find("(Z not given"), std::string::npos) << unknown[1].message;
    EXPECT_EQ(unknown[1].moves, 1);
    EXPECT_EQ(r.count(base::Severity::Error), 0);
    EXPECT_GT(r.removedMm3, 0);  // the move from (20, 10, 19) on is cut
}

TEST(SimRun, ChecksOfOneRecordAreOneFindingAtItsWorst)
{
    sim::CheckList list;
    for (double depth : {0.1, 0.4, 0.2}) {
        sim::Check c;
        c.record = 7;
        c.valueMm = depth;
        list.add(c);
    }
    ASSERT_EQ(list.checks().size(), 1u);
    EXPECT_DOUBLE_EQ(list.checks()[0].valueMm, 0.4);
    EXPECT_EQ(list.checks()[0].moves, 3);
}

// A level arc's pieces are cut as one run and judged as one: an arc that cuts anywhere is not
// air cutting, and its findings count its pieces.
TEST(SimRun, AnArcThatCutsAnywhereIsNotAirCutting)
{
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    Toolpath p = start(flat10());
    p.add(Rapid{{-20, 20, 15}});
    p.add(Arc{{20, 20, 15}, {0, 20, 15}, {0, 0, 1}, true, 0, 300});  // over the top, out of the stock and in
    const sim::SimulationResult r = run(p, stock);
    EXPECT_TRUE(of(r, CheckKind::AirCutting).empty());
    EXPECT_NEAR(r.cuttingMm, 20 * kPiRun, 0.01);
    EXPECT_GT(r.removedMm3, 0);
}

// The shank and holder meet the stock each piece leaves: an arc run whose holder can reach the
// stock is cut piece by piece, and the holder's collision is found.
TEST(SimRun, AnArcDeepInTheStockFindsTheHolder)
{
    for (const double stickOut : {20.0, 45.0}) {
        sim::HeightField stock({{0, 0, 0}, {60, 60, 40}, false}, 0.2);
        Toolpath p = start(flat10(stickOut));
        // Beside the stock, clear of it, then through its corner 30 deep and out: only the
        // arc's middle brings the holder (25 mm in radius) over the stock.
        p.add(Rapid{{-30, 30, 45}});
        p.add(Linear{{-30, 30, 10}, 300});
        p.add(Arc{{30, -30, 10}, {-30, -30, 10}, {0, 0, 1}, true, 0, 300});
        const sim::SimulationResult r = run(p, stock);
        const auto hits = of(r, CheckKind::HolderCollision);
        EXPECT_GT(r.removedMm3, 100) << stickOut;
        if (stickOut < 30) {
            ASSERT_EQ(hits.size(), 1u);
            EXPECT_EQ(hits[0].record, 5);
        } else {
            EXPECT_TRUE(hits.empty()) << (hits.empty() ? ""
                                                       : hits[0].message + " record " + std::to_string(hits[0].record));
        }
    }
}

// The dock and the command line cut the moves in steps of their own: stopping inside a run must
// leave the stock, the figures and the findings that running through leaves.
TEST(SimRun, CuttingInStepsLeavesWhatCuttingThroughLeaves)
{
    Toolpath p = start(flat10());
    p.add(Rapid{{-8, 20, 15}});
    p.add(Arc{{8, 20, 15}, {0, 20, 15}, {0, 0, 1}, true, 0, 300});     // into the stock and out
    p.add(Arc{{-8, 20, 15}, {0, 20, 15}, {0, 0, 1}, true, 0, 300});    // on, under the stock's edge
    p.add(Arc{{30, 20, 12}, {11, 20, 12}, {0, 0, 1}, false, 0, 300});  // a helix down: pieces of its own
    p.add(Linear{{30, 20, 30}, 300});
    p.add(Arc{{-8, 20, 30}, {11, 20, 30}, {0, 0, 1}, false, 0, 300});  // above it all: in air
    const sim::MoveList moves = sim::buildMoves(p);
    const base::Box3 b{{0, 0, 0}, {60, 40, 20}, false};
    sim::HeightField throughStock(b, 0.2);
    sim::test::keepLastCuts(throughStock);
    sim::StockRun through(moves, throughStock);
    through.cutTo(moves.moves.size());
    for (const std::size_t step : {std::size_t(1), std::size_t(7)}) {
        sim::HeightField stepStock(b, 0.2);
        sim::test::keepLastCuts(stepStock);
        sim::StockRun stepped(moves, stepStock);
        while (!stepped.finished())
            stepped.cutTo(stepped.nextMove() + step);
        for (int j = 0; j < stepStock.columnsY(); ++j)
            for (int i = 0; i < stepStock.columnsX(); ++i) {
                // Equal to the heights the field tells apart: the helix cut in one pass takes the
                // lowest of two cuts kEps apart, in turn the first is kept.
                ASSERT_NEAR(stepStock.top(i, j), throughStock.top(i, j), sim::detail::kEps)
                    << i << ", " << j << " step " << step;
                ASSERT_EQ(stepStock.lastCut(i, j), throughStock.lastCut(i, j)) << i << ", " << j << " step " << step;
            }
        // The helix is cut from its last piece back in one pass, in turn in steps: the same
        // losses, added in another order.
        EXPECT_NEAR(stepped.removedMm3(), through.removedMm3(), 1e-9 * through.removedMm3());
        EXPECT_DOUBLE_EQ(stepped.airCuttingMm(), through.airCuttingMm());
        EXPECT_DOUBLE_EQ(stepped.cuttingMm(), through.cuttingMm());
        const std::vector<sim::Check> a = stepped.checks(), c = through.checks();
        ASSERT_EQ(a.size(), c.size());
        for (std::size_t k = 0; k < a.size(); ++k) {
            EXPECT_EQ(a[k].kind, c[k].kind);
            EXPECT_EQ(a[k].record, c[k].record);
            EXPECT_EQ(a[k].move, c[k].move);
            EXPECT_EQ(a[k].moves, c[k].moves);
            EXPECT_DOUBLE_EQ(a[k].valueMm, c[k].valueMm);
        }
    }
    EXPECT_GT(through.airCuttingMm(), 0);  // the last arc
    EXPECT_GT(through.removedMm3(), 100);
}

TEST(SimRun, ThePlanMadeBesideTheCutIsThePlanOfItsMoves)
{
    // SimulationSetup::planOn plans on a second thread while the stock is cut: the same plan as
    // planMotion() on the moves afterwards, and none without it.
    Toolpath p = start(flat10());
    p.add(Rapid{{-8, 20, 15}});
    for (int k = 0; k < 20; ++k)
        p.add(Arc{{k % 2 ? -8.0 : 8.0, 20, 15 - 0.1 * k}, {0, 20, 15}, {0, 0, 1}, true, 0, 300});
    p.add(Linear{{30, 20, 30}, 900});
    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    kinematics::Machine machine = kinematics::defaultLimitsMachine();
    sim::SimulationSetup setup;
    setup.stock = &stock;
    setup.planOn = &machine;
    const sim::SimulationResult r = sim::simulate(p, setup);
    ASSERT_TRUE(r.plan.has_value());
    const sim::MotionPlan alone = sim::planMotion(r.moves, machine);
    ASSERT_EQ(r.plan->moves.size(), alone.moves.size());
    ASSERT_EQ(r.plan->moves.size(), r.moves.moves.size());
    for (std::size_t i = 0; i < alone.moves.size(); ++i) {
        EXPECT_EQ(r.plan->moves[i].start, alone.moves[i].start) << i;
        EXPECT_EQ(r.plan->moves[i].moveSeconds, alone.moves[i].moveSeconds) << i;
        EXPECT_EQ(r.plan->moves[i].exitSpeed, alone.moves[i].exitSpeed) << i;
    }
    EXPECT_EQ(r.plan->totalSeconds, alone.totalSeconds);
    EXPECT_GT(r.plan->totalSeconds, 0);
    EXPECT_GT(r.removedMm3, 0);

    sim::HeightField again({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    EXPECT_FALSE(run(p, again).plan.has_value());
}

TEST(SimRun, CancelStopsThePlanBesideTheCutAndLeavesNoHalfPlan)
{
    // The simulator dock plans beside the cut: Cancel must not wait for the plan, and what the
    // plan had done by then is not handed out as the program's times.
    Toolpath p = start(flat10());
    for (int k = 0; k < 3000; ++k)
        p.add(Linear{{k % 2 ? 50.0 : 10.0, 20, 15}, 900});
    kinematics::Machine machine = kinematics::defaultLimitsMachine();
    std::atomic<bool> cancel{true};
    sim::PlanOptions options;
    options.cancel = &cancel;
    const sim::MoveList moves = sim::buildMoves(p);
    const sim::MotionPlan stopped = sim::planMotion(moves, machine, options);
    EXPECT_TRUE(stopped.cancelled);
    EXPECT_EQ(stopped.totalSeconds, 0) << "no time from a plan that stopped at its first move";

    sim::HeightField stock({{0, 0, 0}, {60, 40, 20}, false}, 0.2);
    sim::SimulationSetup setup;
    setup.stock = &stock;
    setup.planOn = &machine;
    setup.cancel = &cancel;
    const sim::SimulationResult r = sim::simulate(p, setup);
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.plan.has_value());
    setup.stock = nullptr;  // nothing to cut: the plan alone, stopped all the same
    const sim::SimulationResult planOnly = sim::simulate(p, setup);
    EXPECT_TRUE(planOnly.cancelled);
    EXPECT_FALSE(planOnly.plan.has_value());

    cancel = false;
    options.cancel = &cancel;
    const sim::MotionPlan whole = sim::planMotion(moves, machine, options);
    EXPECT_FALSE(whole.cancelled);
    EXPECT_EQ(whole.totalSeconds, sim::planMotion(moves, machine).totalSeconds);
    EXPECT_GT(whole.totalSeconds, 0);
}
