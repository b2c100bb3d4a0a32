// From an operation's model references to what the operation computes from: the contours,
// regions or holes of the loaded model, and its heights (overrides, else derived from the model
// and stock). Used by the job pipeline (every operation) and the GUI's live preview (one).
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "geom/Hole.h"
#include "geom/Region.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"

#include <optional>
#include <vector>

namespace camwb::document {

struct OperationGeometry {
    std::vector<geom::Profile> contours;  // contour: face outer wires and edge chains
    std::vector<geom::Region> regions;    // pocket: faces with their islands
    std::vector<geom::Hole> holes;        // helix, drilling (helix: also picked circular edges)
};

// The operation's tolerance (its `toleranceMm`; 0.01 mm for a kind without one): the chord and
// fitting tolerance its geometry is resolved with.
double toleranceOf(const Operation& op);

// Errors name the operation and the reference ("pocket \\"Pocket 2\\": face 7 is not planar").
base::Result<OperationGeometry> resolveGeometry(const Operation& op, const occ::Model& model);

// Derived heights: clearance = stock top + 10, safe = stock top + 2 (never below the model top),
// start = the highest selected feature top (face Z or hole top, else the stock top), final = the
// floor: for a pocket the face Z, for a contour of a face the model bottom... (see .cpp); then the
// overrides replace what the user set.
ops::Heights resolveHeights(const Operation& op, const OperationGeometry& geometry, const occ::Model& model,
                            const Stock& stock);

// The operation computed as the job would: geometry and heights resolved, the tool looked up.
// `heightsUsed` (may be null) receives the resolved heights once the geometry resolved, even when
// the operation itself then fails (the task panel shows them beside the error).
base::Result<ops::OpResult> computeOperation(const Job& job, int index, const occ::Model& model,
                                             const ops::Progress& progress = {},
                                             std::optional<ops::Heights>* heightsUsed = nullptr);

}  // namespace camwb::document
