#include "geom/Region.h"

#include "geom/detail/LoopQueries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::geom {

using detail::fastDistance;
using detail::fastLength;
using detail::radiusOf;

double Region::area() const
{
    double total = std::abs(outer.signedArea());
    for (const Profile& hole : holes)
        total -= std::abs(hole.signedArea());
    return total;
}

bool Region::contains(Vec2 p) const
{
    if (detail::onLoop(outer, p) ||
        std::any_of(holes.begin(), holes.end(), [p](const Profile& hole) { return detail::onLoop(hole, p); }))
        return true;
    if (!detail::insideLoop(outer, p))
        return false;
    return std::none_of(holes.begin(), holes.end(), [p](const Profile& hole) { return detail::insideLoop(hole, p); });
}

double Region::distanceToBoundary(Vec2 p) const
{
    double best = distanceToProfile(p, outer);
    for (const Profile& hole : holes)
        best = std::min(best, distanceToProfile(p, hole));
    return best;
}

Region Region::normalized() const
{
    Region out;
    out.outer = outer.signedArea() < 0 ? outer.reversed() : outer;
    out.holes.reserve(holes.size());
    for (const Profile& hole : holes)
        out.holes.push_back(hole.signedArea() > 0 ? hole.reversed() : hole);
    return out;
}

double distanceToSegment(Vec2 p, const Segment& s)
{
    if (!s.isArc()) {
        const Vec2 d = s.end - s.start;
        const double len2 = d.dot(d);
        const double t = len2 > 0 ? std::clamp((p - s.start).dot(d) / len2, 0.0, 1.0) : 0.0;
        return fastDistance(p, s.start + d * t);
    }
    // Within the arc's angular range the nearest point is radial; outside it, an end point.
    if (detail::angleAlongArc(s, p) <= std::abs(s.sweep()))
        return std::abs(fastDistance(p, s.center) - radiusOf(s));
    return std::min(fastDistance(p, s.start), fastDistance(p, s.end));
}

double distanceToProfile(Vec2 p, const Profile& profile)
{
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& s : profile.segments)
        best = std::min(best, distanceToSegment(p, s));
    return best;
}

double totalArea(const std::vector<Region>& regions)
{
    double total = 0;
    for (const Region& region : regions)
        total += region.area();
    return total;
}

bool anyContains(const std::vector<Region>& regions, Vec2 p)
{
    return std::any_of(regions.begin(), regions.end(), [p](const Region& region) { return region.contains(p); });
}

}  // namespace camwb::geom
