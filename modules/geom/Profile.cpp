#include "geom/Profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::geom {

double Segment::sweep() const
{
    if (!isArc())
        return 0;
    const Vec2 a = start - center;
    const Vec2 b = end - center;
    double angle = std::atan2(a.cross(b), a.dot(b));  // in (-pi, pi]
    if (ccw) {
        if (angle <= 1e-12)
            angle += 2 * std::numbers::pi;
    } else {
        if (angle >= -1e-12)
            angle -= 2 * std::numbers::pi;
    }
    return angle;
}

double Segment::length() const { return isArc() ? std::abs(sweep()) * radius() : distance(start, end); }

Vec2 Segment::startTangent() const
{
    if (!isArc())
        return (end - start).normalized();
    const Vec2 radial = (start - center).normalized();
    return ccw ? radial.leftNormal() : radial.rightNormal();
}

Vec2 Segment::endTangent() const
{
    if (!isArc())
        return (end - start).normalized();
    const Vec2 radial = (end - center).normalized();
    return ccw ? radial.leftNormal() : radial.rightNormal();
}

Vec2 Segment::pointAt(double t) const
{
    if (!isArc())
        return start + (end - start) * t;
    const Vec2 a = start - center;
    const double angle = std::atan2(a.y, a.x) + sweep() * t;
    const double r = radius();
    return center + Vec2{std::cos(angle) * r, std::sin(angle) * r};
}

Segment Segment::reversed() const
{
    Segment s = *this;
    std::swap(s.start, s.end);
    s.ccw = !ccw;
    return s;
}

double Profile::signedArea() const
{
    // Shoelace over the chords plus, for each arc, the circular segment between chord and arc.
    double area = 0;
    for (const Segment& s : segments) {
        area += 0.5 * s.start.cross(s.end);
        if (s.isArc()) {
            const double sweep = s.sweep();
            const double r = s.radius();
            area += 0.5 * r * r * (sweep - std::sin(sweep));
        }
    }
    return area;
}

double Profile::length() const
{
    double total = 0;
    for (const Segment& s : segments)
        total += s.length();
    return total;
}

Profile Profile::reversed() const
{
    Profile out;
    out.closed = closed;
    for (auto it = segments.rbegin(); it != segments.rend(); ++it)
        out.segments.push_back(it->reversed());
    return out;
}

bool Profile::isContinuous(double tolerance) const
{
    for (std::size_t i = 0; i + 1 < segments.size(); ++i)
        if (distance(segments[i].end, segments[i + 1].start) > tolerance)
            return false;
    if (closed && !segments.empty() && distance(segments.back().end, segments.front().start) > tolerance)
        return false;
    return true;
}

int chordCount(double radius, double sweepAbs, double tolerance)
{
    if (!(radius > 0))
        return 1;
    const double tol = std::min(tolerance >= 1e-6 ? tolerance : 1e-6, radius);  // NaN too
    // Chord error r(1 - cos(step/2)) <= tol.
    const double maxStep = 2 * std::acos(1 - tol / radius);
    return std::max(1, static_cast<int>(std::ceil(sweepAbs / maxStep)));
}

std::vector<Vec2> discretize(const Profile& profile, double tolerance)
{
    std::vector<Vec2> points;
    for (const Segment& s : profile.segments) {
        points.push_back(s.start);
        if (!s.isArc())
            continue;
        const int steps = chordCount(s.radius(), std::abs(s.sweep()), tolerance);
        for (int i = 1; i < steps; ++i)
            points.push_back(s.pointAt(static_cast<double>(i) / steps));
    }
    if (!profile.closed && !profile.segments.empty())
        points.push_back(profile.segments.back().end);
    return points;
}

}  // namespace camwb::geom
