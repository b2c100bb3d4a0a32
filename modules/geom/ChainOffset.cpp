#include "geom/ChainOffset.h"

#include "geom/detail/OffsetCore.h"

#include <cmath>

namespace camwb::geom {

base::Result<Profile> offsetChain(const Profile& chain, ChainSide side, double distance)
{
    if (!(distance > 0) || !std::isfinite(distance))
        return base::makeError("offset distance must be positive, got " + detail::formatMm(distance) + " mm");
    if (chain.empty())
        return base::makeError("cannot offset an empty chain");
    if (!chain.isContinuous())
        return base::makeError("cannot offset a discontinuous chain: consecutive segments do not meet");
    const std::vector<Segment> segs = detail::withoutDegenerate(chain.segments);
    if (segs.empty())
        return base::makeError("cannot offset a chain whose segments all have zero length");
    return detail::offsetToSide(segs, chain.closed, side == ChainSide::Left, distance);
}

}  // namespace camwb::geom
