// Independent pieces of an operation computed on all cores (the 3D pocket's and waterline's levels,
// parallel finishing's lines): each depends only on the model, so they are computed at once and
// the toolpath is written in order afterwards.
#pragma once

#include "ops/OpCommon.h"

#include <cstddef>
#include <functional>

namespace camwb::ops::surface {

// Calls work(i) for every i in [0, count) on all cores (work must be safe to run concurrently);
// the calling thread reports progress in [from, to] as pieces finish. False when cancelled (some
// pieces may then be left undone).
bool forEachOnAllCores(std::size_t count, const std::function<void(std::size_t)>& work, const Progress& progress,
                       double from, double to);

}  // namespace camwb::ops::surface
