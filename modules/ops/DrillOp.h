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
    Heights heights;  // clearance and safe for all holes (safe = the R plane)
    bool depthsFromHoles = true;  // per hole: startZ = hole top, finalZ = hole bottom (through:
                                  // minus breakthroughMm); false: heights.startZ/finalZ for all
    double peckMm = 0;         // Peck / ChipBreak
    double dwellSeconds = 0;   // DrillDwell
    bool retractToClearance = false;  // G98 (clearance) instead of G99 (safe/R plane) between holes
    bool keepOrder = false;           // holes in the given order
    bool depthAtShoulder = false;     // finalZ is the full-diameter depth: the tip goes deeper by
                                      // the point length (tool.pointAngleDeg)
    double breakthroughMm = 0;        // through holes: extra depth below the hole bottom
};

// Visiting order of points that shortens the rapid path from `start`: nearest neighbour, then
// 2-opt until no exchange helps. Returns indices into `points`.
std::vector<int> shortRapidOrder(const std::vector<base::Vec2>& points, base::Vec2 start);

base::Result<OpResult> computeDrill(const std::vector<geom::Hole>& holes, const DrillParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
