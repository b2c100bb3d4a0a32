// Exact offsetting of closed line/arc profiles: lines stay lines, arcs stay arcs, so a contour
// toolpath can be posted with real G2/G3 moves. Clipper (ClipperAdapter.h) is the cross-check.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"

namespace camwb::geom {

// Offsets a closed profile by `distance` mm away from the area it encloses (outside), keeping its
// orientation. Lines stay lines, arcs stay arcs (radius +- distance); at convex corners the offset
// inserts an arc of radius `distance` around the corner (tangent continuous); at concave corners
// consecutive offset elements are trimmed to their intersection (line-line, line-arc, arc-arc).
// Errors: open or discontinuous profile, distance <= 0, an arc whose offset radius would be <= 0
// ("tool too large for the concave arc of radius R at (x, y)"), a segment that vanishes or
// reverses after trimming (tool too large for the feature).
// Limitation: trimming is local (neighbouring elements only); a neck narrower than 2*distance
// between elements that are not neighbours is not detected here.
base::Result<Profile> offsetOutside(const Profile& profile, double distance);

// Offsets a closed profile by `distance` mm into the area it encloses, keeping its orientation;
// the same rules as offsetOutside with the sides swapped (the profile's convex arcs shrink, its
// concave corners get arcs). An offset that would split the area into several loops or let it
// vanish is reported only where a trimmed element vanishes (local trimming, as above).
base::Result<Profile> offsetInside(const Profile& profile, double distance);

}  // namespace camwb::geom
