// The contour operation's checks before computing: its parameters and its input (clear errors
// naming the operation, nothing produced).
#pragma once

#include "base/Result.h"
#include "ops/ContourOp.h"

#include <string>
#include <vector>

namespace camwb::ops::contour {

std::string what(const ContourParams& params);  // contour "Name"

base::Status checkContourInput(const std::vector<geom::Profile>& contours, const ContourParams& params,
                               const ToolController& tc);

}  // namespace camwb::ops::contour
