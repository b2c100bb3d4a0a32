// The pocket operation: checks, the tool-centre region, the pattern computed once (offset or
// zig-zag, clean-up detours), entries planned once, then the same program written at each level
// with the wall finishing pass and the floor finishing level where asked.
#include "ops/PocketOp.h"

#include "base/NumberFormat.h"
#include "geom/RegionOps.h"
#include "ops/pocket/Cleanup.h"
#include "ops/pocket/Patterns.h"
#include "ops/pocket/Program.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops {

namespace {

using namespace pocket;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

// The diagonal of the regions' bounding box (an arc's whole circle counted): no pattern's passes,
// at any angle, spread over more; what the stepover is weighed by.
double widestExtent(const std::vector<geom::Region>& regions)
{
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](geom::Vec2 p, double r) {
        x0 = std::min(x0, p.x - r), x1 = std::max(x1, p.x + r), y0 = std::min(y0, p.y - r), y1 = std::max(y1, p.y + r);
    };
    for (const geom::Region& region : regions)
        for (const geom::Segment& s : region.outer.segments) {
            add(s.start, 0);
            if (s.isArc())
                add(s.center, s.radius());
        }
    return std::hypot(x1 - x0, y1 - y0);
}

base::Status check(const std::string& what, const std::vector<geom::Region>& regions, const PocketParams& p,
                   const ToolController& tc)
{
    if (base::Status s = checkToolController(what, tc); !s)
        return s;
    if (base::Status s = checkHeights(what, p.heights); !s)
        return s;
    if (base::Status s = checkCuttingLength(what, p.heights, tc.tool); !s)
        return s;
    if (regions.empty() || !(geom::totalArea(regions) > 0))
        return opError(what, "no regions to pocket (the selection is empty)");
    const double d = tc.tool.diameterMm;
    const double stepover = p.stepover(d);
    if (!(stepover > 0) || stepover > d + 1e-9)
        return opError(what, "stepover " + fmt(stepover) + " mm must be positive and at most the tool diameter " +
                                 fmt(d) + " mm");
    if (p.stepDownMm < 0)
        return opError(what, "step-down must not be negative, got " + fmt(p.stepDownMm) + " mm");
    if (p.wallStockMm < 0 || p.floorStockMm < 0)
        return opError(what, "stock to leave must not be negative (walls " + fmt(p.wallStockMm) + " mm, floor " +
                                 fmt(p.floorStockMm) + " mm)");
    if (p.heights.finalZ + p.floorStockMm >= p.heights.startZ)
        return opError(what, "floor stock " + fmt(p.floorStockMm) +
                                 " mm leaves nothing to cut between the start depth " + fmt(p.heights.startZ) +
                                 " and the final depth " + fmt(p.heights.finalZ));
    if (!(p.toleranceMm > 0))
        return opError(what, "tolerance must be positive, got " + fmt(p.toleranceMm) + " mm");
    const double depth = p.heights.startZ - p.heights.finalZ;
    if (base::Status s = checkRepeats(what, "step-down", p.stepDownMm, depth - p.floorStockMm, "levels"); !s)
        return s;
    if (p.entry == EntryKind::Helix)
        if (base::Status s = checkRepeats(what, "helix pitch", p.helixPitchMm, depth, "turns"); !s)
            return s;
    if (base::Status s = checkRepeats(what, "stepover", stepover, widestExtent(regions), "passes"); !s)
        return s;
    return checkEntry(what, entryRequest(p), tc);
}

std::vector<double> levelsOf(const PocketParams& p)
{
    std::vector<double> levels = stepDownLevels(p.heights.startZ, p.heights.finalZ + p.floorStockMm, p.stepDownMm);
    if (p.finishFloor)
        levels.push_back(p.heights.finalZ);
    return levels;
}

}  // namespace

base::Result<OpResult> computePocket(const std::vector<geom::Region>& regions, const PocketParams& params,
                                     const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = "pocket \"" + params.name + "\"";
    if (base::Status s = check(what, regions, params, tc); !s)
        return s.error();
    const double radius = tc.tool.diameterMm / 2;
    const double tol = params.toleranceMm;
    const std::vector<geom::Region> toolCentre = geom::offsetRegions(regions, -(radius + params.wallStockMm), tol);
    if (toolCentre.empty())
        return opError(what, "tool diameter " + fmt(tc.tool.diameterMm) + " mm" +
                                 (params.wallStockMm > 0 ? " with wall stock " + fmt(params.wallStockMm) + " mm" : "") +
                                 " does not fit the pocket");

    PatternInput input{&toolCentre,          params.stepover(tc.tool.diameterMm), radius, params.climb, tol,
                       params.zigZagAngleDeg};
    std::optional<std::vector<Cut>> cuts =
        params.pattern == PocketPattern::Offset ? offsetPattern(input, progress) : zigZagPattern(input, progress);
    if (!cuts)
        return cancelledError(what);
    OpResult result;
    // Clean-up is needed only where the pattern does not cover by construction. Offset: a point of
    // the tool-centre region lies within one ring spacing of the last ring around it, so spacings up
    // to the radius leave nothing. Zig-zag: a point lies within half a spacing of a line or of the
    // wall pass. Both less the offsets' safety margins and fitting tolerance. (The union of many
    // overlapping footprints is by far the most expensive step, so it is skipped where it cannot
    // find anything.)
    const double spacing = std::min(input.stepover, 2 * radius - 2 * tol);
    const double covered = params.pattern == PocketPattern::Offset ? spacing : spacing / 2;
    const CleanupResult cleanup =
        covered <= radius - 4 * tol ? CleanupResult{} : addCleanup(*cuts, toolCentre, radius, spacing, tol);
    if (cleanup.uncutArea > 0)
        result.warn(what + ": " + fmt(cleanup.uncutArea) +
                    " mm^2 between passes could not be reached by clean-up moves");
    if (!progress.step(0.6))
        return cancelledError(what);

    // Corners the tool cannot reach: the floor (less wall stock) beyond the tool's reach.
    const std::vector<geom::Region> floor =
        params.wallStockMm > 0 ? geom::offsetRegions(regions, -params.wallStockMm, tol) : regions;
    const double left =
        geom::totalArea(geom::subtract(floor, geom::offsetRegions(toolCentre, radius + 2 * tol, tol), tol));
    if (left > std::max(1e-3, 10 * tol * tol))
        result.warn(what + ": " + fmt(left) + " mm^2 in corners the tool (diameter " + fmt(tc.tool.diameterMm) +
                    " mm) cannot reach is left uncut");

    const EntrySettings entry = entrySettings(entryRequest(params), tc);
    const geom::RegionIndex centreIndex(toolCentre);
    EntryPlanner planner(centreIndex, entry);
    const Program rough = makeProgram(std::move(*cuts), centreIndex, planner);

    std::vector<geom::Region> finishRegion;
    std::optional<geom::RegionIndex> finishIndex;
    std::optional<EntryPlanner> finishPlanner;
    Program finish;
    if (params.finishWalls) {
        finishRegion = params.wallStockMm > 0 ? geom::offsetRegions(regions, -radius, tol) : toolCentre;
        finishIndex.emplace(finishRegion);
        finishPlanner.emplace(*finishIndex, entry);
        finish =
            makeProgram(wallLoops(finishRegion, params.climb, rough.cuts.back().end()), *finishIndex, *finishPlanner);
    }
    const int fallbacks = planner.helixFallbacks() + (finishPlanner ? finishPlanner->helixFallbacks() : 0);
    if (fallbacks > 0)
        result.warn(what + ": the helix of diameter " + fmt(2 * entry.helixRadius) + " mm fits nowhere near " +
                    std::to_string(fallbacks) + " cut start(s); ramped there instead");

    PathWriter out(result.toolpath, operationIndex);
    out.add(sectionBegin(params.name, "pocket", tc, {toolpath::FeedKind::Entry, toolpath::FeedKind::Finishing}));
    // The walls' last pass and the floor's own level (finishFloor: the last one) are finishing.
    const Feed finishing = feedOf(tc, toolpath::FeedKind::Finishing);
    const Clearances clearances{params.heights.clearanceZ, params.heights.safeZ};
    const std::vector<double> levels = levelsOf(params);
    double top = params.heights.startZ;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const bool floorPass = params.finishFloor && i + 1 == levels.size();
        writeProgram(out, rough, top, levels[i], clearances, entry, floorPass ? finishing : entry.cuttingFeed);
        if (params.finishWalls)
            writeProgram(out, finish, top, levels[i], clearances, entry, finishing);
        top = levels[i];
        if (!progress.step(0.6 + 0.4 * static_cast<double>(i + 1) / static_cast<double>(levels.size())))
            return cancelledError(what);
    }
    out.rapid({out.position().x, out.position().y, params.heights.clearanceZ});
    out.add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
