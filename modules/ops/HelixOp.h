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
    Heights heights;              // clearance and safe for all holes
    bool depthsFromHoles = true;  // per hole: startZ = hole top, finalZ = hole bottom (through:
                                  // minus breakthroughMm); false: heights.startZ/finalZ for all
    double pitchMm = 1;
    bool climb = true;
    double radialStockMm = 0;
    bool finishingCircle = false;  // a second full flat circle at the bottom, same radius: a spring
                                   // pass that takes off what the tool's deflection left
    double breakthroughMm = 0.5;   // through holes, with depthsFromHoles
    double toleranceMm = 0.01;     // a last helix piece with a shorter chord joins the half turn before
};

// Records (each with SourceRef{operationIndex, i}): SectionBegin{name, "helix", tool, feeds}; per
// hole, in shortRapidOrder from the first hole given: Rapid to the helix start (circle point in +X
// of the hole) at clearance (first hole) or safe, Rapid down to safe, Linear to start Z at plunge
// feed (Plunge), helical Arcs (one per half turn, ramp feed: Entry, the centre on the hole axis at
// the arc's start Z, lead exactly the pitch, the last one shortened to end at final Z), one full
// flat circle at final Z (two half Arcs, cutting feed: Cutting; the second circle of
// finishingCircle: Finishing), Linear to the hole centre (Exit) and Rapid up to safe (clearance
// after the last hole); SectionEnd. Climb = counter-clockwise.
// A tool narrower than half the hole leaves a core: where it stands (blind hole, or above the
// bottom of a through hole) the result warns and the tool leaves straight up from the circle.
// Errors (nothing produced): no holes, tool controller and height checks, pitch <= 0 or above the
// flute length, negative stock or breakthrough, depth beyond the flute length, a tool that does not
// fit a hole (named by its centre and diameter).

base::Result<OpResult> computeHelix(const std::vector<geom::Hole>& holes, const HelixParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress = {});

}  // namespace camwb::ops
