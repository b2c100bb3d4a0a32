// Robust offsets and booleans of regions through Clipper (integer polygons, ClipperAdapter.h),
// with lines and arcs restored afterwards (ArcFit.h). Loops are discretised so that the chord
// error stays within tolerance/2 and fitted within tolerance/2. Results are conservative where it
// matters for gouging: offsetRegions(..., -d, ...) never comes closer than d to the input
// boundary (the discretisation and fit errors are added to d, not taken from it).
#pragma once

#include "geom/Region.h"

#include <vector>

namespace camwb::geom {

// delta < 0 shrinks the regions (the tool-centre area of a pocket: -(tool radius + stock)),
// delta > 0 grows them (round joins). May split a region into several or make it vanish.
std::vector<Region> offsetRegions(const std::vector<Region>& regions, double delta, double tolerance);

// Regions from closed loops with even-odd nesting (outer loops and holes in any orientation,
// a loop inside a hole is a new outer loop). Loops are taken as given (no discretisation).
std::vector<Region> regionsFromLoops(const std::vector<Profile>& loops, double tolerance);

std::vector<Region> unite(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);
std::vector<Region> subtract(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);
std::vector<Region> intersect(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);

// The parts of open polylines that lie inside the regions (zig-zag lines, links), in order.
std::vector<std::vector<Vec2>> clipPolylines(const std::vector<std::vector<Vec2>>& polylines,
                                             const std::vector<Region>& regions, double tolerance);

// True when the straight segment a-b lies within the regions (touching a loop counts as inside).
bool segmentInside(Vec2 a, Vec2 b, const std::vector<Region>& regions);

// The area a tool of `radius` sweeps along the polylines (the footprint), as regions. Used to
// find uncut material: subtract(machinable, sweptArea(paths)).
std::vector<Region> sweptArea(const std::vector<std::vector<Vec2>>& paths, double radius, double tolerance);

}  // namespace camwb::geom
