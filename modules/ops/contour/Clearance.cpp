#include "ops/contour/Clearance.h"

#include "base/NumberFormat.h"
#include "geom/Region.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops::contour {

namespace {

// Which side of the segment's carrier p lies on, seen along its direction: > 0 left.
double sideOf(Vec2 p, const Segment& s)
{
    if (!s.isArc())
        return (s.end - s.start).cross(p - s.start);
    // Left of a counter-clockwise arc is towards its centre.
    const double inside = s.radius() - distance(p, s.center);
    return s.ccw ? inside : -inside;
}

std::string fmt(double v) { return base::NumberFormat{3, true}.format(v); }

}  // namespace

Material::Material(geom::Profile contour, MaterialSide side) : m_contour(std::move(contour)), m_side(side)
{
    if (side == MaterialSide::InsideLoop || side == MaterialSide::OutsideLoop)
        m_polygon = geom::discretize(m_contour, 1e-4);
}

bool Material::insideLoop(Vec2 p) const
{
    bool inside = false;
    for (std::size_t i = 0, j = m_polygon.size() - 1; i < m_polygon.size(); j = i++) {
        const Vec2 a = m_polygon[i], b = m_polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

double Material::clearance(Vec2 p) const
{
    double best = std::numeric_limits<double>::infinity();
    const Segment* nearest = nullptr;
    // Not geom::distanceToProfile: the side tests of open chains need the nearest segment too.
    for (const Segment& s : m_contour.segments) {
        const double d = geom::distanceToSegment(p, s);
        if (d < best) {
            best = d;
            nearest = &s;
        }
    }
    switch (m_side) {
    case MaterialSide::InsideLoop:
        return insideLoop(p) ? -best : best;
    case MaterialSide::OutsideLoop:
        return insideLoop(p) ? best : -best;
    case MaterialSide::LeftOfChain:
        return nearest && sideOf(p, *nearest) > 1e-9 ? -best : best;
    case MaterialSide::RightOfChain:
        return nearest && sideOf(p, *nearest) < -1e-9 ? -best : best;
    case MaterialSide::None:
        break;
    }
    return best;
}

base::Status checkClear(const Material& material, const std::vector<Segment>& pieces, double minimum, double step,
                        const std::string& what)
{
    if (material.side() == MaterialSide::None)
        return base::Status::success();
    for (const Segment& s : pieces) {
        const int n = std::max(2, static_cast<int>(std::ceil(s.length() / step)));
        for (int i = 0; i <= n; ++i) {
            const Vec2 p = s.pointAt(static_cast<double>(i) / n);
            const double c = material.clearance(p);
            if (c < minimum - 1e-6)
                return base::makeError(what + " at (" + fmt(p.x) + ", " + fmt(p.y) + ") would come " + fmt(c) +
                                       " mm from the contour, less than the " + fmt(minimum) + " mm it must keep");
        }
    }
    return base::Status::success();
}

}  // namespace camwb::ops::contour
