// The 3D operations (3D pocket, waterline, parallel finishing) computed from the model: its mesh
// (welded across faces), the silhouette of the selected faces as the area, the B-rep's flat
// floors, the stock box and, for rest machining, the stock as the enabled operations before this
// one leave it (cut on the simulator's height field). Used by OperationGeometry.cpp only.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"

#include <optional>

namespace camwb::document::detail {

base::Result<ops::OpResult> computeSurfaceOperation(const Job& job, int index, const occ::Model& model,
                                                    const ops::Progress& progress,
                                                    std::optional<ops::Heights>* heightsUsed);

}  // namespace camwb::document::detail
