// What the helix and drilling operations share about holes: the per-hole depths, the visiting
// order (shortRapidOrder, declared in DrillOp.h, implemented in HoleOrder.cpp) and how an error
// names a hole. Internal to modules/ops.
#pragma once

#include "geom/Hole.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::ops {

// The heights for one hole: clearance and safe from `heights`; start and final from the hole
// (top, bottom, through holes `breakthroughMm` deeper) when `depthsFromHoles`, else from `heights`.
Heights holeHeights(const geom::Hole& hole, const Heights& heights, bool depthsFromHoles, double breakthroughMm);

// "hole at (12.5, -3) of 8 mm diameter": how errors and warnings name a hole.
std::string describeHole(const geom::Hole& hole);

// Indices of `holes` in visiting order: shortRapidOrder from the first hole given (so the user
// still picks where to begin), or the given order when `keepOrder`.
std::vector<int> holeVisitingOrder(const std::vector<geom::Hole>& holes, bool keepOrder);

// "0.5" rather than "0.5000": numbers in messages.
std::string formatMm(double value);

}  // namespace camwb::ops
