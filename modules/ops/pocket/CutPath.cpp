#include "ops/pocket/CutPath.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::ops::pocket {

double Cut::length() const
{
    double total = 0;
    for (const Segment& s : path)
        total += s.length();
    return total;
}

Segment subSegment(const Segment& s, double t0, double t1)
{
    const Vec2 a = t0 <= 0 ? s.start : s.pointAt(t0);
    const Vec2 b = t1 >= 1 ? s.end : s.pointAt(t1);
    if (!s.isArc())
        return Segment::line(a, b);
    if (t0 <= 0 && t1 >= 1)
        return s;
    // A sliver of an arc would read as a full circle once its end lands a rounding step behind its
    // start (Segment::sweep); such a piece is a line for every purpose.
    if (std::abs(s.sweep()) * (t1 - t0) < 1e-9)
        return Segment::line(a, b);
    return Segment::arc(a, b, s.center, s.ccw);
}

PathPoint nearestOnSegment(const Segment& s, Vec2 p)
{
    PathPoint best;
    if (!s.isArc()) {
        const Vec2 d = s.end - s.start;
        const double len2 = d.dot(d);
        best.t = len2 > 0 ? std::clamp((p - s.start).dot(d) / len2, 0.0, 1.0) : 0.0;
        best.point = s.start + d * best.t;
        best.distance = distance(p, best.point);
        return best;
    }
    const Vec2 a = s.start - s.center;
    const Vec2 q = p - s.center;
    const double sweep = s.sweep();
    double angle = std::atan2(a.cross(q), a.dot(q));
    if (sweep < 0)
        angle = -angle;
    if (angle < 0)
        angle += 2 * std::numbers::pi;
    if (angle <= std::abs(sweep) && q.length() > 0) {
        best.t = angle / std::abs(sweep);
        best.point = s.center + q.normalized() * s.radius();
    } else {
        const bool startCloser = distance(p, s.start) <= distance(p, s.end);
        best.t = startCloser ? 0.0 : 1.0;
        best.point = startCloser ? s.start : s.end;
    }
    best.distance = distance(p, best.point);
    return best;
}

PathPoint nearestOnPath(const std::vector<Segment>& path, Vec2 p)
{
    PathPoint best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < path.size(); ++i) {
        PathPoint candidate = nearestOnSegment(path[i], p);
        if (candidate.distance < best.distance) {
            candidate.segment = i;
            best = candidate;
        }
    }
    return best;
}

PathPoint nearestOnRegions(const std::vector<geom::Region>& regions, Vec2 p)
{
    PathPoint best;
    best.distance = std::numeric_limits<double>::infinity();
    auto consider = [&](const geom::Profile& loop) {
        const PathPoint candidate = nearestOnPath(loop.segments, p);
        if (candidate.distance < best.distance)
            best = candidate;
    };
    for (const geom::Region& region : regions) {
        consider(region.outer);
        for (const geom::Profile& hole : region.holes)
            consider(hole);
    }
    return best;
}

std::vector<Segment> loopFrom(const std::vector<Segment>& loop, std::size_t i, double t)
{
    constexpr double kEnd = 1e-12;
    if (loop.empty())
        return loop;
    if (t >= 1 - kEnd) {
        i = (i + 1) % loop.size();
        t = 0;
    }
    std::vector<Segment> out;
    out.reserve(loop.size() + 1);
    out.push_back(t <= kEnd ? loop[i] : subSegment(loop[i], t, 1));
    for (std::size_t k = 1; k < loop.size(); ++k)
        out.push_back(loop[(i + k) % loop.size()]);
    if (t > kEnd)
        out.push_back(subSegment(loop[i], 0, t));
    return out;
}

std::vector<Segment> loopNearest(const std::vector<Segment>& loop, Vec2 p)
{
    const PathPoint at = nearestOnPath(loop, p);
    return loopFrom(loop, at.segment, at.t);
}

std::vector<Segment> loopAtLongest(const std::vector<Segment>& loop)
{
    std::size_t best = 0;
    double bestScore = -1;
    Vec2 bestMiddle;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        // Straight sides first: an entry or a link meets a line more predictably than an arc.
        const double score = loop[i].length() * (loop[i].isArc() ? 0.25 : 1.0);
        // Sides of the same length: the lowest (then leftmost), whichever the loop starts with.
        const Vec2 middle = loop[i].pointAt(0.5);
        const bool tie = std::abs(score - bestScore) <= 1e-9 * (1 + score);
        if ((!tie && score > bestScore) ||
            (tie && (middle.y < bestMiddle.y - 1e-9 || (middle.y <= bestMiddle.y + 1e-9 && middle.x < bestMiddle.x)))) {
            best = i;
            bestScore = score;
            bestMiddle = middle;
        }
    }
    return loopFrom(loop, best, 0.5);
}

std::vector<Vec2> samplePath(const std::vector<Segment>& path, double tolerance)
{
    geom::Profile open;
    open.segments = path;
    open.closed = false;
    return geom::discretize(open, tolerance);
}

void appendLine(std::vector<Segment>& path, Vec2 a, Vec2 b)
{
    if (distance(a, b) > 1e-9)
        path.push_back(Segment::line(a, b));
}

}  // namespace camwb::ops::pocket
