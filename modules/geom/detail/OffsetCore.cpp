#include "geom/detail/OffsetCore.h"

#include "base/NumberFormat.h"

#include <cmath>
#include <numbers>
#include <optional>

namespace camwb::geom::detail {

std::string formatMm(double v) { return base::NumberFormat{3, true}.format(v); }

std::string formatPoint(Vec2 p) { return "(" + formatMm(p.x) + ", " + formatMm(p.y) + ")"; }

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLengthTol = 1e-9;   // mm: shorter segments are degenerate
constexpr double kTangentTol = 1e-9;  // rad: smaller turns are tangent joints

std::string fmt(double v) { return formatMm(v); }

std::string fmt(Vec2 p) { return formatPoint(p); }

base::Error offsetError(double distance, const std::string& what)
{
    return base::makeError("offset by " + fmt(distance) + " mm: " + what);
}

// Angle from a to b (vectors from a centre) travelling in direction `ccw`, in [0, 2*pi).
double angleInDirection(Vec2 a, Vec2 b, bool ccw)
{
    double angle = std::atan2(a.cross(b), a.dot(b));
    if (!ccw)
        angle = -angle;
    if (angle < 0)
        angle += 2 * kPi;
    return angle;
}

// Treat a travel angle close to a full turn as a small step backwards (an extension).
double signedTravel(double angle, double sweepAbs)
{
    return angle > sweepAbs && angle > 0.5 * (sweepAbs + 2 * kPi) ? angle - 2 * kPi : angle;
}

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

// Offset of one element, before trimming.
base::Result<Segment> offsetElement(const Segment& s, bool toLeft, double d)
{
    if (!s.isArc()) {
        const Vec2 t = (s.end - s.start).normalized();
        const Vec2 n = toLeft ? t.leftNormal() : t.rightNormal();
        return Segment::line(s.start + n * d, s.end + n * d);
    }
    const double r = s.radius();
    // An arc turning away from the offset side (its centre on the other side) grows.
    const double newRadius = s.ccw != toLeft ? r + d : r - d;
    if (newRadius <= kLengthTol)
        return offsetError(d, "tool too large for the concave arc of radius " + fmt(r) + " at " + fmt(s.center));
    const double k = newRadius / r;
    return Segment::arc(s.center + (s.start - s.center) * k, s.center + (s.end - s.center) * k, s.center, s.ccw);
}

}  // namespace

std::optional<Vec2> carrierIntersection(const Segment& a, const Segment& b, Vec2 near)
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

std::vector<Segment> withoutDegenerate(const std::vector<Segment>& segments)
{
    std::vector<Segment> out;
    for (const Segment& s : segments)
        if (s.length() > kLengthTol)
            out.push_back(s);
    return out;
}

base::Result<Profile> offsetToSide(const std::vector<Segment>& segs, bool closed, bool toLeft, double distance)
{
    const std::size_t n = segs.size();
    std::vector<Segment> untrimmed;
    for (const Segment& s : segs) {
        auto o = offsetElement(s, toLeft, distance);
        if (!o)
            return o.error();
        untrimmed.push_back(o.value());
    }
    std::vector<Segment> trimmed = untrimmed;
    std::vector<std::optional<Segment>> cornerArcs(n);  // cornerArcs[i]: between element i and i+1

    const std::size_t corners = closed ? n : n - 1;
    for (std::size_t i = 0; i < corners; ++i) {
        const std::size_t j = (i + 1) % n;
        const Vec2 vertex = segs[i].end;
        const Vec2 t1 = segs[i].endTangent();
        const Vec2 t2 = segs[j].startTangent();
        const double turn = std::atan2(t1.cross(t2), t1.dot(t2));  // signed, in (-pi, pi]
        const double outwardTurn = toLeft ? -turn : turn;          // > 0: convex on the offset side
        if (std::abs(turn) < kTangentTol) {
            // Tangent joint: both offsets end at the same point; snap away rounding noise.
            trimmed[j].start = trimmed[i].end;
            continue;
        }
        if (std::abs(std::abs(turn) - kPi) < kTangentTol)
            return offsetError(distance, "the profile turns back on itself at " + fmt(vertex));
        if (outwardTurn > 0) {
            // The corner arc turns the same way as the corner: left turns are counter-clockwise.
            cornerArcs[i] = Segment::arc(untrimmed[i].end, untrimmed[j].start, vertex, turn > 0);
            continue;
        }
        const Vec2 near = (untrimmed[i].end + untrimmed[j].start) * 0.5;
        const auto p = carrierIntersection(untrimmed[i], untrimmed[j], near);
        if (!p)
            return offsetError(distance, "the offsets at the concave corner " + fmt(vertex) +
                                             " do not meet: tool too large for the feature");
        trimmed[i].end = *p;
        trimmed[j].start = *p;
    }

    // A trimmed element must keep its direction and a length: otherwise the tool cannot reach.
    for (std::size_t i = 0; i < n; ++i) {
        const Segment& o = untrimmed[i];
        const Segment& t = trimmed[i];
        bool vanished = false;
        if (!o.isArc()) {
            vanished = (t.end - t.start).dot((o.end - o.start).normalized()) <= kLengthTol;
        } else {
            const double sweepAbs = std::abs(o.sweep());
            const double fromStart =
                signedTravel(angleInDirection(o.start - o.center, t.start - o.center, o.ccw), sweepAbs);
            const double fromEnd = signedTravel(angleInDirection(t.end - o.center, o.end - o.center, o.ccw), sweepAbs);
            vanished = (sweepAbs - fromStart - fromEnd) * o.radius() <= kLengthTol;
        }
        if (vanished) {
            const Segment& s = segs[i];
            return offsetError(distance, std::string("the ") + (s.isArc() ? "arc" : "line") + " from " + fmt(s.start) +
                                             " to " + fmt(s.end) +
                                             " vanishes or reverses after trimming: tool too large for the feature");
        }
    }

    Profile out;
    out.closed = closed;
    for (std::size_t i = 0; i < n; ++i) {
        out.segments.push_back(trimmed[i]);
        if (cornerArcs[i])
            out.segments.push_back(*cornerArcs[i]);
    }
    return out;
}

}  // namespace camwb::geom::detail
