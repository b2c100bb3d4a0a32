// Intersections of the carriers of profile segments (the whole line through a line segment, the
// full circle of an arc): where two offsets meet at a concave corner. Used by the exact profile
// offsets (Offset.h, ChainOffset.h) and by the NC interpreters' cutter compensation.
#pragma once

#include "geom/Profile.h"

#include <optional>
#include <vector>

namespace camwb::geom {

// Points where the line through `p` with unit direction `dir` meets the circle (c, r): none, or
// two (equal when it touches; a near-touch within a relative 1e-9 counts as touching).
std::vector<Vec2> lineCircle(Vec2 p, Vec2 dir, Vec2 c, double r);
// Points where two circles meet: none (apart, nested, concentric) or two, as for lineCircle.
std::vector<Vec2> circleCircle(Vec2 c1, double r1, Vec2 c2, double r2);
// The intersection of the carriers of `a` and `b` nearest to `near`; nullopt for parallel lines
// and carriers that do not meet.
std::optional<Vec2> intersectCarriers(const Segment& a, const Segment& b, Vec2 near);

}  // namespace camwb::geom
