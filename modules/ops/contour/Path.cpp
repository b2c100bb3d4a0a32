#include "ops/contour/Path.h"

#include "ops/pocket/CutPath.h"  // nearestOnSegment: the pocket's nearest point on a line or arc

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops::contour {

double Path::length() const
{
    double total = 0;
    for (const Segment& s : segments)
        total += s.length();
    return total;
}

Vec2 Path::freeNormalAtStart() const
{
    return materialOnRight ? startTangent().leftNormal() : startTangent().rightNormal();
}

Vec2 Path::freeNormalAtEnd() const { return materialOnRight ? endTangent().leftNormal() : endTangent().rightNormal(); }

Segment partOf(const Segment& s, double t0, double t1)
{
    if (!s.isArc())
        return Segment::line(s.pointAt(t0), s.pointAt(t1));
    // Ends computed from the sweep keep the radius exact; whole arcs keep their own end points.
    const Vec2 a = t0 <= 0 ? s.start : s.pointAt(t0);
    const Vec2 b = t1 >= 1 ? s.end : s.pointAt(t1);
    return Segment::arc(a, b, s.center, s.ccw);
}

std::vector<Segment> piecesBetween(const Path& path, double from, double to)
{
    std::vector<Segment> out;
    double at = 0;
    for (const Segment& s : path.segments) {
        const double len = s.length();
        const double a = std::max(from, at), b = std::min(to, at + len);
        if (b - a > 1e-9 && len > 0)
            out.push_back(partOf(s, (a - at) / len, (b - at) / len));
        at += len;
    }
    return out;
}

double nearestArclength(const Path& path, Vec2 p)
{
    double best = std::numeric_limits<double>::infinity();
    double bestS = 0, at = 0;
    for (const Segment& s : path.segments) {
        const double t = pocket::nearestOnSegment(s, p).t;
        const double d = distance(p, s.pointAt(t));
        if (d < best) {
            best = d;
            bestS = at + t * s.length();
        }
        at += s.length();
    }
    return bestS;
}

std::vector<Segment> startAtLongestLine(const std::vector<Segment>& loop)
{
    std::size_t best = loop.size();
    double bestLength = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        if (!loop[i].isArc() && loop[i].length() > bestLength) {
            best = i;
            bestLength = loop[i].length();
        }
    if (best == loop.size())
        return loop;
    const Segment& split = loop[best];
    const Vec2 mid = (split.start + split.end) * 0.5;
    std::vector<Segment> out;
    out.push_back(Segment::line(mid, split.end));
    for (std::size_t k = 1; k < loop.size(); ++k)
        out.push_back(loop[(best + k) % loop.size()]);
    out.push_back(Segment::line(split.start, mid));
    return out;
}

}  // namespace camwb::ops::contour
