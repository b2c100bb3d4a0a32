// Planning one contour before any record is written: the cutting path of each radial pass
// (exact offsets, direction from climb/conventional, start on the longest line), leads, tabs and
// the helix, each checked against the finished contour so that nothing gouges it.
#pragma once

#include "base/Result.h"
#include "ops/ContourOp.h"
#include "ops/contour/Clearance.h"
#include "ops/contour/Emitter.h"
#include "ops/contour/Leads.h"

#include <optional>
#include <vector>

namespace camwb::ops::contour {

struct PassPlan {
    Cut cut;
    Tabs tabs;                   // spans on cut.path; topZ set by the caller
    std::optional<Helix> helix;  // the shape of the helical entry (its Z range is set per level)
    bool helixLeft = true;       // side of the entry direction the helix centre lies on
};

struct LoopPlan {
    std::size_t index = 0;  // in the input
    Material material;
    std::vector<PassPlan> passes;  // outermost first, the last on the contour offset
    toolpath::CutterCompSide compSide = toolpath::CutterCompSide::Off;
};

// The plan of contour `index`. Errors name the operation (offset failures, leads, helix or tabs
// that do not fit).
base::Result<LoopPlan> planLoop(const geom::Profile& contour, std::size_t index, const ContourParams& params,
                                const ToolController& tc);

// Whether a feed move at depth from `from` to `to` keeps clear of the part (stay down between
// levels and passes instead of retracting).
bool linkIsClear(const LoopPlan& plan, Vec2 from, Vec2 to, double toolRadius, const ContourParams& params);

}  // namespace camwb::ops::contour
