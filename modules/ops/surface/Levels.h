// Z levels computed on all cores: each level's region or contours depend only on the model, so
// the 3D pocket and waterline compute them at once and write the toolpath in order afterwards.
#pragma once

#include "ops/OpCommon.h"

#include <cstddef>
#include <functional>

namespace camwb::ops::surface {

// Calls work(i) for every i in [0, count) on all cores (work must be safe to run concurrently);
// the calling thread reports progress in [from, to] as levels finish. False when cancelled (some
// levels may then be left undone).
bool forEachLevel(std::size_t count, const std::function<void(std::size_t)>& work, const Progress& progress,
                  double from, double to);

}  // namespace camwb::ops::surface
