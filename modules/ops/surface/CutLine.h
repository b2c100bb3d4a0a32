// A cut along a straight line in XY on the drop-cutter's surface: the dropped samples made dense
// enough that no straight move between neighbours dips into the surface (bisected where it would,
// stepped up vertically where the surface jumps), then thinned to the fewest points whose chords
// stay above every sample and within the tolerance of it.
#pragma once

#include "base/Vec.h"
#include "ops/surface/DropCutter.h"

#include <vector>

namespace camwb::ops::surface {

// `points` (x, y, tip z) along one straight XY line, in order; `toleranceMm` the most a move may
// dip below the dropped surface between two samples. Returns the points with those inserted.
std::vector<base::Vec3> refineCut(const DropCutter& cutter, const std::vector<base::Vec3>& points, double toleranceMm);

// Drops points while the straight move that replaces them stays at or above each dropped one and
// at most `toleranceMm` above it. Points with the same XY (vertical steps) are all kept.
std::vector<base::Vec3> thinCut(const std::vector<base::Vec3>& points, double toleranceMm);

}  // namespace camwb::ops::surface
