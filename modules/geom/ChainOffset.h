// Exact offsetting of open line/arc chains (edge chains of a part, cut left or right of their
// direction): lines stay lines, arcs stay arcs, convex corners get arcs, concave ones are trimmed,
// the same way Offset.h treats closed profiles. The chain's ends are offset straight sideways.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"

namespace camwb::geom {

enum class ChainSide { Left, Right };  // seen along the chain's direction

// Offsets `chain` by `distance` mm to `side` of its direction, keeping the direction; a closed
// profile is offset as a loop (the last corner included). Errors: empty or discontinuous chain,
// distance <= 0, an arc whose offset radius would be <= 0, a segment that vanishes or reverses
// after trimming (tool too large for the feature). Trimming is local as in Offset.h: a chain
// that comes back within 2*distance of itself elsewhere is not detected here.
base::Result<Profile> offsetChain(const Profile& chain, ChainSide side, double distance);

}  // namespace camwb::geom
