// When Import Model replaces the job's model, the operations' references (face, edge and hole
// numbers of the old model) are looked up in the new model by what they are: a face, edge or
// hole of the same kind, at the same place and of the same size. A number alone would point at
// whatever the new model numbers so, and the operation would cut it without a word.
#pragma once

#include "document/Job.h"
#include "occ/Model.h"

#include <string>
#include <vector>

namespace camwb::document {

struct LostReference {
    int operation = 0;      // index in the job
    std::string reference;  // "face 25", "edge 3", "hole 21" (the old model's numbers)
};

struct RemappedOperations {
    std::vector<Operation> operations;  // references renumbered for the new model; lost ones removed
    std::vector<LostReference> lost;    // in job order
    // False when the old model was not loaded (a missing file): nothing could be compared, so
    // `operations` keep their numbers unchecked and `lost` is empty.
    bool checked = true;
};

RemappedOperations remapReferences(const std::vector<Operation>& operations, const occ::Model& from,
                                   const occ::Model& to);

// `pocket "Pocket 1": face 25` for each lost reference, one per line.
std::string describeLost(const std::vector<LostReference>& lost, const std::vector<Operation>& operations);

}  // namespace camwb::document
