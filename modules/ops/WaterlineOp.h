// Waterline finishing: constant-Z contours of the tool touching the model, at a step-down chosen
// so that the scallop between two contours on a wall stays below the requested height, limited to
// walls steeper than a slope angle so that parallel finishing (ParallelOp.h) takes the rest.
#pragma once

#include "ops/OpCommon.h"
#include "ops/surface/SurfaceInput.h"

#include <string>

namespace camwb::ops {

struct WaterlineParams {
    std::string name = "Waterline";
    Heights heights;           // start: the highest contour; final: the lowest
    double scallopMm = 0.01;   // largest scallop height between contours
    double maxStepDownMm = 1;  // never more than this between contours
    double minSlopeDeg = 30;   // contours only where the model is steeper than this (0: everywhere)
    double stockMm = 0;        // left on the model
    bool climb = true;
    double toleranceMm = 0.01;
};

base::Result<OpResult> computeWaterline(const SurfaceInput& input, const WaterlineParams& params,
                                        const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
