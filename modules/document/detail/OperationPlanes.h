// 3+2: the working planes an operation is computed in, and its toolpath put together from one
// computation per plane. Used by OperationGeometry.cpp (computeOperation) only.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "occ/Model.h"
#include "ops/OpCommon.h"
#include "toolpath/ClRecords.h"

#include <vector>

namespace camwb::document::detail {

struct PlaneGroup {
    toolpath::WorkingPlane plane;  // not tilted: the workpiece's own XY
    std::vector<int> holes;        // drilling: the holes drilled in this plane (the operation's order)
};

// The operation's own plane (its face's normal or its angles), one group; drilling in the flat
// plane: one group per direction of its holes' axes, each hole reachable along its group's tool
// axis. Errors name the operation and the face.
base::Result<std::vector<PlaneGroup>> operationPlanes(const Operation& op, const occ::Model& model);

// The stock box as seen in `plane`'s frame: the box around its corners there.
Stock stockInFrame(const Stock& stock, const toolpath::WorkingPlane& plane);

// The records of each group's computation in one section: WorkingPlane before each group's moves
// (in its frame), WorkingPlane{} before the SectionEnd where any was tilted; records renumbered.
ops::OpResult joinPlanes(std::vector<ops::OpResult> parts, const std::vector<PlaneGroup>& groups, int operationIndex);

}  // namespace camwb::document::detail
