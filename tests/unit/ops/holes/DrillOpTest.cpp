// Drilling: Cycle records over generated hole sets (points on the axes bit for bit, depths with
// the point angle, grouping, order, G98/G99), their expansion into moves, every error, a golden.
#include "ops/DrillOp.h"
#include "HoleTestSupport.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

using namespace camwb;
using ops::test::uniform;
using toolpath::CycleKind;

namespace {

struct DrillCase {
    std::vector<geom::Hole> holes;
    ops::DrillParams params;
    ops::ToolController tc;
};

DrillCase randomCase(std::mt19937& random)
{
    DrillCase c;
    c.holes = ops::test::randomHoles(random, 1 + random() % 12, 5, 6);
    const bool fewDepths = random() % 2;  // then many holes share top and bottom: grouped cycles
    for (geom::Hole& hole : c.holes) {
        hole.diameterMm = 5;  // the drill's size (or a hundredth under)
        if (fewDepths) {
            hole.topZ = random() % 2 ? 0 : -2;
            hole.bottomZ = random() % 2 ? -8 : -15;
        }
    }
    const CycleKind kinds[] = {CycleKind::Drill, CycleKind::DrillDwell, CycleKind::Peck, CycleKind::ChipBreak};
    ops::DrillParams& p = c.params;
    p.name = "D";
    p.cycle = kinds[random() % 4];
    p.heights = {50, 8, 0, 0};
    p.peckMm = uniform(random, 0.5, 4);
    p.dwellSeconds = random() % 2 ? uniform(random, 0, 2) : 0;
    p.retractToClearance = random() % 2;
    p.keepOrder = random() % 4 == 0;
    p.depthAtShoulder = random() % 2;
    p.breakthroughMm = uniform(random, 0, 1.5);
    const double angles[] = {0, 118, 135, 140};
    c.tc = ops::test::toolController(5 + 0.01 * (random() % 2));  // a hundredth over is allowed
    c.tc.tool.kind = "drill";
    c.tc.tool.pointAngleDeg = angles[random() % 4];
    return c;
}

double tipLength(const toolpath::Tool& tool)
{
    return tool.pointAngleDeg > 0 ? tool.diameterMm / 2 / std::tan(tool.pointAngleDeg / 2 * std::numbers::pi / 180) : 0;
}

double expectedBottom(const DrillCase& c, const geom::Hole& hole)
{
    const double bottom = hole.through ? hole.bottomZ - c.params.breakthroughMm : hole.bottomZ;
    return bottom - (c.params.depthAtShoulder ? tipLength(c.tc.tool) : 0);
}

std::vector<toolpath::Cycle> cyclesOf(const toolpath::Toolpath& tp)
{
    std::vector<toolpath::Cycle> cycles;
    for (const toolpath::Record& r : tp.records())
        if (const auto* cycle = std::get_if<toolpath::Cycle>(&r))
            cycles.push_back(*cycle);
    return cycles;
}

// The moves of every hole of `cycle` from `at` (updated), as toolpath::expandCycleHole gives them.
std::vector<toolpath::Record> expand(const toolpath::Cycle& cycle, toolpath::Vec3& at)
{
    std::vector<toolpath::Record> out;
    for (const toolpath::Vec3& hole : cycle.holes) {
        for (const toolpath::Record& r : toolpath::expandCycleHole(cycle, hole, at, {3000, true})) {
            if (const auto* rapid = std::get_if<toolpath::Rapid>(&r))
                at = rapid->to;
            if (const auto* line = std::get_if<toolpath::Linear>(&r))
                at = line->to;
            out.push_back(r);
        }
    }
    return out;
}

// Checks the expanded moves of one cycle: feeds only on the hole axes, down to the bottom exactly,
// pecks no deeper than the peck, full retracts (peck) or short lifts (chip breaking).
void checkExpansion(const toolpath::Cycle& cycle, const std::vector<toolpath::Record>& moves)
{
    toolpath::Vec3 at{NAN, NAN, NAN};
    int feeds = 0, dwells = 0, retractsToR = 0;
    double deepest = INFINITY;
    for (const toolpath::Record& r : moves) {
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            if (!std::isnan(at.x) && !(rapid->to.xy() == at.xy()))
                EXPECT_GE(at.z, cycle.retractZ) << "sideways below the R plane";
            if (rapid->to.z == cycle.retractZ && at.z < cycle.retractZ)
                ++retractsToR;
            at = rapid->to;
        } else if (const auto* line = std::get_if<toolpath::Linear>(&r)) {
            EXPECT_TRUE(line->to.xy() == at.xy()) << "a feed off the hole axis";
            EXPECT_LT(line->to.z, at.z);
            if (cycle.kind == CycleKind::Peck || cycle.kind == CycleKind::ChipBreak)
                EXPECT_LE(std::min(cycle.topZ, deepest) - line->to.z, cycle.peckMm + 1e-12);
            EXPECT_EQ(line->feedMmPerMin, cycle.feedMmPerMin);
            deepest = std::min(deepest, line->to.z);
            ++feeds;
            at = line->to;
        } else if (std::holds_alternative<toolpath::Dwell>(r)) {
            EXPECT_EQ(at.z, cycle.bottomZ);
            ++dwells;
        }
        if (at.z == cycle.bottomZ)
            deepest = INFINITY;  // the next hole starts from its top
    }
    const int holes = static_cast<int>(cycle.holes.size());
    EXPECT_EQ(at.z, toolpath::cycleReturnZ(cycle));
    EXPECT_EQ(dwells, cycle.dwellSeconds > 0 ? holes : 0);
    const bool pecking = cycle.kind == CycleKind::Peck || cycle.kind == CycleKind::ChipBreak;
    const int feedsPerHole =
        pecking ? static_cast<int>(std::ceil((cycle.topZ - cycle.bottomZ) / cycle.peckMm - 1e-9)) : 1;
    EXPECT_EQ(feeds, holes * feedsPerHole);
    // Chip breaking never goes back up to R between pecks; peck drilling does after every peck.
    // (G99 adds the return to R after each hole.)
    EXPECT_EQ(retractsToR,
              (cycle.kind == CycleKind::Peck ? holes * (feedsPerHole - 1) : 0) + (cycle.returnToClearance ? 0 : holes));
}

}  // namespace

TEST(DrillOp, GeneratedHoleSetsDrillEveryHoleOnItsAxisAtItsDepth)
{
    std::mt19937 random(77);
    for (int trial = 0; trial < 300; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const DrillCase c = randomCase(random);
        auto result = ops::computeDrill(c.holes, c.params, c.tc, 1);
        ASSERT_TRUE(result) << result.error().message;
        const toolpath::Toolpath& tp = result->toolpath;
        EXPECT_EQ(std::get<toolpath::SectionBegin>(tp.record(0)).strategy, "drilling");
        const auto& first = std::get<toolpath::Rapid>(tp.record(1));
        EXPECT_EQ(first.to.z, c.params.heights.clearanceZ);

        const std::vector<toolpath::Cycle> cycles = cyclesOf(tp);
        std::vector<int> visited;
        toolpath::Vec3 at = first.to;
        for (std::size_t k = 0; k < cycles.size(); ++k) {
            const toolpath::Cycle& cycle = cycles[k];
            EXPECT_EQ(cycle.kind, c.params.cycle);
            EXPECT_EQ(cycle.clearanceZ, c.params.heights.clearanceZ);
            EXPECT_EQ(cycle.retractZ, c.params.heights.safeZ);
            EXPECT_EQ(cycle.returnToClearance, c.params.retractToClearance);
            EXPECT_EQ(cycle.feedMmPerMin, c.tc.cuttingFeedMmPerMin);
            EXPECT_EQ(cycle.dwellSeconds, c.params.cycle == CycleKind::Drill ? 0 : c.params.dwellSeconds);
            if (k > 0)
                EXPECT_FALSE(cycle.topZ == cycles[k - 1].topZ && cycle.bottomZ == cycles[k - 1].bottomZ)
                    << "two cycles in a row with the same depths";
            for (const toolpath::Vec3& point : cycle.holes) {
                const auto hole = std::find_if(c.holes.begin(), c.holes.end(), [&](const geom::Hole& h) {
                    return h.center.x == point.x && h.center.y == point.y;
                });
                ASSERT_NE(hole, c.holes.end()) << "drilled off every hole axis";
                EXPECT_EQ(point.z, hole->topZ);
                EXPECT_EQ(cycle.topZ, hole->topZ);
                EXPECT_NEAR(cycle.bottomZ, expectedBottom(c, *hole), 1e-12);
                visited.push_back(static_cast<int>(hole - c.holes.begin()));
            }
            checkExpansion(cycle, expand(cycle, at));
        }
        std::vector<int> order = visited;
        std::sort(order.begin(), order.end());
        EXPECT_EQ(std::adjacent_find(order.begin(), order.end()), order.end()) << "a hole drilled twice";
        ASSERT_EQ(visited.size(), c.holes.size());
        std::vector<base::Vec2> centres;
        for (const geom::Hole& hole : c.holes)
            centres.push_back(hole.center);
        if (c.params.keepOrder || c.holes.size() < 3)
            EXPECT_EQ(visited, order);
        else
            EXPECT_EQ(visited, ops::shortRapidOrder(centres, centres.front()));
        // Back at clearance at the end: the last cycle's G98 return, or a rapid.
        const toolpath::Record& last = tp.record(tp.size() - 2);
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&last))
            EXPECT_EQ(rapid->to.z, c.params.heights.clearanceZ);
        else
            EXPECT_TRUE(std::get<toolpath::Cycle>(last).returnToClearance);
        EXPECT_EQ(result->counts.cycles, static_cast<int>(cycles.size()));
        EXPECT_TRUE(result->warnings.empty());
    }
}

TEST(DrillOp, PointAngleAndBreakthroughInTheDepth)
{
    ops::DrillParams p;
    p.heights = {30, 5, 0, 0};
    p.depthAtShoulder = true;
    p.breakthroughMm = 1;
    ops::ToolController tc = ops::test::toolController(8);
    tc.tool.pointAngleDeg = 118;
    const std::vector<geom::Hole> holes = {{1, {0, 0}, 8, 0, -10, false}, {2, {20, 0}, 8, 0, -10, true}};
    auto result = ops::computeDrill(holes, p, tc, 0);
    ASSERT_TRUE(result);
    const std::vector<toolpath::Cycle> cycles = cyclesOf(result->toolpath);
    ASSERT_EQ(cycles.size(), 2u);
    const double tip = 4 / std::tan(59 * std::numbers::pi / 180);  // 2.4034 mm
    EXPECT_NEAR(tip, 2.4034, 1e-4);
    EXPECT_DOUBLE_EQ(cycles[0].bottomZ, -10 - tip);
    EXPECT_DOUBLE_EQ(cycles[1].bottomZ, -11 - tip);

    p.depthAtShoulder = false;  // the point angle is then not added
    result = ops::computeDrill(holes, p, tc, 0);
    EXPECT_EQ(cyclesOf(result->toolpath)[0].bottomZ, -10);
    EXPECT_EQ(cyclesOf(result->toolpath)[1].bottomZ, -11);

    p.depthsFromHoles = false;  // the parameters' depths for all holes, no breakthrough: one cycle
    p.heights = {30, 5, -1, -6};
    result = ops::computeDrill(holes, p, tc, 0);
    ASSERT_EQ(cyclesOf(result->toolpath).size(), 1u);
    EXPECT_EQ(cyclesOf(result->toolpath)[0].topZ, -1);
    EXPECT_EQ(cyclesOf(result->toolpath)[0].bottomZ, -6);
}

TEST(DrillOp, G98ReturnsToClearanceAndG99ToTheRPlane)
{
    ops::DrillParams p;
    p.heights = {30, 5, 0, 0};
    const std::vector<geom::Hole> holes = {{1, {0, 0}, 6, 0, -10, false}, {2, {20, 0}, 6, 0, -10, false}};
    for (bool g98 : {true, false}) {
        p.retractToClearance = g98;
        auto result = ops::computeDrill(holes, p, ops::test::toolController(6), 0);
        ASSERT_TRUE(result);
        const toolpath::Cycle cycle = cyclesOf(result->toolpath).at(0);
        EXPECT_EQ(cycle.returnToClearance, g98);
        EXPECT_EQ(toolpath::cycleReturnZ(cycle), g98 ? 30 : 5);
        // G99 leaves the tool at R: a rapid up to clearance ends the operation.
        EXPECT_EQ(result->toolpath.size(), g98 ? 4u : 5u);
    }
}

TEST(DrillOp, DrillMuchSmallerThanTheHoleWarns)
{
    ops::DrillParams p;
    p.name = "D";
    p.heights = {30, 5, 0, 0};
    auto result = ops::computeDrill({{1, {1, 2}, 8, 0, -10, false}}, p, ops::test::toolController(6.8), 0);
    ASSERT_TRUE(result);
    ASSERT_EQ(result->warnings.size(), 1u);
    EXPECT_EQ(result->warnings[0].message,
              "drilling \"D\": hole at (1, 2) of 8 mm diameter: the 6.8 mm drill leaves it undersize");
}

TEST(DrillOp, Errors)
{
    const geom::Hole hole{3, {10, -4.5}, 6, 0, -12, false};
    ops::DrillParams p;
    p.name = "D";
    p.heights = {30, 5, 0, 0};
    const ops::ToolController tc = ops::test::toolController(6);
    auto message = [](const std::vector<geom::Hole>& holes, const ops::DrillParams& params,
                      const ops::ToolController& t) {
        auto result = ops::computeDrill(holes, params, t, 0);
        return result ? std::string("no error") : result.error().message;
    };
    EXPECT_EQ(message({}, p, tc), "drilling \"D\": no holes selected");
    for (CycleKind kind : {CycleKind::Peck, CycleKind::ChipBreak}) {
        ops::DrillParams peck = p;
        peck.cycle = kind;
        EXPECT_EQ(message({hole}, peck, tc), std::string("drilling \"D\": peck depth must be positive for a ") +
                                                 (kind == CycleKind::Peck ? "peck" : "chip-breaking") +
                                                 " cycle, got 0 mm");
    }
    ops::DrillParams dwell = p;
    dwell.cycle = CycleKind::DrillDwell;
    dwell.dwellSeconds = -1;
    EXPECT_EQ(message({hole}, dwell, tc), "drilling \"D\": dwell must not be negative, got -1 s");
    ops::DrillParams tap = p;
    tap.cycle = CycleKind::Tap;
    EXPECT_EQ(message({hole}, tap, tc),
              "drilling \"D\": the cycle must be drill, drill with dwell, peck or chip breaking");
    EXPECT_EQ(message({hole}, p, ops::test::toolController(6.02)),
              "drilling \"D\": the 6.02 mm drill is larger than the hole at (10, -4.5) of 6 mm diameter");
    EXPECT_EQ(message({hole}, p, ops::test::toolController(6.01)), "no error");
    ops::ToolController shortDrill = tc;
    shortDrill.tool.fluteLengthMm = 11;
    EXPECT_EQ(message({hole}, p, shortDrill), "drilling \"D\": hole at (10, -4.5) of 6 mm diameter: cut depth 12 mm is "
                                              "beyond the cutting length 11 mm of tool 4");
    ops::DrillParams tipDeep = p;  // 12 mm fits a 12.5 mm flute, but not with the 118 degree tip
    tipDeep.depthAtShoulder = true;
    shortDrill.tool.fluteLengthMm = 12.5;
    shortDrill.tool.pointAngleDeg = 118;
    EXPECT_EQ(message({hole}, p, shortDrill), "no error");
    EXPECT_NE(message({hole}, tipDeep, shortDrill).find("cut depth 13.8026 mm is beyond"), std::string::npos)
        << message({hole}, tipDeep, shortDrill);
    ops::DrillParams low = p;
    low.heights.safeZ = 0;
    EXPECT_EQ(message({hole}, low, tc),
              "drilling \"D\": hole at (10, -4.5) of 6 mm diameter: safe height 0 must be above the start depth 0");
    ops::ToolController noSpindle = tc;
    noSpindle.spindleRpm = 0;
    EXPECT_EQ(message({hole}, p, noSpindle), "drilling \"D\": spindle speed must be positive, got 0 rpm");
}

TEST(DrillOp, ReportsProgressAndStopsWhenCancelled)
{
    std::mt19937 random(9);
    const std::vector<geom::Hole> holes = ops::test::randomHoles(random, 6, 6, 6);
    ops::DrillParams p;
    p.heights = {30, 8, 0, 0};
    ops::test::expectProgressAndCancel(
        [&](const ops::Progress& progress) {
            return ops::computeDrill(holes, p, ops::test::toolController(6), 0, progress);
        },
        holes.size(), "drilling \"Drilling\"");
}

TEST(DrillOp, GoldenTrace)
{
    ops::DrillParams p;
    p.name = "Drill golden";
    p.cycle = CycleKind::Peck;
    p.peckMm = 3;
    p.heights = {25, 2, 0, 0};
    p.depthAtShoulder = true;
    p.breakthroughMm = 0.5;
    ops::ToolController tc = ops::test::toolController(6);
    tc.tool.pointAngleDeg = 118;
    const std::vector<geom::Hole> holes = {
        {1, {0, 0}, 6, 0, -10, false}, {2, {60, 0}, 6, 0, -10, false}, {3, {30, 0}, 6, 0, -10, false},
        {4, {30, 30}, 6, 0, -8, true}, {5, {0, 30}, 6, 0, -10, false}, {6, {60, 30}, 6, -2, -12, false},
    };
    auto result = ops::computeDrill(holes, p, tc, 5);
    ASSERT_TRUE(result) << result.error().message;
    ops::test::expectGolden("holes", "drill.trace", toolpath::traceOf(result->toolpath));
}
