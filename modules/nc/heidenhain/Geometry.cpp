// Tangents and corner roundings of contour elements (see Geometry.h): the rounding centre is the
// intersection of both elements offset by the radius towards the inside of the turn.
#include "nc/heidenhain/Geometry.h"

#include "nc/detail/PlaneAxes.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace camwb::nc::heidenhain {

namespace {

constexpr double kEps = 1e-9;

using detail::inPlane;
using detail::planeAxes;

// The unit direction of travel at `at` (on an arc; a line's own direction) in `plane`.
std::optional<Vec2> tangentAt(const Element& e, const Vec3& at, int plane)
{
    const detail::PlaneAxes in = planeAxes(plane);
    Vec2 d;
    if (e.type == Element::Type::Line) {
        d = inPlane(e.end - e.start, in);
    } else if (e.type == Element::Type::Arc) {
        const detail::PlaneAxes own = planeAxes(e.plane);
        const Vec2 radial = inPlane(at, own) - e.center;
        if (radial.length() < kEps)
            return std::nullopt;
        d = e.clockwise ? radial.rightNormal() : radial.leftNormal();
        if (e.plane != plane)
            d = inPlane(detail::withInPlane(Vec3{}, own, d), in);  // the 3D tangent seen in `plane`
    } else {
        return std::nullopt;
    }
    return d.length() < kEps ? std::nullopt : std::optional<Vec2>(d.normalized());
}

// A line (point and unit direction) or a circle (centre and radius) in the plane.
struct Curve {
    bool circle = false;
    Vec2 point;
    Vec2 dir;
    double radius = 0;
};

void intersect(const Curve& a, const Curve& b, std::vector<Vec2>& out)
{
    if (!a.circle && !b.circle) {
        const double d = a.dir.cross(b.dir);
        if (std::abs(d) < kEps)
            return;
        out.push_back(a.point + a.dir * ((b.point - a.point).cross(b.dir) / d));
        return;
    }
    if (a.circle && !b.circle)
        return intersect(b, a, out);
    if (!a.circle) {  // line a, circle b
        const Vec2 d = a.point - b.point;
        const double p = d.dot(a.dir);
        const double disc = p * p - (d.dot(d) - b.radius * b.radius);
        if (disc < -kEps)
            return;
        const double root = std::sqrt(std::max(0.0, disc));
        out.push_back(a.point + a.dir * (-p + root));
        out.push_back(a.point + a.dir * (-p - root));
        return;
    }
    const Vec2 d = b.point - a.point;
    const double dist = d.length();
    if (dist < kEps || dist > a.radius + b.radius + kEps || dist < std::abs(a.radius - b.radius) - kEps)
        return;
    const double along = (a.radius * a.radius - b.radius * b.radius + dist * dist) / (2 * dist);
    const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
    const Vec2 u = d * (1 / dist);
    const Vec2 m = a.point + u * along;
    out.push_back(m + u.leftNormal() * h);
    out.push_back(m - u.leftNormal() * h);
}

// The element shifted sideways by `offset` (> 0 to the left of its direction of travel).
std::optional<Curve> offsetCurve(const Element& e, double offset)
{
    Curve c;
    if (e.type == Element::Type::Line) {
        const auto t = startTangent(e);
        if (!t)
            return std::nullopt;
        c.point = e.start.xy() + t->leftNormal() * offset;
        c.dir = *t;
        return c;
    }
    // Left of a counter-clockwise arc is its centre.
    const double r = distance(e.start.xy(), e.center) + (e.clockwise ? offset : -offset);
    if (r <= kEps)
        return std::nullopt;
    c.circle = true;
    c.point = e.center;
    c.radius = r;
    return c;
}

Vec2 foot(const Element& e, const Vec2& p)
{
    if (e.type == Element::Type::Line) {
        const Vec2 t = *startTangent(e);
        return e.start.xy() + t * (p - e.start.xy()).dot(t);
    }
    const Vec2 d = p - e.center;
    const double len = d.length();
    return len < kEps ? e.start.xy() : e.center + d * (distance(e.start.xy(), e.center) / len);
}

// Whether `p` (on the element's line or circle) lies between its start and end.
bool within(const Element& e, const Vec2& p)
{
    if (e.type == Element::Type::Line) {
        const Vec2 d = (e.end - e.start).xy();
        const double t = (p - e.start.xy()).dot(d) / d.dot(d);
        return t >= -kEps && t <= 1 + kEps;
    }
    if (distance(p, e.start.xy()) < 1e-7 || distance(p, e.end.xy()) < 1e-7)
        return true;
    const double total = travelledDegrees(e, e.start.xy(), e.end.xy()) + 360.0 * e.turns;
    return travelledDegrees(e, e.start.xy(), p) <= total + 1e-7;
}

}  // namespace

std::optional<Vec2> startTangent(const Element& e, int plane) { return tangentAt(e, e.start, plane); }

std::optional<Vec2> endTangent(const Element& e, int plane)
{
    return tangentAt(e, e.type == Element::Type::Line ? e.start : e.end, plane);
}

double travelledDegrees(const Element& arc, const Vec2& from, const Vec2& to)
{
    const Vec2 a = from - arc.center, b = to - arc.center;
    double angle = std::atan2(a.cross(b), a.dot(b)) * 180 / std::numbers::pi;  // counter-clockwise
    if (arc.clockwise)
        angle = -angle;
    if (angle <= 1e-9)
        angle += 360;
    return angle;
}

std::optional<Rounding> roundCorner(const Element& a, const Element& b, double radius, std::string& problem)
{
    const auto ta = endTangent(a), tb = startTangent(b);
    if (!ta || !tb) {
        problem = "needs motion in the working plane on both sides: ignored";
        return std::nullopt;
    }
    const double turn = ta->cross(*tb);
    if (std::abs(turn) < 1e-9 && ta->dot(*tb) > 0) {
        problem = "between elements in one direction: ignored";
        return std::nullopt;
    }
    const double side = turn > 0 ? 1.0 : -1.0;  // the centre lies on the inside of the turn
    const auto oa = offsetCurve(a, side * radius), ob = offsetCurve(b, side * radius);
    std::vector<Vec2> candidates;
    if (oa && ob)
        intersect(*oa, *ob, candidates);
    const Vec2 corner = a.end.xy();
    std::optional<Rounding> best;
    double bestDistance = 0;
    for (const Vec2& c : candidates) {
        const Vec2 from = foot(a, c), to = foot(b, c);
        if (!within(a, from) || !within(b, to))
            continue;
        const double d = distance(c, corner);
        if (!best || d < bestDistance) {
            best = Rounding{from, to, c, side < 0};
            bestDistance = d;
        }
    }
    if (!best)
        problem = "does not fit the adjacent elements";
    return best;
}

}  // namespace camwb::nc::heidenhain
