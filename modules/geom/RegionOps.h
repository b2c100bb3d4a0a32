// Robust offsets and booleans of regions. Offsets are exact lines and arcs: the raw offset of each
// loop is built from its lines and arcs, Clipper (integer polygons, ClipperAdapter.h) only decides
// where the offset loops cross, merge, split or vanish, and the result is put back onto the exact
// pieces. Booleans discretise the loops (chord error within tolerance/2) and fit lines and arcs
// back (ArcFit.h, within tolerance/2). Results are conservative where it matters for gouging:
// offsetRegions(..., -d, ...) never comes closer than d to the input boundary.
#pragma once

#include "geom/Region.h"

#include <vector>

namespace camwb::geom {

// delta < 0 shrinks the regions (the tool-centre area of a pocket: -(tool radius + stock)),
// delta > 0 grows them (round joins). May split a region into several or make it vanish.
// Shrinking offsets by |delta| + offsetSafetyMargin(tolerance); growing offsets by delta itself.
// The loops lie at exactly that distance from the input loops (lines stay lines, arcs arcs, round
// joins are arcs), except that an arc collapsing to nothing is taken as its polygon (chords within
// tolerance/2, on the far side of it) and a loop whose crossings cannot be placed back on the
// pieces is fitted within tolerance/2 of its polygon: both stay within the margin. delta == 0
// returns the regions normalised. Tolerances below 1e-5 mm are raised to it. Coordinates beyond
// 1e9 mm give an empty result.
std::vector<Region> offsetRegions(const std::vector<Region>& regions, double delta, double tolerance);

// What a shrink adds to |delta| (about 1.28 * tolerance): enough for a result discretised and
// fitted back (chords of the input arcs tolerance/2 + fit tolerance/2 + chords of round joins
// 2.25 * offsetArcTolerance, as Clipper rounds a join's step count, + 4 nm rounding), so that
// shrinks keep their distance whichever way they were computed.
double offsetSafetyMargin(double tolerance);
// Nominal chord error of Clipper's round joins in offsets and swept areas: tolerance/8 (so that
// even a join's long last step, 2.25 times that, stays below the fit tolerance/2).
double offsetArcTolerance(double tolerance);

// Regions from closed loops with even-odd nesting (outer loops and holes in any orientation,
// a loop inside a hole is a new outer loop). Loops are taken as given (no discretisation); they
// must not cross each other. Loops with an area below 1e-3 * tolerance^2 are dropped.
std::vector<Region> regionsFromLoops(const std::vector<Profile>& loops, double tolerance);

std::vector<Region> unite(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);
std::vector<Region> subtract(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);
std::vector<Region> intersect(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance);

// The parts of open polylines that lie inside the regions (zig-zag lines, links), in order and in
// the polylines' direction. Exact (edges are cut at their exact crossings with the line/arc loops;
// parts running along a loop count as inside); `tolerance` is not needed and kept for symmetry.
std::vector<std::vector<Vec2>> clipPolylines(const std::vector<std::vector<Vec2>>& polylines,
                                             const std::vector<Region>& regions, double tolerance);

// True when the straight segment a-b lies within the regions (touching a loop counts as inside).
bool segmentInside(Vec2 a, Vec2 b, const std::vector<Region>& regions);

// The area a tool of `radius` sweeps along the polylines (the footprint), as regions. Used to
// find uncut material: subtract(machinable, sweptArea(paths)). A single-point path gives a disc.
// Round ends and joins are inscribed polygons (chord error offsetArcTolerance), then fitted
// within tolerance/2: the result lies within tolerance of the exact footprint.
std::vector<Region> sweptArea(const std::vector<std::vector<Vec2>>& paths, double radius, double tolerance);

}  // namespace camwb::geom
