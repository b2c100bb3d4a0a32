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
// Edges are checked whole (every point of an edge within tolerance of the arc), not only their
// midpoints. Arcs sweep at most 270 degrees, so a full circle gives two arcs, never one whose
// start equals its end. A closed polyline is started at its sharpest corner and a first and last
// piece that one line or arc can cover are merged (a rounded rectangle gives 4 lines + 4 arcs).
// Runs are found by exponential growth and bisection: O(n log n) for n points. Repeated and
// non-finite points are dropped; tolerance below 1e-9 (or NaN) is raised to 1e-9.
Profile fitLinesAndArcs(const std::vector<Vec2>& points, bool closed, double tolerance, double maxArcRadius = 1e4);

}  // namespace camwb::geom
