// The simulator's move list: arcs split within the chord tolerance, cycles expanded, working
// planes applied, feeds per revolution and in inverse time resolved, unknown positions never
// invented, joint-interpolated five-axis moves split along the tip's curve.
#include "sim/Moves.h"

#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace camwb;
using namespace camwb::toolpath;
using sim::MoveKind;

namespace {

constexpr double kPi = 3.14159265358979323846;

Tool flat10()
{
    Tool t;
    t.number = 3;
    t.diameterMm = 10;
    t.lengthMm = 50;
    return t;
}

}  // namespace

TEST(SimMoves, StraightMovesKeepFeedToolSpindleAndRecord)
{
    Toolpath p;
    p.add(ToolChange{flat10()});
    p.add(Spindle{2000, true});
    p.add(Rapid{{0, 0, 10}});
    p.add(Linear{{0, 0, -2}, 100});
    p.add(Linear{{30, 0, -2}, 600});
    const sim::MoveList list = sim::buildMoves(p);
    // The tool change (no position yet), the tool standing where the first rapid ends (from an
    // unknown place) and two feed moves.
    ASSERT_EQ(list.moves.size(), 4u);
    EXPECT_EQ(list.moves[0].kind, MoveKind::ToolChange);
    EXPECT_FALSE(list.moves[0].positionKnown);
    EXPECT_EQ(list.moves[1].kind, MoveKind::Rapid);
    EXPECT_EQ(list.moves[1].record, 2u);
    EXPECT_DOUBLE_EQ(list.moves[1].lengthMm(), 0);
    EXPECT_EQ(list.moves[2].kind, MoveKind::Feed);
    EXPECT_DOUBLE_EQ(list.moves[2].feedMmPerMin, 100);
    EXPECT_EQ(list.moves[3].record, 4u);
    EXPECT_EQ(list.moves[3].tool, 3);
    EXPECT_DOUBLE_EQ(list.moves[3].spindleRpm, 2000);
    EXPECT_DOUBLE_EQ(list.moves[3].lengthMm(), 30);
    ASSERT_NE(list.tool(3), nullptr);
    EXPECT_DOUBLE_EQ(list.tool(3)->diameterMm, 10);
}

TEST(SimMoves, AMoveFromAnUnknownPositionMakesNoMotion)
{
    Toolpath p;
    p.add(Rapid{{0, 0, 20}, AxisMask{AxisMask::kZ}});  // only Z known
    p.add(Rapid{{5, 6, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
    p.add(Linear{{5, 6, 0}, 100});
    const sim::MoveList list = sim::buildMoves(p);
    // The tool standing where the position became whole, then the plunge from (5, 6, 20); never
    // a line from a guess.
    ASSERT_EQ(list.moves.size(), 2u);
    EXPECT_EQ(list.moves[0].kind, MoveKind::Rapid);
    EXPECT_EQ(list.moves[0].from, (Vec3{5, 6, 20}));
    EXPECT_EQ(list.moves[0].to, (Vec3{5, 6, 20}));
    EXPECT_EQ(list.moves[1].from, (Vec3{5, 6, 20}));
    EXPECT_EQ(list.moves[1].to, (Vec3{5, 6, 0}));
    // Both rapids started where an axis was unknown: the first with X and Y, the second with X, Y.
    ASSERT_EQ(list.untraced.size(), 2u);
    EXPECT_EQ(list.untraced[0].record, 0u);
    EXPECT_EQ(list.untraced[0].unknownAxes, (AxisMask{AxisMask::kX | AxisMask::kY | AxisMask::kZ}));
    EXPECT_EQ(list.untraced[1].record, 1u);
    EXPECT_EQ(list.untraced[1].kind, MoveKind::Rapid);
    EXPECT_EQ(list.untraced[1].unknownAxes, (AxisMask{AxisMask::kX | AxisMask::kY}));
}

// An untraced retract (M140 MB MAX read without a machine) leaves Z unknown: the move across is
// not made at the old depth, and the simulation goes on from the first move whose start is known.
TEST(SimMoves, AfterUnknownAxesNoMoveStartsFromTheirOldValues)
{
    Toolpath p;
    p.add(Rapid{{10, 10, 20}});
    p.add(Linear{{10, 10, -5}, 100});
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    p.add(Rapid{{90, 90, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
    p.add(Rapid{{0, 0, 5}, AxisMask{AxisMask::kZ}});
    p.add(Linear{{90, 90, -5}, 100});
    const sim::MoveList list = sim::buildMoves(p);
    // The tool standing where the first rapid ends, the two plunges, and the tool standing where
    // Z is given again.
    ASSERT_EQ(list.moves.size(), 4u);
    EXPECT_EQ(list.moves[0].to, (Vec3{10, 10, 20}));
    EXPECT_EQ(list.moves[1].to, (Vec3{10, 10, -5}));
    EXPECT_EQ(list.moves[2].kind, MoveKind::Rapid);
    EXPECT_EQ(list.moves[2].from, (Vec3{90, 90, 5}));
    EXPECT_EQ(list.moves[2].to, (Vec3{90, 90, 5}));
    EXPECT_EQ(list.moves[2].record, 4u);
    EXPECT_EQ(list.moves[3].from, (Vec3{90, 90, 5}));
    EXPECT_EQ(list.moves[3].record, 5u);
    // The first move, the one across with Z unknown, and the one down to Z 5.
    ASSERT_EQ(list.untraced.size(), 3u);
    EXPECT_EQ(list.untraced[0].record, 0u);
    EXPECT_EQ(list.untraced[1].record, 3u);
    EXPECT_EQ(list.untraced[1].unknownAxes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(list.untraced[2].record, 4u);
}

// A feed move, an arc or a canned cycle's hole where the way is not known: each is named, with
// what was not known, so that the simulation can say what it did not cut.
TEST(SimMoves, FeedMovesFromAnUnknownPositionAreNamed)
{
    Toolpath p;
    p.add(Rapid{{0, 0, 5}, AxisMask{AxisMask::kZ}});
    p.add(Linear{{0, 0, -1}, 100, AxisMask{AxisMask::kZ}});
    p.add(Arc{{10, 0, -1}, {5, 0, -1}, {0, 0, 1}, false, 0, 100});
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    toolpath::Cycle drill;
    drill.holes = {{20, 20, 0}};
    p.add(drill);
    const sim::MoveList list = sim::buildMoves(p);
    ASSERT_EQ(list.untraced.size(), 4u);
    EXPECT_EQ(list.untraced[1].record, 1u);
    EXPECT_EQ(list.untraced[1].kind, MoveKind::Feed);
    EXPECT_EQ(list.untraced[1].unknownAxes, (AxisMask{AxisMask::kX | AxisMask::kY}));
    EXPECT_EQ(list.untraced[2].record, 2u);
    EXPECT_EQ(list.untraced[2].kind, MoveKind::Feed);
    EXPECT_EQ(list.untraced[3].record, 4u);
    EXPECT_EQ(list.untraced[3].kind, MoveKind::Feed);
    EXPECT_EQ(list.untraced[3].unknownAxes, AxisMask{AxisMask::kZ});
}

TEST(SimMoves, ArcsAreSplitWithinTheChordTolerance)
{
    Toolpath p;
    p.add(Rapid{{10, 0, 0}});
    p.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 300});
    sim::MoveOptions options;
    options.chordToleranceMm = 0.01;
    const sim::MoveList list = sim::buildMoves(p, options);
    ASSERT_GT(list.moves.size(), 10u);
    EXPECT_EQ(list.moves[0].lengthMm(), 0);  // the rapid from an unknown place: the tool stands at its end
    double length = 0;
    for (std::size_t i = 1; i < list.moves.size(); ++i) {
        const sim::Move& m = list.moves[i];
        EXPECT_TRUE(m.fromArc);
        EXPECT_DOUBLE_EQ(m.feedMmPerMin, 300);
        const base::Vec3 mid = (m.from + m.to) * 0.5;
        EXPECT_LE(10 - mid.length(), 0.01 + 1e-9);
        length += m.lengthMm();
    }
    EXPECT_NEAR(length, 10 * kPi, 0.05);
}

TEST(SimMoves, InverseTimeFeedSharesTheBlockTimeOverItsPieces)
{
    Toolpath p;
    p.add(Rapid{{10, 0, 0}});
    p.add(FeedModeChange{FeedMode::InverseTime});
    p.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 2});  // 1/2 minute for the half circle
    p.add(FeedModeChange{FeedMode::PerRevolution});
    p.add(Spindle{1000, true});
    p.add(Linear{{-10, 0, -5}, 0.1});
    const sim::MoveList list = sim::buildMoves(p);
    double minutes = 0;
    for (std::size_t i = 0; i + 1 < list.moves.size(); ++i)
        minutes += list.moves[i].minutes;
    EXPECT_NEAR(minutes, 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(list.moves.back().feedMmPerMin, 100);  // 0.1 mm/rev at 1000 rpm
}

TEST(SimMoves, CyclesAreTheMovesAControlMakes)
{
    Toolpath p;
    p.add(Rapid{{0, 0, 20}});
    Cycle c;
    c.clearanceZ = 20;
    c.retractZ = 2;
    c.topZ = 0;
    c.bottomZ = -10;
    c.feedMmPerMin = 120;
    c.holes = {{10, 0, 0}, {20, 0, 0}};
    p.add(c);
    const sim::MoveList list = sim::buildMoves(p);
    int feeds = 0;
    double deepest = 0;
    EXPECT_EQ(list.moves.at(0).record, 0u);  // the tool standing where the first rapid ends
    for (std::size_t i = 1; i < list.moves.size(); ++i) {
        const sim::Move& m = list.moves[i];
        feeds += m.kind == MoveKind::Feed;
        deepest = std::min(deepest, m.to.z);
        EXPECT_EQ(m.record, 1u);
    }
    EXPECT_EQ(feeds, 2);
    EXPECT_DOUBLE_EQ(deepest, -10);
}

TEST(SimMoves, WorkingPlanesPutMovesInTheWorkpieceFrame)
{
    Toolpath p;
    WorkingPlane plane;  // turned 90 degrees about Y: the plane's Z is the workpiece's +X
    plane.origin = {100, 0, 0};
    plane.xAxis = {0, 0, -1};
    plane.zAxis = {1, 0, 0};
    p.add(plane);
    p.add(Rapid{{0, 0, 10}});
    p.add(Linear{{0, 0, 0}, 100});
    const sim::MoveList list = sim::buildMoves(p);
    ASSERT_EQ(list.moves.size(), 2u);  // standing where the first rapid ends, then the feed
    EXPECT_NEAR(list.moves[0].to.x, 110, 1e-12);
    EXPECT_NEAR(list.moves[1].from.x, 110, 1e-12);
    EXPECT_NEAR(list.moves[1].to.x, 100, 1e-12);
    EXPECT_NEAR(list.moves[1].toAxis().x, 1, 1e-12);  // the tool stands along the plane's Z
}

TEST(SimMoves, SectionsSpanTheirMoves)
{
    Toolpath p;
    p.add(Rapid{{0, 0, 10}});
    SectionBegin s;
    s.operationName = "Slot";
    s.toolNumber = 3;
    p.add(s);
    p.add(Linear{{0, 0, 0}, 100});
    p.add(Linear{{10, 0, 0}, 100});
    p.add(SectionEnd{});
    p.add(Rapid{{10, 0, 10}});
    const sim::MoveList list = sim::buildMoves(p);
    ASSERT_EQ(list.sections.size(), 1u);
    EXPECT_EQ(list.sections[0].name, "Slot");
    EXPECT_EQ(list.sections[0].firstMove, 1u);  // after the tool standing where the first rapid ends
    EXPECT_EQ(list.sections[0].endMove, 3u);
}

TEST(SimMoves, JointInterpolatedMovesFollowTheTipsCurve)
{
    // Table-table A/C (seed 003 layout): turning C by 90 degrees with the tip off the C axis
    // swings the tip on a circle; the pieces follow it within the tolerance.
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::TableTable;
    chain.joints = {{"A", true, {-1, 0, 0}, {0, 0, 0}}, {"C", true, {0, 0, -1}, {0, 0, 0}}};
    Toolpath p;
    ToolAxisMove a;
    a.tip = {50, 0, 0};
    a.machine.known = RotaryAxes::kA | RotaryAxes::kC;
    p.add(a);
    ToolAxisMove b = a;
    b.feedMmPerMin = 500;
    b.machine.cDeg = 90;
    b.tip = {50, 0, 0};  // the same tip on the workpiece: the machine turns the part under it
    b.jointInterpolated = true;
    p.add(b);
    sim::MoveOptions options;
    options.chain = &chain;
    options.chordToleranceMm = 0.01;
    const sim::MoveList list = sim::buildMoves(p, options);
    // Without TCPM the linear axes travel straight from one end to the other while C turns, so
    // the tip leaves (50, 0, 0) on the workpiece and comes back: pieces, not a zero-length move.
    ASSERT_GT(list.moves.size(), 4u);
    EXPECT_EQ(list.moves[0].lengthMm(), 0);  // the first pose, reached from an unknown place
    double farthest = 0;
    for (std::size_t i = 1; i < list.moves.size(); ++i) {
        const sim::Move& m = list.moves[i];
        EXPECT_TRUE(m.jointInterpolated);
        farthest = std::max(farthest, base::distance(m.to, {50, 0, 0}));
    }
    EXPECT_GT(farthest, 10);
    EXPECT_NEAR(list.moves.back().to.x, 50, 1e-9);
    EXPECT_NEAR(list.moves.back().to.y, 0, 1e-9);
}

TEST(SimMoves, ANewToolAxisIsATurnAboutTheStandingTip)
{
    // After a move, a tilted plane: the machine turns the tool before the next move, and that
    // turn is a move of its own (no jump of the axis between two moves), its rotary positions
    // unknown (the move after it gives none either).
    Toolpath p;
    p.add(Rapid{{0, 0, 50}});
    ToolAxisMove tilted;
    tilted.tip = {0, 0, 50};
    tilted.axis = {0, 0, 1};
    tilted.machine.known = RotaryAxes::kB | RotaryAxes::kC;
    WorkingPlane plane;
    plane.xAxis = {0, 0, -1};
    plane.zAxis = {1, 0, 0};
    p.add(tilted);
    p.add(plane);
    p.add(Rapid{{0, 0, 60}});
    const sim::MoveList list = sim::buildMoves(p);
    ASSERT_EQ(list.moves.size(), 3u);  // standing where the first rapid ends, the turn, the rapid
    const sim::Move& turn = list.moves[1];
    EXPECT_EQ(turn.kind, MoveKind::Rapid);
    EXPECT_EQ(turn.from, turn.to);
    EXPECT_NEAR(turn.fromAxis().z, 1, 1e-12);
    EXPECT_NEAR(turn.toAxis().x, 1, 1e-12);
    EXPECT_EQ(turn.toMachine().known, 0);
    EXPECT_EQ(turn.record, 2u);
    const sim::Move& after = list.moves[2];
    EXPECT_NEAR(after.fromAxis().x, 1, 1e-12);  // continues from the turned axis
    EXPECT_EQ(after.fromMachine().known, 0);
    EXPECT_NEAR(after.to.x, 60, 1e-12);  // along the plane's Z, which is the workpiece's X
}

TEST(SimMoves, TheToolAxisTurnsEvenly)
{
    sim::Move m;
    m.setFromAxis({0, 0, 1});
    m.setToAxis({std::sin(1.2), 0, std::cos(1.2)});  // 1.2 rad apart
    for (double u : {0.0, 0.1, 0.5, 0.9, 1.0}) {
        EXPECT_NEAR(m.axisAt(u).angleTo(m.fromAxis()), 1.2 * u, 1e-12);
        EXPECT_NEAR(m.axisAt(u).length(), 1, 1e-12);
    }
    m.setToAxis({0, 0, -1});  // opposite: no even turn, the start's axis
    EXPECT_EQ(m.axisAt(0.5), m.fromAxis());
}

// The stock sweeps an arc about Z itself (HeightField::cutArcRun): its pieces carry the circle,
// which pointAt() follows; an arc in another plane is left to its chords.
// A helix's pieces go on from each other (a stock cuts them as one run) unless they plunge: a
// steep helix's pieces are judged one by one, as a straight plunge is.
TEST(SimMoves, AHelixIsARunUnlessItsPiecesPlunge)
{
    Toolpath p;
    p.add(Rapid{{10, 0, 0}});
    p.add(Arc{{10, 0, -2}, {0, 0, -2}, {0, 0, 1}, false, 0, 300});     // record 1: 2 mm a turn of radius 10
    p.add(Arc{{9, 0, -40}, {9.5, 0, -40}, {0, 0, 1}, false, 0, 300});  // record 2: 38 mm a half turn of radius 0.5
    const sim::MoveList list = sim::buildMoves(p);
    int runs = 0, plunges = 0;
    for (std::size_t i = 1; i + 1 < list.moves.size(); ++i) {
        const sim::Move &m = list.moves[i], &next = list.moves[i + 1];
        if (m.record != next.record)
            continue;
        EXPECT_FALSE(sim::continuesLevelArc(m, next));
        if (m.record == 1) {
            EXPECT_FALSE(m.plunges());
            EXPECT_TRUE(sim::continuesArc(m, next));
            ++runs;
        } else {
            EXPECT_TRUE(m.plunges());
            EXPECT_FALSE(sim::continuesArc(m, next));
            ++plunges;
        }
    }
    EXPECT_GT(runs, 10);
    EXPECT_GT(plunges, 5);
}

TEST(SimMoves, PiecesOfAnArcAboutZCarryItsCircle)
{
    Toolpath p;
    p.add(Rapid{{10, 0, 0}});
    p.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 300});
    p.add(Arc{{10, 0, 0}, {0, 0, 0}, {0, 1, 0}, false, 0, 300});  // G18: about Y
    const sim::MoveList list = sim::buildMoves(p);
    std::size_t aboutZ = 0, aboutY = 0;
    for (std::size_t i = 1; i < list.moves.size(); ++i) {
        const sim::Move& m = list.moves[i];
        if (m.record == 1) {
            ++aboutZ;
            EXPECT_EQ(m.arcCentre, (base::Vec2{0, 0}));
            EXPECT_DOUBLE_EQ(m.arcRadius, 10);
            EXPECT_NEAR(m.pointAt(0.5).xy().length(), 10, 1e-12);
            EXPECT_EQ(m.pointAt(0), m.from);
            EXPECT_EQ(m.pointAt(1), m.to);
            if (i + 1 < list.moves.size() && list.moves[i + 1].record == 1)
                EXPECT_TRUE(sim::continuesLevelArc(m, list.moves[i + 1]));
        } else {
            ++aboutY;
            EXPECT_EQ(m.arcRadius, 0);
            EXPECT_FALSE(sim::continuesLevelArc(list.moves[i - 1], m));
        }
    }
    EXPECT_GT(aboutZ, 10u);
    EXPECT_GT(aboutY, 10u);
}

TEST(SimMoves, TheListIsReservedOnceAndNotMuchMore)
{
    // The reservation is faulted in at once (base::prefault): it must hold every move, so the list
    // is not regrown and copied, and not much more, or the memory is spent for nothing.
    Toolpath p;
    p.add(ToolChange{flat10()});
    p.add(Rapid{{0, 0, 5}});
    for (int i = 0; i < 1000; ++i) {
        p.add(Linear{{double(i % 50), double(i / 50), 0}, 500});
        if (i % 100 == 0)
            p.add(Arc{{double(i % 50), double(i / 50) + 4, 0},
                      {double(i % 50), double(i / 50) + 2, 0},
                      {0, 0, 1},
                      false,
                      0,
                      500});
    }
    p.add(Dwell{1.0});
    const sim::MoveList list = sim::buildMoves(p);
    ASSERT_GT(list.moves.size(), 1000u);
    EXPECT_GE(list.moves.capacity(), list.moves.size());
    EXPECT_LE(list.moves.capacity(), list.moves.size() + list.moves.size() / 20);
}

TEST(SimMoves, TheToolsTurnIsKeptApartAndCopiedWithItsMove)
{
    // A long program's moves are its largest array (156k of them for the 20,000-block benchmark
    // program): the tool axes and rotary positions only five-axis moves need are not in it.
    static_assert(sizeof(sim::Move) <= 128, "a move holds its tool's turn apart (ToolTurn)");
    sim::Move m;
    EXPECT_EQ(m.fromAxis(), (base::Vec3{0, 0, 1}));
    EXPECT_EQ(m.toMachine().known, 0);
    m.setToAxis({1, 0, 0});
    toolpath::RotaryAxes c90;
    c90.known = toolpath::RotaryAxes::kC;
    c90.cDeg = 90;
    m.setToMachine(c90);
    const sim::Move copy = m;
    m.setToAxis({0, 1, 0});  // the copy keeps its own
    m.setToMachine({});
    EXPECT_EQ(copy.toAxis(), (base::Vec3{1, 0, 0}));
    EXPECT_EQ(copy.fromAxis(), (base::Vec3{0, 0, 1}));
    EXPECT_DOUBLE_EQ(copy.toMachine().cDeg, 90);
    EXPECT_EQ(m.toAxis(), (base::Vec3{0, 1, 0}));
    EXPECT_EQ(m.toMachine().known, 0);
    sim::Move moved = std::move(m);
    EXPECT_EQ(moved.toAxis(), (base::Vec3{0, 1, 0}));
}

TEST(SimMoves, ATurnKeepsItsAxisBitForBit)
{
    // Only the defaults themselves leave the turn out: an axis with a negative zero (an angle
    // worked out from it may land on the other side of ±180°) is kept as given.
    sim::Move m;
    m.setToAxis({-0.0, 0, 1});
    EXPECT_TRUE(std::signbit(m.toAxis().x));
    toolpath::RotaryAxes c;
    c.cDeg = -0.0;
    m.setFromMachine(c);
    EXPECT_TRUE(std::signbit(m.fromMachine().cDeg));
}
