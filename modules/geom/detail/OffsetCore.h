// The exact line/arc offset shared by closed profiles (Offset.h) and open chains (ChainOffset.h):
// each element offset to one side of the direction of travel, convex corners rounded with an arc,
// concave corners trimmed to the intersection of the neighbouring offsets.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::geom::detail {

// Offsets `segments` (continuous, no degenerate ones) by `distance` > 0 to the left of travel
// (toLeft) or to the right. `closed`: the last segment joins the first (that corner is handled
// too). Lines stay lines, arcs stay arcs. Errors as documented for offsetOutside (Offset.h).
base::Result<Profile> offsetToSide(const std::vector<Segment>& segments, bool closed, bool toLeft, double distance);

// The segments longer than a nanometre: degenerate ones have no tangent and, on a continuous
// profile, can be dropped without opening a gap.
std::vector<Segment> withoutDegenerate(const std::vector<Segment>& segments);

std::string formatMm(double v);
std::string formatPoint(Vec2 p);

}  // namespace camwb::geom::detail
