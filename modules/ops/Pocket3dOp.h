// The 3D pocket: z-level roughing of any part given as a triangle mesh. At each level the tool
// centre may go where the tool, by its true shape (flat, ball, bull-nose) grown by the stock to
// leave (side and bottom apart), touches no part of the model at or above the level; that region
// is cleared with the 2.5D pocket's offset or zig-zag pattern and entries. Levels step down from
// the start height and are forced onto the model's flat floors. With a rest stock, a level cuts
// only where material is left (rest roughing after a larger tool).
#pragma once

#include "ops/ContourOp.h"  // EntryKind
#include "ops/OpCommon.h"
#include "ops/PocketOp.h"  // PocketPattern
#include "ops/surface/SurfaceInput.h"

#include <string>

namespace camwb::ops {

struct Pocket3dParams {
    std::string name = "3D Pocket";
    PocketPattern pattern = PocketPattern::Offset;
    double zigZagAngleDeg = 0;
    double stepoverPercent = 50;  // of the tool diameter; used when stepoverMm is 0
    double stepoverMm = 0;
    Heights heights;  // start: the top of the stock; final: the lowest level
    double stepDownMm = 1;
    double sideStockMm = 0.3;    // left on walls (radially)
    double bottomStockMm = 0.2;  // left on floors and shallow surfaces (axially)
    bool climb = true;
    EntryKind entry = EntryKind::Helix;
    double helixDiameterMm = 0;  // 0 = 90 % of the tool diameter
    double helixPitchMm = 1;
    double rampAngleDeg = 3;
    bool restMachining = false;  // cut only what SurfaceInput::restStock still has
    double toleranceMm = 0.01;
    double stepover(double toolDiameter) const
    {
        return stepoverMm > 0 ? stepoverMm : toolDiameter * stepoverPercent / 100.0;
    }
};

base::Result<OpResult> computePocket3d(const SurfaceInput& input, const Pocket3dParams& params,
                                       const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
