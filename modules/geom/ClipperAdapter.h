// Polygon offsetting and area through Clipper 6.4 (libpolyclipping): the independent cross-check
// for the exact line/arc offset, and the basis for pocketing later. Clipper works on integers:
// coordinates are scaled by kClipperScale (1 unit = 1e-6 mm = 1 nm) and rounded.
#pragma once

#include "base/Vec.h"

#include <vector>

namespace camwb::geom {

// Clipper integer units per mm. |coordinates| must stay below ~4.6e12 mm (int64 range / scale).
inline constexpr double kClipperScale = 1e6;

// Offsets a closed polygon (either orientation; the last point is not repeated) by `delta` mm
// with round joins: delta > 0 grows the enclosed area, delta < 0 shrinks it. `arcTolerance` is
// the largest chord error (mm) of the round joins. The result may hold several polygons: outer
// boundaries counter-clockwise, holes clockwise (so the signed areas add up).
std::vector<std::vector<base::Vec2>> clipperOffset(const std::vector<base::Vec2>& polygon, double delta,
                                                   double arcTolerance);

// The union of closed polygons (either orientation, nonzero fill: overlapping ones merge), as
// outer boundaries counter-clockwise and holes clockwise; polygons are exact to Clipper's 1 nm grid.
// The silhouette of many small pieces (projected triangles) in one sweep.
std::vector<std::vector<base::Vec2>> clipperUnion(const std::vector<std::vector<base::Vec2>>& polygons);

// Signed shoelace area (mm^2) of a closed polygon: positive for counter-clockwise. Computed in
// doubles, not on the integer grid, so it does not carry Clipper's rounding.
double polygonArea(const std::vector<base::Vec2>& polygon);

}  // namespace camwb::geom
