#include "geom/Offset.h"

#include "geom/detail/OffsetCore.h"

#include <cmath>
#include <string>

namespace camwb::geom {

namespace {

// The checks both closed offsets make; on success `segs` holds the profile without degenerate
// segments and `ccw` its orientation.
base::Status prepareClosed(const Profile& profile, double distance, const char* side, std::vector<Segment>& segs,
                           bool& ccw)
{
    if (!(distance > 0) || !std::isfinite(distance))
        return base::makeError("offset distance must be positive, got " + detail::formatMm(distance) + " mm");
    if (profile.empty())
        return base::makeError("cannot offset an empty profile");
    if (!profile.closed)
        return base::makeError(std::string("cannot offset an open profile ") + side + ": it encloses no area");
    if (!profile.isContinuous())
        return base::makeError("cannot offset a discontinuous profile: consecutive segments do not meet");
    segs = detail::withoutDegenerate(profile.segments);
    if (segs.empty())
        return base::makeError("cannot offset a profile whose segments all have zero length");
    const double area = Profile{segs, true}.signedArea();
    if (std::abs(area) < 1e-12)
        return base::makeError("cannot offset a profile that encloses no area");
    ccw = area > 0;
    return base::Status::success();
}

}  // namespace

base::Result<Profile> offsetOutside(const Profile& profile, double distance)
{
    std::vector<Segment> segs;
    bool ccw = true;
    if (base::Status s = prepareClosed(profile, distance, "outside", segs, ccw); !s)
        return s.error();
    // Outside is on the right of a counter-clockwise loop.
    return detail::offsetToSide(segs, true, !ccw, distance);
}

base::Result<Profile> offsetInside(const Profile& profile, double distance)
{
    std::vector<Segment> segs;
    bool ccw = true;
    if (base::Status s = prepareClosed(profile, distance, "inside", segs, ccw); !s)
        return s.error();
    return detail::offsetToSide(segs, true, ccw, distance);
}

}  // namespace camwb::geom
