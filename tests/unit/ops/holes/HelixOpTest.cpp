// Helix (hole milling): properties over generated hole sets (circle, pitch, depths, no gouge,
// rapids), every error, and one golden CL trace.
#include "ops/HelixOp.h"
#include "../support/FeedKinds.h"
#include "HoleTestSupport.h"
#include "toolpath/ClArcs.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

using namespace camwb;
using ops::test::uniform;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct HelixCase {
    std::vector<geom::Hole> holes;
    ops::HelixParams params;
    ops::ToolController tc;
};

HelixCase randomCase(std::mt19937& random)
{
    HelixCase c;
    c.holes = ops::test::randomHoles(random, 1 + random() % 5, 8, 40);
    double smallest = c.holes.front().diameterMm;
    for (const geom::Hole& hole : c.holes)
        smallest = std::min(smallest, hole.diameterMm);
    c.params.name = "H";
    c.params.heights = {40, 12, 0, 0};
    c.params.radialStockMm = random() % 2 ? uniform(random, 0, 0.3) : 0;
    c.params.pitchMm = uniform(random, 0.2, 4);
    c.params.climb = random() % 2;
    c.params.finishingCircle = random() % 2;
    c.params.breakthroughMm = uniform(random, 0, 1);
    c.tc = ops::test::toolController(uniform(random, 2, smallest - 2 * c.params.radialStockMm - 0.5));
    return c;
}

double helixRadius(const HelixCase& c, const geom::Hole& hole)
{
    return (hole.diameterMm - c.tc.tool.diameterMm) / 2 - c.params.radialStockMm;
}

double finalZ(const HelixCase& c, const geom::Hole& hole)
{
    return hole.through ? hole.bottomZ - c.params.breakthroughMm : hole.bottomZ;
}

bool coreStands(const HelixCase& c, const geom::Hole& hole)
{
    return helixRadius(c, hole) > c.tc.tool.diameterMm / 2 && !hole.through;
}

// What the walk over one hole's arcs adds up.
struct HoleSums {
    double helixSweep = 0, flatSweep = 0;
    double firstArcZ = NAN, lastHelixZ = NAN;
};

// Walks the toolpath and checks every record against the case; returns the sums per hole.
std::map<int, HoleSums> checkToolpath(const HelixCase& c, const toolpath::Toolpath& tp)
{
    std::map<int, HoleSums> sums;
    const double safe = c.params.heights.safeZ;
    const double toolRadius = c.tc.tool.diameterMm / 2;
    toolpath::Vec3 at{NAN, NAN, NAN};
    auto checkInside = [&](const toolpath::Vec3& p) {
        const geom::Hole& hole = ops::test::holeAround(c.holes, p.xy());
        const double r = base::distance(p.xy(), hole.center);
        EXPECT_LE(r, hole.diameterMm / 2 - toolRadius - c.params.radialStockMm + 1e-9) << "gouge";
        EXPECT_GE(p.z, finalZ(c, hole) - 1e-12) << "below the final depth";
        if (coreStands(c, hole) && p.z < hole.topZ)
            EXPECT_GE(r, helixRadius(c, hole) - 1e-9) << "into the core";
    };
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const toolpath::Record& record = tp.record(i);
        EXPECT_EQ(tp.source(i).recordIndex, static_cast<int>(i));
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&record)) {
            EXPECT_GE(rapid->to.z, safe) << "rapid below safe";
            if (!std::isnan(at.x) && !(rapid->to.xy() == at.xy()))
                EXPECT_GE(at.z, safe) << "sideways rapid below safe";
            at = rapid->to;
        } else if (const auto* line = std::get_if<toolpath::Linear>(&record)) {
            checkInside(at);
            checkInside(line->to);
            at = line->to;
        } else if (const auto* arc = std::get_if<toolpath::Arc>(&record)) {
            const auto hole = std::find_if(c.holes.begin(), c.holes.end(),
                                           [&](const geom::Hole& h) { return arc->center.xy() == h.center; });
            EXPECT_NE(hole, c.holes.end()) << "arc centre off every hole axis";
            if (hole == c.holes.end())
                return sums;
            const double radius = helixRadius(c, *hole);
            EXPECT_NEAR(base::distance(at.xy(), hole->center), radius, 1e-9);
            EXPECT_NEAR(base::distance(arc->to.xy(), hole->center), radius, 1e-9);
            EXPECT_EQ(arc->center.z, at.z) << "centre in the start's plane";
            EXPECT_EQ(arc->normal, (toolpath::Vec3{0, 0, 1}));
            EXPECT_EQ(arc->clockwise, !c.params.climb);
            EXPECT_EQ(arc->turns, 0);
            checkInside(arc->to);
            const double sweep = toolpath::forwardAngle(*arc, at, arc->to);
            HoleSums& s = sums[hole->faceIndex];
            if (std::isnan(s.firstArcZ))
                s.firstArcZ = at.z;
            if (arc->to.z != at.z) {
                EXPECT_NEAR((at.z - arc->to.z) / sweep * kTwoPi, c.params.pitchMm, 1e-9) << "lead";
                EXPECT_EQ(arc->feedMmPerMin, c.tc.rampFeed());
                EXPECT_TRUE(std::isnan(s.lastHelixZ) || s.flatSweep == 0) << "helix after the flat circle";
                s.helixSweep += sweep;
                s.lastHelixZ = arc->to.z;
            } else {
                EXPECT_EQ(arc->to.z, finalZ(c, *hole)) << "flat circle off the final depth";
                EXPECT_EQ(arc->feedMmPerMin, c.tc.cuttingFeedMmPerMin);
                s.flatSweep += sweep;
            }
            at = arc->to;
        }
    }
    return sums;
}

}  // namespace

TEST(HelixOp, GeneratedHoleSetsKeepCirclePitchDepthAndStayInside)
{
    std::mt19937 random(20240611);
    for (int trial = 0; trial < 300; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const HelixCase c = randomCase(random);
        auto result = ops::computeHelix(c.holes, c.params, c.tc, 3);
        ASSERT_TRUE(result) << result.error().message;
        const toolpath::Toolpath& tp = result->toolpath;
        ASSERT_TRUE(std::holds_alternative<toolpath::SectionBegin>(tp.record(0)));
        ASSERT_TRUE(std::holds_alternative<toolpath::SectionEnd>(tp.record(tp.size() - 1)));
        EXPECT_EQ(std::get<toolpath::Rapid>(tp.record(tp.size() - 2)).to.z, c.params.heights.clearanceZ);
        EXPECT_EQ(std::get<toolpath::Rapid>(tp.record(1)).to.z, c.params.heights.clearanceZ);

        const std::map<int, HoleSums> sums = checkToolpath(c, tp);
        ASSERT_EQ(sums.size(), c.holes.size()) << "every hole milled once";
        std::size_t cores = 0;
        for (const geom::Hole& hole : c.holes) {
            const HoleSums& s = sums.at(hole.faceIndex);
            const double depth = hole.topZ - finalZ(c, hole);
            EXPECT_EQ(s.firstArcZ, hole.topZ);
            EXPECT_NEAR(s.helixSweep / kTwoPi * c.params.pitchMm, depth, 1e-9);
            EXPECT_EQ(s.lastHelixZ, finalZ(c, hole)) << "final Z exact";
            EXPECT_NEAR(s.flatSweep, kTwoPi * (c.params.finishingCircle ? 2 : 1), 1e-9);
            cores += coreStands(c, hole);
        }
        EXPECT_EQ(result->warnings.size(), cores);
        const ops::MotionCounts counts = ops::countMotions(tp);
        EXPECT_EQ(result->counts.helices, counts.helices);
        EXPECT_EQ(result->counts.arcs, static_cast<int>(c.holes.size()) * (c.params.finishingCircle ? 4 : 2));
    }
}

TEST(HelixOp, HalfTurnsEndOppositeEachOtherAndTheLastIsShortened)
{
    ops::HelixParams p;
    p.heights = {20, 5, 0, 0};
    p.pitchMm = 2;  // 3.5 mm deep: three half turns of 1 mm and one of 0.5 mm (90 degrees)
    const geom::Hole hole{1, {10, 20}, 16, 0, -3.5, false};
    auto result = ops::computeHelix({hole}, p, ops::test::toolController(8), 0);
    ASSERT_TRUE(result) << result.error().message;
    std::vector<toolpath::Arc> arcs;
    for (const toolpath::Record& r : result->toolpath.records())
        if (const auto* arc = std::get_if<toolpath::Arc>(&r))
            arcs.push_back(*arc);
    ASSERT_EQ(arcs.size(), 4u + 2u);
    EXPECT_EQ(arcs[0].to, (toolpath::Vec3{6, 20, -1}));
    EXPECT_EQ(arcs[1].to, (toolpath::Vec3{14, 20, -2}));
    EXPECT_EQ(arcs[2].to, (toolpath::Vec3{6, 20, -3}));
    EXPECT_NEAR(arcs[3].to.x, 10, 1e-12);  // counter-clockwise (climb) a quarter on from (6, 20)
    EXPECT_NEAR(arcs[3].to.y, 16, 1e-12);
    EXPECT_EQ(arcs[3].to.z, -3.5);
    EXPECT_EQ(arcs[3].center, (toolpath::Vec3{10, 20, -3}));
    EXPECT_FALSE(arcs[3].clockwise);
    EXPECT_TRUE(result->warnings.empty());  // 8 mm tool in a 16 mm hole: no core
}

TEST(HelixOp, ALastPieceShorterThanTheToleranceLengthensTheLastHalfTurn)
{
    ops::HelixParams p;
    p.heights = {20, 5, 0, 0};
    p.pitchMm = 2;
    const geom::Hole hole{1, {0, 0}, 16, 0, -2.000001, false};
    auto result = ops::computeHelix({hole}, p, ops::test::toolController(8), 0);
    ASSERT_TRUE(result);
    std::vector<toolpath::Arc> helix;
    for (const toolpath::Record& r : result->toolpath.records())
        if (const auto* arc = std::get_if<toolpath::Arc>(&r); arc && arc->to.z != arc->center.z)
            helix.push_back(*arc);
    ASSERT_EQ(helix.size(), 2u);
    EXPECT_EQ(helix[1].to.z, -2.000001);
    EXPECT_GT(base::distance(helix[1].to.xy(), {4, 0}), 0);  // just past the start point, not on it
}

TEST(HelixOp, DepthsFromTheParametersWhenNotFromTheHoles)
{
    ops::HelixParams p;
    p.heights = {20, 5, -1, -4};
    p.depthsFromHoles = false;
    p.finishingCircle = true;
    const geom::Hole hole{1, {0, 0}, 12, 0, -30, true};
    auto result = ops::computeHelix({hole}, p, ops::test::toolController(6), 0);
    ASSERT_TRUE(result);
    double lowest = 100;
    for (const toolpath::Record& r : result->toolpath.records())
        if (const auto* arc = std::get_if<toolpath::Arc>(&r))
            lowest = std::min(lowest, arc->to.z);
    EXPECT_EQ(lowest, -4);
    EXPECT_EQ(std::get<toolpath::Linear>(result->toolpath.record(3)).to.z, -1);  // plunge to start
}

TEST(HelixOp, ACoreLeftInABlindHoleWarnsAndTheToolLeavesStraightUp)
{
    ops::HelixParams p;
    p.name = "Bore";
    p.heights = {20, 5, 0, 0};
    const geom::Hole hole{1, {0, 0}, 30, 0, -3, false};
    auto result = ops::computeHelix({hole}, p, ops::test::toolController(6), 0);  // radius 12 > 3
    ASSERT_TRUE(result);
    ASSERT_EQ(result->warnings.size(), 1u);
    EXPECT_EQ(result->warnings[0].message,
              "helix \"Bore\": hole at (0, 0) of 30 mm diameter: the 6 mm tool leaves a core of "
              "18 mm diameter standing (tool narrower than half the hole)");
    const auto& exit = std::get<toolpath::Rapid>(result->toolpath.record(result->toolpath.size() - 2));
    EXPECT_NEAR(base::distance(exit.to.xy(), {0, 0}), 12, 1e-9);

    const geom::Hole through{1, {0, 0}, 30, 0, -3, true};  // the core falls out
    result = ops::computeHelix({through}, p, ops::test::toolController(6), 0);
    ASSERT_TRUE(result);
    EXPECT_TRUE(result->warnings.empty());
}

TEST(HelixOp, Errors)
{
    const geom::Hole hole{7, {12.5, -3}, 8, 0, -5, false};
    const ops::ToolController tc = ops::test::toolController(6);
    ops::HelixParams p;
    p.name = "H";
    p.heights = {20, 5, 0, 0};
    auto message = [&](const std::vector<geom::Hole>& holes, const ops::HelixParams& params,
                       const ops::ToolController& t) {
        auto result = ops::computeHelix(holes, params, t, 0);
        return result ? std::string("no error") : result.error().message;
    };
    EXPECT_EQ(message({}, p, tc), "helix \"H\": no holes selected");
    EXPECT_EQ(message({hole}, p, ops::test::toolController(8)),
              "helix \"H\": the 8 mm tool does not fit the hole at (12.5, -3) of 8 mm diameter");
    ops::HelixParams stock = p;
    stock.radialStockMm = 1;
    EXPECT_EQ(message({hole}, stock, tc),
              "helix \"H\": the 6 mm tool does not fit the hole at (12.5, -3) of 8 mm diameter with 1 mm radial stock");
    stock.radialStockMm = -0.1;
    EXPECT_EQ(message({hole}, stock, tc), "helix \"H\": radial stock must not be negative, got -0.1 mm");
    ops::HelixParams pitch = p;
    pitch.pitchMm = 0;
    EXPECT_EQ(message({hole}, pitch, tc), "helix \"H\": pitch must be positive, got 0 mm");
    pitch.pitchMm = 13;
    ops::ToolController shortTool = tc;
    shortTool.tool.fluteLengthMm = 12;
    EXPECT_EQ(message({hole}, pitch, shortTool),
              "helix \"H\": pitch 13 mm is more than the cutting length 12 mm of tool 4");
    shortTool.tool.fluteLengthMm = 4;
    EXPECT_EQ(message({hole}, p, shortTool), "helix \"H\": hole at (12.5, -3) of 8 mm diameter: cut depth 5 mm is "
                                             "beyond the cutting length 4 mm of tool 4");
    ops::HelixParams low = p;
    low.heights.safeZ = -1;
    EXPECT_EQ(message({hole}, low, tc),
              "helix \"H\": hole at (12.5, -3) of 8 mm diameter: safe height -1 must be above the start depth 0");
    ops::ToolController noFeed = tc;
    noFeed.cuttingFeedMmPerMin = 0;
    EXPECT_EQ(message({hole}, p, noFeed), "helix \"H\": cutting feed must be positive, got 0 mm/min");
}

TEST(HelixOp, ReportsProgressAndStopsWhenCancelled)
{
    std::mt19937 random(5);
    const std::vector<geom::Hole> holes = ops::test::randomHoles(random, 4, 20, 30);
    ops::HelixParams p;
    p.heights = {40, 12, 0, 0};
    ops::test::expectProgressAndCancel(
        [&](const ops::Progress& progress) {
            return ops::computeHelix(holes, p, ops::test::toolController(10), 0, progress);
        },
        holes.size(), "helix \"Helix\"");
}

TEST(HelixOp, GoldenTrace)
{
    ops::HelixParams p;
    p.name = "Helix golden";
    p.heights = {25, 3, 0, 0};
    p.pitchMm = 1.6;  // half turns of 0.8 mm: every hole ends with a shortened one
    p.finishingCircle = true;
    p.climb = false;
    p.radialStockMm = 0.1;
    const std::vector<geom::Hole> holes = {
        {1, {40, 10}, 12, 0, -4, true},     // through: 0.5 mm breakthrough, a partial last half turn
        {2, {0, 0}, 10, -2, -5, false},     // blind
        {3, {35, -30}, 20, 0, -1.5, false}  // a 6 mm tool leaves a core: straight up
    };
    auto result = ops::computeHelix(holes, p, ops::test::toolController(6), 2);
    ASSERT_TRUE(result) << result.error().message;
    ops::test::expectGolden("holes", "helix.trace", toolpath::traceOf(result->toolpath));
    ops::test::expectFeedKindsAgreeWithSections(result->toolpath);
}
