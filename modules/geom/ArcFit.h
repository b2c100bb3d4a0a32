// Restoring lines and arcs from a polyline (Clipper output, sampled B-splines): the polyline is
// covered greedily by the longest lines and circular arcs that stay within a tolerance of every
// vertex and edge midpoint, so that offsets and approximations post as G1/G2/G3 again.
#pragma once

#include "geom/Profile.h"

#include <vector>

namespace camwb::geom {

// Segments start and end on polyline vertices (so consecutive segments meet exactly and a closed
// polyline gives a closed profile); no point of the polyline is farther than `tolerance` from
// the result and no point of the result farther than `tolerance` from the polyline. An arc is
// only used when its radius is below `maxArcRadius` (near-straight runs become lines).
// `closed`: the last point connects back to the first (not repeated in `points`).
Profile fitLinesAndArcs(const std::vector<Vec2>& points, bool closed, double tolerance,
                        double maxArcRadius = 1e4);

}  // namespace camwb::geom
