#include "geom/detail/LoopQueries.h"

#include "geom/Region.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::geom::detail {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Half-open crossing rule for a piece that is monotone in y: counts when the piece spans p.y and
// meets the horizontal line y = p.y to the right of p. `xAt` gives that meeting point.
template <class XAt> int crossesRight(Vec2 p, double ya, double yb, XAt xAt)
{
    if ((ya > p.y) == (yb > p.y))
        return 0;
    return xAt() > p.x ? 1 : 0;
}

// Crossings counted by splitting the arc into y-monotone pieces: exact for rays through the
// arc's ends or tangent to its circle, where the shortcut below could not decide.
int arcCrossingsByPieces(Vec2 p, const Segment& s, double r);

int arcCrossingsRight(Vec2 p, const Segment& s)
{
    const double r = radiusOf(s);
    const Vec2 c = s.center;
    if (p.y > c.y + r || p.y < c.y - r || p.x > c.x + r)
        return 0;
    // Shortcut: the ray meets the circle at c.x +- h; a meeting point is on the arc when it lies
    // on the arc's side of the chord (right of start->end for ccw arcs), any sweep.
    const double scale = 1e-9 * (1 + std::abs(p.y) + r);
    const double dy = p.y - c.y;
    if (std::abs(p.y - s.start.y) <= scale || std::abs(p.y - s.end.y) <= scale || r - std::abs(dy) <= scale)
        return arcCrossingsByPieces(p, s, r);
    const double h = std::sqrt(r * r - dy * dy);
    const bool fullCircle = s.start == s.end;
    const Vec2 chord = s.end - s.start;
    const double side = s.ccw ? -1.0 : 1.0;
    int count = 0;
    for (const double x : {c.x - h, c.x + h})
        if (x > p.x && (fullCircle || side * chord.cross(Vec2{x, p.y} - s.start) > 0))
            ++count;
    return count;
}

int arcCrossingsByPieces(Vec2 p, const Segment& s, double r)
{
    const Vec2 c = s.center;
    // Split at the top and bottom of the circle so each piece is monotone in y.
    const double sweep = s.sweep();
    const double dir = sweep >= 0 ? 1.0 : -1.0;
    const Vec2 a = s.start - c;
    const double a0 = std::atan2(a.y, a.x);
    // Angles (relative to a0, in the sweep direction) of the extremes pi/2 + k*pi inside the sweep.
    std::vector<double> cuts;
    for (int k = 0; k < 2; ++k) {
        double rel = dir * (std::numbers::pi / 2 + k * std::numbers::pi - a0);
        rel = std::fmod(rel, kTwoPi);
        if (rel < 0)
            rel += kTwoPi;
        if (rel > 1e-12 && rel < std::abs(sweep) - 1e-12)
            cuts.push_back(rel);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double x, double y) { return std::abs(x - y) < 1e-12; }),
               cuts.end());
    const double h = p.y - c.y;
    const double halfChord = std::sqrt(std::max(0.0, r * r - h * h));
    int count = 0;
    Vec2 from = s.start;
    double fromRel = 0;
    for (std::size_t i = 0; i <= cuts.size(); ++i) {
        const bool lastPiece = i == cuts.size();
        const double toRel = lastPiece ? std::abs(sweep) : cuts[i];
        const double angle = a0 + dir * toRel;
        const Vec2 to = lastPiece ? s.end : c + Vec2{r * std::cos(angle), r * std::sin(angle)};
        const double midAngle = a0 + dir * 0.5 * (fromRel + toRel);
        const double side = std::cos(midAngle) >= 0 ? 1.0 : -1.0;
        count += crossesRight(p, from.y, to.y, [&] { return c.x + side * halfChord; });
        from = to;
        fromRel = toRel;
    }
    return count;
}

// Whether q (on the circle of arc s, within rounding) lies within the arc's sweep.
bool withinSweep(const Segment& s, Vec2 q)
{
    if (fastDistance(q, s.start) <= kOnBoundary || fastDistance(q, s.end) <= kOnBoundary)
        return true;
    return angleAlongArc(s, q) <= std::abs(s.sweep()) + kOnBoundary / radiusOf(s);
}

void lineLine(Vec2 a, Vec2 b, const Segment& s, std::vector<double>& ts)
{
    const Vec2 d = b - a;
    const Vec2 e = s.end - s.start;
    const double dl = fastLength(d), el = fastLength(e);
    const double denom = d.cross(e);
    const Vec2 w = s.start - a;
    if (el <= 0) {
        const double t = std::clamp(w.dot(d) / (dl * dl), 0.0, 1.0);
        if (fastDistance(a + d * t, s.start) <= kOnBoundary)
            ts.push_back(t);
        return;
    }
    if (std::abs(denom) <= 1e-12 * dl * el) {
        // Parallel: only a collinear overlap matters; its ends break the segment.
        if (std::abs(w.cross(d)) / dl > kOnBoundary)
            return;
        for (Vec2 q : {s.start, s.end}) {
            const double t = (q - a).dot(d) / (dl * dl);
            if (t >= 0 && t <= 1)
                ts.push_back(t);
        }
        return;
    }
    const double t = w.cross(e) / denom;
    const double u = w.cross(d) / denom;
    const double et = kOnBoundary / dl, eu = kOnBoundary / el;
    if (t >= -et && t <= 1 + et && u >= -eu && u <= 1 + eu)
        ts.push_back(std::clamp(t, 0.0, 1.0));
}

void lineArc(Vec2 a, Vec2 b, const Segment& s, std::vector<double>& ts)
{
    const Vec2 d = b - a;
    const Vec2 f = a - s.center;
    const double r = radiusOf(s);
    // Quick rejections: the segment misses the circle, or lies inside it.
    const double tNear = std::clamp(-f.dot(d) / d.dot(d), 0.0, 1.0);
    if (fastLength(f + d * tNear) > r + kOnBoundary)
        return;
    if (fastLength(f) < r - kOnBoundary && fastLength(b - s.center) < r - kOnBoundary)
        return;
    const double A = d.dot(d);
    const double B = 2 * f.dot(d);
    const double C = f.dot(f) - r * r;
    const double et = kOnBoundary / std::sqrt(A);
    double roots[2];
    int count = 0;
    const double disc = B * B - 4 * A * C;
    const double tClosest = -B / (2 * A);
    if (disc <= 0 || std::abs(fastDistance(a + d * tClosest, s.center) - r) <= kOnBoundary) {
        // Tangent or a near miss within the boundary tolerance: one touching point.
        if (std::abs(fastDistance(a + d * tClosest, s.center) - r) <= kOnBoundary)
            roots[count++] = tClosest;
    } else {
        const double q = std::sqrt(disc);
        roots[count++] = (-B - q) / (2 * A);
        roots[count++] = (-B + q) / (2 * A);
    }
    for (int i = 0; i < count; ++i) {
        const double t = roots[i];
        if (t < -et || t > 1 + et)
            continue;
        if (withinSweep(s, a + d * t))
            ts.push_back(std::clamp(t, 0.0, 1.0));
    }
    // Arc ends touching the segment (a near-tangent end may be missed by the roots above).
    for (Vec2 q : {s.start, s.end}) {
        const double t = std::clamp((q - a).dot(d) / A, 0.0, 1.0);
        if (fastDistance(a + d * t, q) <= kOnBoundary)
            ts.push_back(t);
    }
}

}  // namespace

double angleAlongArc(const Segment& s, Vec2 q)
{
    const Vec2 a = s.start - s.center;
    const Vec2 v = q - s.center;
    double angle = std::atan2(a.cross(v), a.dot(v));
    if (!s.ccw)
        angle = -angle;
    return angle < 0 ? angle + kTwoPi : angle;
}

int crossingsRight(Vec2 p, const Segment& s)
{
    if (s.isArc())
        return arcCrossingsRight(p, s);
    return crossesRight(p, s.start.y, s.end.y,
                        [&] { return s.start.x + (p.y - s.start.y) / (s.end.y - s.start.y) * (s.end.x - s.start.x); });
}

bool insideLoop(const Profile& loop, Vec2 p)
{
    int crossings = 0;
    for (const Segment& s : loop.segments)
        crossings += crossingsRight(p, s);
    return crossings % 2 == 1;
}

bool nearSegment(Vec2 p, const Segment& s)
{
    constexpr double e = kOnBoundary;
    if (s.isArc()) {
        if (std::abs(fastDistance(p, s.center) - radiusOf(s)) > e)
            return false;
    } else if (p.x < std::min(s.start.x, s.end.x) - e || p.x > std::max(s.start.x, s.end.x) + e ||
               p.y < std::min(s.start.y, s.end.y) - e || p.y > std::max(s.start.y, s.end.y) + e) {
        return false;
    }
    return distanceToSegment(p, s) <= e;
}

bool onLoop(const Profile& loop, Vec2 p)
{
    for (const Segment& s : loop.segments)
        if (nearSegment(p, s))
            return true;
    return false;
}

void appendCrossings(Vec2 a, Vec2 b, const Segment& s, std::vector<double>& ts)
{
    if (fastDistance(a, b) <= 0)
        return;
    if (s.isArc())
        lineArc(a, b, s, ts);
    else
        lineLine(a, b, s, ts);
}

Box boxOf(const Segment& s)
{
    Box box{std::min(s.start.x, s.end.x), std::min(s.start.y, s.end.y), std::max(s.start.x, s.end.x),
            std::max(s.start.y, s.end.y)};
    if (!s.isArc())
        return box;
    // The ends plus each axis extreme of the circle that the sweep passes (a flat arc of a huge
    // radius keeps a flat box).
    const double r = radiusOf(s);
    const double sweep = s.sweep();
    const double dir = sweep >= 0 ? 1.0 : -1.0;
    const Vec2 a = s.start - s.center;
    const double a0 = std::atan2(a.y, a.x);
    for (int k = 0; k < 4; ++k) {
        double rel = std::fmod(dir * (k * std::numbers::pi / 2 - a0), kTwoPi);
        if (rel < 0)
            rel += kTwoPi;
        if (rel > std::abs(sweep))
            continue;
        const Vec2 extreme = s.center + Vec2{k == 0 ? r : k == 2 ? -r : 0.0, k == 1 ? r : k == 3 ? -r : 0.0};
        box = {std::min(box.minX, extreme.x), std::min(box.minY, extreme.y), std::max(box.maxX, extreme.x),
               std::max(box.maxY, extreme.y)};
    }
    return box;
}

}  // namespace camwb::geom::detail
