// Where a ball's centre, at a given height, comes within its radius of a flat convex piece of the
// part (an upward triangle clipped to a band of heights): the horizontal section of the piece
// grown by a sphere, {q : |(q, zc) - p| <= r for some p of the piece}. It is convex, so it is
// given by its support lines, each found in closed form along the piece's edges, added where the
// boundary bends (a slanted edge's reach is an elongated ellipse, not a circle of radius r); the
// polygon of those lines contains the exact set and stands at most `chord` outside it. This is what lets the
// tool-centre regions of a ball be exact, one polygon per triangle, where growing thin bands of
// the part by the ball's radius at each band cost a polygon per triangle per band.
#pragma once

#include "base/Vec.h"

#include <vector>

namespace camwb::ops::surface {

// Counter-clockwise; empty when the piece lies wholly above or below zc +- radius. `piece`: a
// planar convex polygon (3 or more points), exact when all of it lies within zc +- radius (parts
// beyond count as if at the rim: a larger set, on the safe side).
// `grow`: the set grown by that much horizontally (the side stock on a ball lowered by the bottom
// stock, as the tool-centre regions grow every cutter).
std::vector<base::Vec2> ballReach(const std::vector<base::Vec3>& piece, double zc, double radius, double grow,
                                  double chord);

}  // namespace camwb::ops::surface
