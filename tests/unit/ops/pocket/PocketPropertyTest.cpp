// Property tests of the pocket over a corpus of generated shapes, both patterns, several tools
// and stepovers: no gouge (every sampled point of every feed move at least radius + wall stock
// from every boundary loop, inside the outer loops, outside the islands, not below the floor
// stock), rapids only at or above the safe height, and the pocket cleared (a raster of the tool
// footprint at the last level leaves at most 0.1 % of the reachable area).
#include "PocketTestSupport.h"

#include "geom/RegionOps.h"

#include <gtest/gtest.h>

#include <variant>

using namespace camwb;
using namespace camwb::ops::pocket::test;

namespace {

struct Config {
    ops::PocketPattern pattern;
    double diameter;
    double stepoverPercent;
    ops::EntryKind entry;
    double wallStock, floorStock;
    bool finishWalls, finishFloor;
    double angle;
};

std::string describe(const Config& c)
{
    return std::string(c.pattern == ops::PocketPattern::Offset ? "offset" : "zigzag") + " D" +
           std::to_string(c.diameter) + " stepover " + std::to_string(c.stepoverPercent) + "%";
}

void checkPocket(const Shape& shape, const Config& c)
{
    SCOPED_TRACE(shape.name + ", " + describe(c));
    ops::PocketParams p = baseParams();
    p.pattern = c.pattern;
    p.stepoverPercent = c.stepoverPercent;
    p.entry = c.entry;
    p.wallStockMm = c.wallStock;
    p.floorStockMm = c.floorStock;
    p.finishWalls = c.finishWalls;
    p.finishFloor = c.finishFloor;
    p.zigZagAngleDeg = c.angle;
    const ops::ToolController tc = toolOf(c.diameter);
    auto result = ops::computePocket(shape.regions, p, tc, 7);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const toolpath::Toolpath& tp = result->toolpath;
    ASSERT_GT(tp.size(), 4u);
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionBegin>(tp.record(0)));
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionEnd>(tp.record(tp.size() - 1)));

    const double radius = c.diameter / 2;
    // The finishing wall pass runs at zero wall stock; everything else keeps the stock.
    const double keep = radius + (c.finishWalls ? 0.0 : c.wallStock);
    const double floorZ = p.heights.finalZ + (c.finishFloor ? 0.0 : c.floorStock);
    for (std::size_t i = 0; i < tp.size(); ++i) {
        EXPECT_EQ(tp.source(i).operationIndex, 7);
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&tp.record(i)))
            EXPECT_GE(rapid->to.z, p.heights.safeZ - 1e-9) << "rapid below the safe height, record " << i;
    }
    const Loops loops = sampledLoops(shape.regions, 1e-4);
    int gouges = 0;
    for (const MovePoint& m : sampleFeedMoves(tp, 0.25)) {
        const geom::Vec2 xy = m.p.xy();
        const double d = distanceToLoops(shape.regions, xy);
        const bool inside = insideLoops(loops, xy);
        if ((d < keep - 1e-6 || !inside || m.p.z < floorZ - 1e-9) && ++gouges <= 5)
            ADD_FAILURE() << "record " << m.record << " at (" << m.p.x << ", " << m.p.y << ", " << m.p.z
                          << "): distance " << d << " (keep " << keep << "), inside " << inside;
    }
    EXPECT_EQ(gouges, 0);

    // Cleared at the last roughing level, over what the tool centre can reach grown by the radius.
    const std::vector<geom::Region> toolCentre =
        geom::offsetRegions(shape.regions, -(radius + c.wallStock), p.toleranceMm);
    const std::vector<geom::Region> reach = geom::offsetRegions(toolCentre, radius, p.toleranceMm);
    const double lastLevel = p.heights.finalZ + c.floorStock;
    const Coverage cov = rasterCoverage(reach, sampleFlatMovesAt(tp, lastLevel, 0.02), radius, 0.1);
    ASSERT_GT(cov.machinable, 1000);
    EXPECT_LE(static_cast<double>(cov.uncut), 1e-3 * static_cast<double>(cov.machinable))
        << cov.uncut << " of " << cov.machinable << " cells uncut";
}

class PocketProperty : public testing::TestWithParam<Config> {};

TEST_P(PocketProperty, NoGougeRapidsSafeAndCleared)
{
    for (const Shape& shape : shapeCorpus())
        checkPocket(shape, GetParam());
}

using ops::EntryKind;
using ops::PocketPattern;
INSTANTIATE_TEST_SUITE_P(
    Corpus, PocketProperty,
    testing::Values(Config{PocketPattern::Offset, 6, 50, EntryKind::Helix, 0, 0, false, false, 0},
                    Config{PocketPattern::Offset, 8, 75, EntryKind::Ramp, 0.3, 0.2, false, false, 0},
                    Config{PocketPattern::Offset, 4, 100, EntryKind::Plunge, 0, 0, false, false, 0},
                    Config{PocketPattern::Offset, 5, 40, EntryKind::Helix, 0.4, 0.3, true, true, 0},
                    Config{PocketPattern::ZigZag, 6, 50, EntryKind::Helix, 0, 0, false, false, 0},
                    Config{PocketPattern::ZigZag, 8, 80, EntryKind::Ramp, 0.25, 0, false, false, 30},
                    Config{PocketPattern::ZigZag, 4, 100, EntryKind::Plunge, 0, 0.5, false, false, 90},
                    Config{PocketPattern::ZigZag, 5, 60, EntryKind::Helix, 0.5, 0.2, true, true, -20}));

}  // namespace
