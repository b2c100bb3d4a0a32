// What "New Contour/Pocket/Helix/Drilling" proposes before the user edits it in the task panel:
// a tool of the job suited to the kind (or a default tool controller to add with the operation)
// and geometry taken from the user's face selection or, without one, from the model. Plain data,
// no Qt, so the choices are unit-testable.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "occ/Model.h"

#include <optional>
#include <vector>

namespace camwb::gui {

struct OperationProposal {
    document::Operation operation;
    std::optional<ops::ToolController> newTool;  // added to the job together with the operation
};

// Defaults without a selection:
//  contour: the topmost +Z planar face (its outer wire is the part's outline seen from above);
//  pocket:  a +Z planar face below the top, faces with islands (inner wires) first, then the
//           largest (a pocket floor);
//  helix:   the largest holes (all of that diameter) larger than the end mill, with the
//           largest end mill of the job that fits them;
//  drill:   the holes whose diameter is within 0.1 mm of the drill's, else the holes of the
//           diameter nearest to it (one drill, one hole size).
//  groove:  the thesis' Kod 1 groove (it needs no model) with the job's first grooving tool, or a
//           3 mm grooving insert to add with it.
// Selected faces are used when they fit the kind: planar faces for contour and pocket, the
// cylindrical faces of holes for helix and drilling. Errors say what is missing.
base::Result<OperationProposal> proposeOperation(document::OperationKind kind, const document::Job& job,
                                                 const occ::Model& model, const std::vector<int>& selectedFaces = {});

// The tool of `job` a new operation of `kind` uses: the first drill for drilling, the first
// grooving tool for a groove, else the first tool that is neither; nullptr when the job has none.
const ops::ToolController* suitedTool(document::OperationKind kind, const document::Job& job);

}  // namespace camwb::gui
