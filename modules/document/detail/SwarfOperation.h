// The swarf operation computed from the model: the face's drive (occ), the cut (ops) and the gouge
// check of every pose against the model, which fails the operation naming the face and the place.
// Used by OperationGeometry.cpp (computeOperation) only.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"

#include <optional>

namespace camwb::document::detail {

base::Result<ops::OpResult> computeSwarfOperation(const Job& job, int index, const occ::Model& model,
                                                  const ops::Progress& progress,
                                                  std::optional<ops::Heights>* heightsUsed);

}  // namespace camwb::document::detail
