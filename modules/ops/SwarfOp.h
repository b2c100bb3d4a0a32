// Swarf milling, the simultaneous five-axis operation: the tool's side along a ruled, developable
// face, its axis on the face's rulings, its tip on the drive edge (the face's bottom edge) moved
// off the face by the tool radius along the normal. The drive comes from the model
// (occ::Model::swarfFace); the gouge check against the model is the caller's (document).
#pragma once

#include "geom/Ruling.h"
#include "ops/OpCommon.h"

#include <functional>
#include <string>

namespace camwb::ops {

// The drive edge over [t0, t1] (closed: a loop) and the face's ruling at each of its points.
struct SwarfDrive {
    double t0 = 0, t1 = 1;
    bool closed = false;
    std::function<geom::RulingPoint(double t)> at;
};

struct SwarfParams {
    std::string name = "Swarf";
    Heights heights;                 // clearanceZ and safeZ, reached along the tool axis (start/final unused)
    bool climb = true;               // the material on the right of the cut, seen from the spindle
    double axialOffsetMm = 0;        // the tip above (+) or below (-) the drive edge, along the tool axis
    double radialStockMm = 0;        // left on the face
    int radialPasses = 1;            // passes from the outermost in to the face (plus stock)
    double radialStepoverMm = 1;     // between passes
    double chordToleranceMm = 0.01;  // the tip and the flutes' top stay this close to the face's path
    double angleToleranceDeg = 1;    // the most the tool axis turns between consecutive points
    double gougeToleranceMm = 0.01;  // how deep the tool may enter the model (the caller checks it)
};

// One pose of the cut: the tip, the unit tool axis (tip to spindle) and the drive parameter.
struct SwarfPose {
    base::Vec3 tip;
    base::Vec3 axis;
    double t = 0;
};

// The poses of one pass `offsetMm` off the face along the drive (t0 to t1), as few as keep the tip
// and the point `heightMm` up the axis within the chord tolerance of the exact path, and the axis
// within the angle tolerance from one pose to the next. Empty when cancelled.
std::vector<SwarfPose> swarfPass(const SwarfDrive& drive, double offsetMm, double axialOffsetMm, double heightMm,
                                 double chordToleranceMm, double angleToleranceDeg, const Progress& progress = {});

// Records (each with SourceRef{operationIndex, i}): SectionBegin{name, "swarf", tool, feeds};
// ToolAxisMove rapids (feed 0) to the first pose's axis line at clearance Z, then at safe Z; a
// ToolAxisMove down the axis to the first pose at the plunge feed; the pass's poses at the cutting
// feed; the next pass (closed drive: a feed move across to its start; open: retract along the axis
// to clearance and enter again); after the last pass a rapid up the axis to clearance; SectionEnd.
// Passes run in the direction that climbs (or not): the drive is reversed where needed.
// Errors (nothing produced): tool controller checks, clearance below safe, passes < 1, stepover
// <= 0 with several passes, tolerances <= 0, a tool axis pointing down or nearly level at an
// entry or exit (no Z to reach along it), safe Z below the tip there, the face higher above the
// tip than the flute length, a drive that gives no ruling.
base::Result<OpResult> computeSwarf(const SwarfDrive& drive, const SwarfParams& params, const ToolController& tc,
                                    int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
