// The pocket operation: clears regions (outer boundary with islands) level by level with an offset
// (spiral inward from the walls) or zig-zag pattern, then a wall pass; stock on walls and floor,
// optional finishing of walls and floor; entry by helix, ramp or plunge. No gouges by
// construction (the tool centre stays in the region shrunk by radius + stock), no uncut slivers
// (clean-up moves are added where the rings leave material), corners the tool cannot reach left.
#pragma once

#include "geom/Region.h"
#include "ops/ContourOp.h"  // EntryKind
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::ops {

enum class PocketPattern { Offset, ZigZag };

struct PocketParams {
    std::string name = "Pocket";
    PocketPattern pattern = PocketPattern::Offset;
    double zigZagAngleDeg = 0;
    double stepoverPercent = 50;  // of the tool diameter; used when stepoverMm is 0
    double stepoverMm = 0;
    Heights heights;
    double stepDownMm = 0;  // 0 = one level
    double wallStockMm = 0;
    double floorStockMm = 0;
    bool finishWalls = false;  // a last wall pass at zero wall stock, per level
    bool finishFloor = false;  // a last level at finalZ at zero floor stock
    bool climb = true;
    EntryKind entry = EntryKind::Helix;
    double helixDiameterMm = 0;  // 0 = 90 % of the tool diameter
    double helixPitchMm = 1;
    double rampAngleDeg = 3;
    double toleranceMm = 0.01;
    double stepover(double toolDiameter) const
    {
        return stepoverMm > 0 ? stepoverMm : toolDiameter * stepoverPercent / 100.0;
    }
};

// `regions`: the floor to clear, seen from above (islands as holes). Plunge entry is refused for a
// tool that is not centre-cutting (Tool::centreCutting). Errors: empty regions, a tool that fits
// nowhere, bad stepover/stock/ramp angle/helix diameter or pitch, the common checks. Where a
// helix fits nowhere near a cut start, that cut ramps instead (with a warning); corners the tool
// cannot reach and material clean-up could not reach are reported in OpResult.warnings.
base::Result<OpResult> computePocket(const std::vector<geom::Region>& regions, const PocketParams& params,
                                     const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
