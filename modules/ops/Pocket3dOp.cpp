// The 3D pocket: checks, the levels (step-down plus the flat floors), then per level the tool-
// centre region from ToolCentreRegions (cut down to the rest material's reach when rest
// machining, and only the cuts that still remove material from the stock as cut so far), cleared with the 2.5D pocket's
// pattern, clean-up, entries and linking, entered from the level above. With a rest stock the toolpath is run through a
// copy of it to report how much of it cuts air.
#include "ops/Pocket3dOp.h"

#include "base/NumberFormat.h"
#include "geom/RegionOps.h"
#include "ops/pocket/Cleanup.h"
#include "ops/pocket/Patterns.h"
#include "ops/pocket/Program.h"
#include "ops/surface/AllCores.h"
#include "ops/surface/RestMaterial.h"
#include "ops/surface/SectionCheck.h"
#include "ops/surface/ToolCentre.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops {

namespace {

using namespace pocket;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

base::Status check(const std::string& what, const SurfaceInput& in, const Pocket3dParams& p, const ToolController& tc)
{
    if (base::Status s = checkToolController(what, tc); !s)
        return s;
    if (base::Status s = checkHeights(what, p.heights); !s)
        return s;
    if (base::Status s = checkCuttingLength(what, p.heights, tc.tool); !s)
        return s;
    if (base::Status s = surface::checkSurfaceInput(what, in, "rough"); !s)
        return s;
    const double d = tc.tool.diameterMm;
    const double stepover = p.stepover(d);
    if (!(stepover > 0) || stepover > d + 1e-9)
        return opError(what, "stepover " + fmt(stepover) + " mm must be positive and at most the tool diameter " +
                                 fmt(d) + " mm");
    if (!(p.stepDownMm > 0))
        return opError(what, "step-down must be positive, got " + fmt(p.stepDownMm) + " mm");
    if (!(p.sideStockMm >= 0) || !(p.bottomStockMm >= 0))
        return opError(what, "stock to leave must not be negative (side " + fmt(p.sideStockMm) + " mm, bottom " +
                                 fmt(p.bottomStockMm) + " mm)");
    if (!(p.toleranceMm > 0) || p.toleranceMm > 1)
        return opError(what, "tolerance must be in (0, 1] mm, got " + fmt(p.toleranceMm) + " mm");
    const double depth = p.heights.startZ - p.heights.finalZ;
    if (base::Status s = checkRepeats(what, "step-down", p.stepDownMm, depth, "levels"); !s)
        return s;
    if (p.entry == EntryKind::Helix)
        if (base::Status s = checkRepeats(what, "helix pitch", p.helixPitchMm, depth, "turns"); !s)
            return s;
    if (base::Status s =
            checkRepeats(what, "stepover", stepover,
                         std::hypot(in.stock.max.x - in.stock.min.x, in.stock.max.y - in.stock.min.y), "passes");
        !s)
        return s;
    if (p.restMachining && !in.restStock)
        return opError(what, "rest machining needs the stock the previous operations left, and there is none "
                             "(no operation before this one was simulated)");
    return checkEntry(what, entryRequest(p), tc);
}

// Step-down levels plus a level exactly on each flat floor (raised by the bottom stock) in range;
// a step level closer than the tolerance to a floor level gives way to it.
std::vector<double> levelsOf(const SurfaceInput& in, const Pocket3dParams& p)
{
    std::vector<double> levels = stepDownLevels(p.heights.startZ, p.heights.finalZ, p.stepDownMm);
    for (double floor : in.flatLevels) {
        const double z = floor + p.bottomStockMm;
        if (z >= p.heights.finalZ - 1e-9 && z < p.heights.startZ - p.toleranceMm)
            levels.push_back(z);
    }
    std::sort(levels.begin(), levels.end(), std::greater<>());
    std::vector<double> out;
    for (double z : levels) {
        if (!out.empty() && out.back() - z < p.toleranceMm) {
            const bool isFloor = std::any_of(in.flatLevels.begin(), in.flatLevels.end(),
                                             [&](double f) { return std::abs(f + p.bottomStockMm - z) < 1e-9; });
            if (isFloor)
                out.back() = z;  // the floor's exact level wins
            continue;
        }
        out.push_back(z);
    }
    return out;
}

struct LevelWriter {
    const Pocket3dParams& params;
    const ToolController& tc;
    EntrySettings entry;
    PathWriter& out;
    sim::HeightField* rest = nullptr;  // rest machining: the stock as cut so far
    int helixFallbacks = 0;
    double uncutArea = 0;

    // Clears `region` at `level`, entering from `top`; false when cancelled.
    bool write(const std::vector<geom::Region>& region, double top, double level, const Progress& progress)
    {
        const double radius = tc.tool.diameterMm / 2, tol = params.toleranceMm;
        PatternInput input{
            &region, params.stepover(tc.tool.diameterMm), radius, params.climb, tol, params.zigZagAngleDeg};
        std::optional<std::vector<Cut>> cuts = params.pattern == PocketPattern::Offset
                                                   ? offsetPattern(input, Progress{{}, progress.cancel})
                                                   : zigZagPattern(input, Progress{{}, progress.cancel});
        if (!cuts)
            return false;
        if (cuts->empty())
            return true;
        // As the 2.5D pocket: clean-up only where the pattern does not cover by construction.
        const double spacing = std::min(input.stepover, 2 * radius - 2 * tol);
        const double covered = params.pattern == PocketPattern::Offset ? spacing : spacing / 2;
        if (covered > radius - 4 * tol)
            uncutArea += addCleanup(*cuts, region, radius, spacing, tol).uncutArea;
        if (rest) {
            *cuts = surface::cutsThatCut(std::move(*cuts), *rest, level, tc.tool, tol);
            if (cuts->empty())
                return true;
        }
        const geom::RegionIndex index(region);
        EntryPlanner planner(index, entry);
        const Program program = makeProgram(std::move(*cuts), index, planner);
        helixFallbacks += planner.helixFallbacks();
        writeProgram(out, program, top, level, {params.heights.clearanceZ, params.heights.safeZ}, entry,
                     entry.cuttingFeed);
        return true;
    }
};

}  // namespace

base::Result<OpResult> computePocket3d(const SurfaceInput& input, const Pocket3dParams& params,
                                       const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = "3D pocket \"" + params.name + "\"";
    if (base::Status s = check(what, input, params, tc); !s)
        return s.error();
    const double tol = params.toleranceMm;
    const surface::ToolCentreRegions centres(*input.model, tc.tool, {params.sideStockMm, params.bottomStockMm, tol});
    if (!progress.step(0.05))
        return cancelledError(what);
    const std::vector<geom::Region> area = surface::toolCentreArea(input);
    const std::vector<double> levels = levelsOf(input, params);

    OpResult result;
    PathWriter out(result.toolpath, operationIndex);
    out.add(sectionBegin(params.name, "pocket3d", tc, {toolpath::FeedKind::Entry}));
    LevelWriter writer{params, tc, entrySettings(entryRequest(params), tc), out};
    std::optional<sim::HeightField> rest;
    if (params.restMachining) {
        rest.emplace(*input.restStock);
        writer.rest = &*rest;
    }
    double top = params.heights.startZ;
    int cleared = 0;
    // The levels' regions on all cores, then each level cleared in order.
    std::vector<std::vector<geom::Region>> regions(levels.size());
    const auto regionAt = [&](std::size_t i) {
        regions[i] = centres.at(levels[i], area);
        if (params.restMachining && !regions[i].empty())
            regions[i] = surface::restRegion(*input.restStock, levels[i], tc.tool.diameterMm / 2, regions[i], tol);
    };
    if (!surface::forEachOnAllCores(levels.size(), regionAt, progress, 0.05, 0.6))
        return cancelledError(what);
    // The regions come from the shadows of the model's upward triangles; its sections (another
    // algorithm on the same mesh) must agree that the tool keeps clear of it, or nothing is cut.
    const surface::SectionClearance clearance{tc.tool.diameterMm / 2 + params.sideStockMm, centres.fullRadiusHeightMm(),
                                              params.bottomStockMm, tol};
    if (auto bad = surface::firstLevelTouchingSection(*input.model, levels, regions, clearance))
        return opError(what, "internal check failed: at Z " + fmt(levels[*bad]) +
                                 " the area to clear comes closer to the model's section than the tool's radius "
                                 "and side stock; nothing is cut (please report this with the model)");
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const std::vector<geom::Region>& region = regions[i];
        if (!region.empty()) {
            const std::size_t before = result.toolpath.size();
            if (!writer.write(region, top, levels[i], progress))
                return cancelledError(what);
            if (result.toolpath.size() > before) {
                top = levels[i];
                ++cleared;
            }
        }
        if (!progress.step(0.6 + 0.35 * double(i + 1) / double(levels.size())))
            return cancelledError(what);
    }
    if (cleared == 0 && !params.restMachining)
        return opError(what, "the tool (diameter " + fmt(tc.tool.diameterMm) + " mm) fits at no level between " +
                                 fmt(params.heights.startZ) + " and " + fmt(params.heights.finalZ));
    if (out.hasPosition())
        out.rapid({out.position().x, out.position().y, params.heights.clearanceZ});
    out.add(toolpath::SectionEnd{});
    if (writer.helixFallbacks > 0)
        result.warn(what + ": the helix fits nowhere near " + std::to_string(writer.helixFallbacks) +
                    " cut start(s); ramped there instead");
    if (writer.uncutArea > 0)
        result.warn(what + ": " + fmt(writer.uncutArea) +
                    " mm^2 between passes could not be reached by clean-up moves");
    if (input.restStock) {
        const surface::StockFigures f = surface::simulateOn(*input.restStock, result.toolpath, tc.tool);
        result.warn(what + ": " + fmt(f.airMm) + " mm of " + fmt(f.airMm + f.cuttingMm) +
                    " mm of feed moves cut air in the stock the previous operations left");
    }
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
