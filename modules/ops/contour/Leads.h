// Lead-in/out, the straight approach and departure moves cutter compensation needs, and the
// helical entry, all placed on the free side of a cutting path (away from the material).
#pragma once

#include "ops/ContourOp.h"
#include "ops/contour/Path.h"

#include <optional>
#include <vector>

namespace camwb::ops::contour {

// One pass round one loop (or along one chain) with its leads, in XY.
struct Cut {
    Path path;
    std::vector<Segment> leadIn;    // ends at the path's start
    std::vector<Segment> leadOut;   // starts at the path's end
    std::optional<Vec2> approach;   // compensation: where the tool is when it switches it on
    std::optional<Vec2> departure;  // compensation: where it goes after switching it off

    // Where the tool goes down (before any helix) and the direction it then moves in.
    Vec2 entryPoint() const;
    Vec2 entryDirection() const;
    Vec2 exitPoint() const;
};

// The path with leads of `params`; under compensation (`control`) the approach and departure
// points lie `approachMm` out on the free side of the lead ends.
Cut withLeads(Path path, const ContourParams& params, bool control, double approachMm);

// One helical descent ending at `end` moving along `direction`: its circle, centred `radius` off
// the end to one side, and the arcs from its start down to the end (half turns at most).
struct Helix {
    Vec2 centre;
    bool ccw = true;
    Vec2 start;
    std::vector<std::pair<Segment, double>> arcs;  // piece, Z at its end
    Segment circle() const { return Segment::arc(start, start, centre, ccw); }
};
Helix helixTo(Vec2 end, Vec2 direction, bool leftOfDirection, double radius, double pitch, double zTop, double zEnd);

}  // namespace camwb::ops::contour
