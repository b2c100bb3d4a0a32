// What the helix and drilling operations share about holes: the first checks, the per-hole
// depths, the visiting order (shortRapidOrder, declared in DrillOp.h, implemented in
// HoleOrder.cpp), planning in that order and how messages name a hole.
// Internal to modules/ops.
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

// The checks both hole operations start with: a selection that is not empty, the tool controller.
base::Status checkHolesAndTool(const std::string& what, const std::vector<geom::Hole>& holes, const ToolController& tc);

// planHole(hole) -> base::Result<Plan> for every hole in visiting order; the first error stops.
template <class Plan, class PlanHole>
base::Result<std::vector<Plan>> planHoles(const std::vector<geom::Hole>& holes, bool keepOrder, PlanHole planHole)
{
    std::vector<Plan> plans;
    for (int i : holeVisitingOrder(holes, keepOrder)) {
        base::Result<Plan> plan = planHole(holes[i]);
        if (!plan)
            return plan.error();
        plans.push_back(std::move(plan.value()));
    }
    return plans;
}

}  // namespace camwb::ops
