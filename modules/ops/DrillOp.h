// The drilling operation: simple, dwell, peck (full retract) and chip-breaking cycles over holes,
// retracting to the safe (R, G99) or clearance plane (G98) between holes, in an order that
// shortens the rapids (nearest neighbour, then 2-opt) unless the user keeps their own order.
// Output as Cycle records: posts write native cycles or expand them (toolpath/CycleExpansion.h).
#pragma once

#include "geom/Hole.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::ops {

struct DrillParams {
    std::string name = "Drilling";
    toolpath::CycleKind cycle = toolpath::CycleKind::Drill;  // Drill, DrillDwell, Peck, ChipBreak

    Heights heights;                  // clearance and safe for all holes (safe = the R plane)
    bool depthsFromHoles = true;      // per hole: startZ = hole top, finalZ = hole bottom (through:
                                      // minus breakthroughMm); false: heights.startZ/finalZ for all
    double peckMm = 0;                // Peck / ChipBreak
    double dwellSeconds = 0;          // DrillDwell
    bool retractToClearance = false;  // G98 (clearance) instead of G99 (safe/R plane) between holes
    bool keepOrder = false;           // holes in the given order
    bool depthAtShoulder = false;     // finalZ is the full-diameter depth: the tip goes deeper by
                                      // the point length (tool.pointAngleDeg)
    double breakthroughMm = 0;        // through holes: extra depth below the hole bottom
};

// Records (each with SourceRef{operationIndex, i}): SectionBegin{name, "drilling", tool, feeds},
// Rapid over the first hole at clearance, one Cycle record for each run of holes (in visiting
// order) with the same top and bottom Z (retractZ = safe, topZ = hole top, holes = top centres,
// feed = cutting feed, dwell only for DrillDwell/Peck/ChipBreak), Rapid up to clearance when the
// last cycle returns to the R plane, SectionEnd. The order starts at the first hole given.
// Warnings: a drill smaller than a hole by more than 0.1 mm and 5 % (left undersize).
// Errors (nothing produced): no holes, tool controller and height checks, a cycle other than the
// four, peck <= 0 for Peck/ChipBreak, negative dwell or breakthrough, a point angle >= 180 with
// depthAtShoulder, a drill over 0.01 mm larger than a hole, depth beyond the flute length.
//
// Visiting order of points that shortens the rapid path from `start`: nearest neighbour, then
// 2-opt until no exchange helps. Returns indices into `points`.
std::vector<int> shortRapidOrder(const std::vector<base::Vec2>& points, base::Vec2 start);

base::Result<OpResult> computeDrill(const std::vector<geom::Hole>& holes, const DrillParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
