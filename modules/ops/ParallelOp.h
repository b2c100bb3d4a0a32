// Parallel finishing: raster lines over the area, each dropped onto the model point by point (the
// drop-cutter of a revolved tool on the triangle mesh), limited to areas shallower than a slope
// angle so that waterline finishing (WaterlineOp.h) takes the steep walls.
#pragma once

#include "ops/OpCommon.h"
#include "ops/surface/SurfaceInput.h"

#include <string>

namespace camwb::ops {

struct ParallelParams {
    std::string name = "Parallel";
    Heights heights;            // clearance and safe are used; the model gives the cut's depth
    double stepoverMm = 0.5;    // between raster lines
    double angleDeg = 0;        // of the raster lines to X
    double maxSlopeDeg = 90;    // cut only where the model is at most this steep (90: everywhere)
    double stockMm = 0;         // left on the model
    bool zigZag = true;         // lines cut both ways; false: always the same way, linked above
    double toleranceMm = 0.01;  // drop-cutter sampling and the chord of the line through the points
};

base::Result<OpResult> computeParallel(const SurfaceInput& input, const ParallelParams& params,
                                       const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
