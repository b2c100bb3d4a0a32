#include "geom/CarrierIntersection.h"

#include <cmath>

namespace camwb::geom {

std::vector<Vec2> lineCircle(Vec2 p, Vec2 dir, Vec2 c, double r)
{
    const Vec2 foot = p + dir * (c - p).dot(dir);
    double h2 = r * r - (c - foot).dot(c - foot);
    if (h2 < 0 && h2 > -1e-9 * r * r)
        h2 = 0;
    if (h2 < 0)
        return {};
    const double h = std::sqrt(h2);
    return {foot + dir * h, foot - dir * h};
}

std::vector<Vec2> circleCircle(Vec2 c1, double r1, Vec2 c2, double r2)
{
    const Vec2 delta = c2 - c1;
    const double dd = delta.length();
    if (dd < 1e-12)
        return {};
    const Vec2 u = delta * (1 / dd);
    const double a = (r1 * r1 - r2 * r2 + dd * dd) / (2 * dd);
    double h2 = r1 * r1 - a * a;
    if (h2 < 0 && h2 > -1e-9 * r1 * r1)
        h2 = 0;
    if (h2 < 0)
        return {};
    const double h = std::sqrt(h2);
    const Vec2 foot = c1 + u * a;
    return {foot + u.leftNormal() * h, foot - u.leftNormal() * h};
}

std::optional<Vec2> intersectCarriers(const Segment& a, const Segment& b, Vec2 near)
{
    std::vector<Vec2> candidates;
    if (!a.isArc() && !b.isArc()) {
        const Vec2 da = (a.end - a.start).normalized();
        const Vec2 db = (b.end - b.start).normalized();
        const double denom = da.cross(db);
        if (std::abs(denom) < 1e-12)
            return std::nullopt;
        const double t = (b.start - a.start).cross(db) / denom;
        return a.start + da * t;
    }
    if (!a.isArc())
        candidates = lineCircle(a.start, (a.end - a.start).normalized(), b.center, b.radius());
    else if (!b.isArc())
        candidates = lineCircle(b.start, (b.end - b.start).normalized(), a.center, a.radius());
    else
        candidates = circleCircle(a.center, a.radius(), b.center, b.radius());
    if (candidates.empty())
        return std::nullopt;
    Vec2 best = candidates.front();
    for (const Vec2& c : candidates)
        if (distance(c, near) < distance(best, near))
            best = c;
    return best;
}

}  // namespace camwb::geom
