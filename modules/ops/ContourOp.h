// The contour (profile) operation: closed loops cut outside, inside or on, open edge chains cut
// left, right or on; climb or conventional; radial and axial stock; step-downs and radial passes;
// lead-in/out, ramp or helical entry, holding tabs; output as the tool-centre path or as the
// programmed contour with cutter compensation (G41/G42, RL/RR) for the control to offset.
#pragma once

#include "geom/Profile.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::ops {

// Outside/Inside for closed loops (relative to the area they enclose); Left/Right for open chains
// (relative to the chain's direction as given); On: the tool centre on the contour, both kinds.
enum class ContourSide { Outside, Inside, On, Left, Right };
// Arc: a tangent quarter arc; Line: a tangent straight; PerpendicularLine: straight in from the
// free side at right angles. leadRadiusMm is the arc's radius or the line's length.
enum class LeadKind { None, Arc, Line, PerpendicularLine };
enum class EntryKind { Plunge, Ramp, Helix };
enum class CompensationOutput { ToolCentre, Control };  // Control: programmed contour + CutterComp

struct ContourParams {
    std::string name = "Contour";
    ContourSide side = ContourSide::Outside;
    bool climb = true;
    double radialStockMm = 0;
    double axialStockMm = 0;  // left above finalZ
    Heights heights;
    double stepDownMm = 0;  // 0 = one level at final depth
    int radialPasses = 1;   // > 1: passes from the outermost inwards to the contour, stepover apart
    double radialStepoverMm = 0;
    LeadKind leadIn = LeadKind::None;
    LeadKind leadOut = LeadKind::None;
    double leadRadiusMm = 0;  // arc leads: radius; line leads: length
    EntryKind entry = EntryKind::Plunge;
    double rampAngleDeg = 3;     // ramp entry: along the contour at this angle
    double helixDiameterMm = 0;  // helical entry (0 = tool diameter)
    double helixPitchMm = 1;     // helical entry: Z per revolution
    int tabCount = 0;            // holding tabs on the last levels, evenly spaced along each loop
    double tabWidthMm = 5;
    double tabHeightMm = 2;  // above finalZ
    CompensationOutput compensation = CompensationOutput::ToolCentre;
    double toleranceMm = 0.01;  // arc fitting / approximation
};

// Each input profile is one loop or chain, cut in turn (nearest next start). Closed profiles
// must be continuous; open ones are chains. Errors: empty input, Outside/Inside with an open chain,
// Left/Right with a closed loop, tool too large for a concave arc or feature, and the common
// checks (OpCommon.h). Records carry SourceRef{operationIndex, i}.
base::Result<OpResult> computeContour(const std::vector<geom::Profile>& contours, const ContourParams& params,
                                      const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
