// The helix operation (hole milling): the tool spirals down inside each hole on a circle of
// (hole diameter - tool diameter - 2 * stock) / 2 radius at `pitch` per turn, makes a full flat
// circle at the bottom, optionally a second finishing circle, and leaves along the centre.
// Output as helical Arc records (one per half turn), so posts write G2/G3 with Z or CP IPA.
#pragma once

#include "geom/Hole.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::ops {

struct HelixParams {
    std::string name = "Helix";
    Heights heights;  // clearance and safe for all holes
    bool depthsFromHoles = true;  // per hole: startZ = hole top, finalZ = hole bottom (through:
                                  // minus breakthroughMm); false: heights.startZ/finalZ for all
    double pitchMm = 1;
    bool climb = true;
    double radialStockMm = 0;
    bool finishingCircle = false;
    double breakthroughMm = 0.5;  // through holes, with depthsFromHoles
    double toleranceMm = 0.01;
};

base::Result<OpResult> computeHelix(const std::vector<geom::Hole>& holes, const HelixParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
