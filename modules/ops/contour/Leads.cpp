#include "ops/contour/Leads.h"

#include <cmath>
#include <numbers>

namespace camwb::ops::contour {

namespace {

// A quarter arc of radius r tangent to the path at `at` (travel direction t), bending towards
// the free normal n; `into`: the arc ends at `at` (lead-in), else it starts there (lead-out).
Segment quarterArc(Vec2 at, Vec2 t, Vec2 n, double r, bool into)
{
    const Vec2 centre = at + n * r;
    const bool ccw = n.cross(t) < 0;  // n on the left of t: counter-clockwise round the centre
    return into ? Segment::arc(centre - t * r, at, centre, ccw) : Segment::arc(at, centre + t * r, centre, ccw);
}

std::vector<Segment> lead(LeadKind kind, Vec2 at, Vec2 t, Vec2 n, double r, bool into)
{
    switch (kind) {
    case LeadKind::None:
        return {};
    case LeadKind::Arc:
        return {quarterArc(at, t, n, r, into)};
    case LeadKind::Line:
        return {into ? Segment::line(at - t * r, at) : Segment::line(at, at + t * r)};
    case LeadKind::PerpendicularLine:
        return {into ? Segment::line(at + n * r, at) : Segment::line(at, at + n * r)};
    }
    return {};
}

}  // namespace

Vec2 Cut::entryPoint() const
{
    if (approach)
        return *approach;
    return leadIn.empty() ? path.start() : leadIn.front().start;
}

Vec2 Cut::entryDirection() const
{
    if (approach) {
        const Vec2 to = leadIn.empty() ? path.start() : leadIn.front().start;
        return (to - *approach).normalized();
    }
    return leadIn.empty() ? path.startTangent() : leadIn.front().startTangent();
}

Vec2 Cut::exitPoint() const
{
    if (departure)
        return *departure;
    return leadOut.empty() ? path.end() : leadOut.back().end;
}

Cut withLeads(Path path, const ContourParams& params, bool control, double approachMm)
{
    Cut cut;
    cut.leadIn =
        lead(params.leadIn, path.start(), path.startTangent(), path.freeNormalAtStart(), params.leadRadiusMm, true);
    cut.leadOut =
        lead(params.leadOut, path.end(), path.endTangent(), path.freeNormalAtEnd(), params.leadRadiusMm, false);
    if (control) {
        // Straight moves from and to the free side, on which the control builds up and drops
        // the compensation (it refuses to switch on an arc).
        const Vec2 in = cut.leadIn.empty() ? path.start() : cut.leadIn.front().start;
        const Vec2 out = cut.leadOut.empty() ? path.end() : cut.leadOut.back().end;
        cut.approach = in + path.freeNormalAtStart() * approachMm;
        cut.departure = out + path.freeNormalAtEnd() * approachMm;
    }
    cut.path = std::move(path);
    return cut;
}

Helix helixTo(Vec2 end, Vec2 direction, bool leftOfDirection, double radius, double pitch, double zTop, double zEnd)
{
    Helix h;
    const Vec2 side = leftOfDirection ? direction.leftNormal() : direction.rightNormal();
    h.centre = end + side * radius;
    h.ccw = leftOfDirection;  // centre on the left of travel: counter-clockwise
    const double total = 2 * std::numbers::pi * (zTop - zEnd) / pitch;
    const double signedTotal = h.ccw ? total : -total;
    const Vec2 r = end - h.centre;
    const double a0 = std::atan2(r.y, r.x) - signedTotal;
    h.start = h.centre + Vec2{std::cos(a0), std::sin(a0)} * radius;
    // The remainder first, then half turns, so the last arc ends exactly on `end`.
    const double half = std::numbers::pi;
    const int halves = static_cast<int>(std::floor(total / half + 1e-9));
    const double remainder = total - halves * half;
    double angle = a0, z = zTop;
    auto step = [&](double sweep) {
        angle += h.ccw ? sweep : -sweep;
        z -= (zTop - zEnd) * sweep / total;
        const Vec2 from = h.arcs.empty() ? h.start : h.arcs.back().first.end;
        h.arcs.push_back(
            {Segment::arc(from, h.centre + Vec2{std::cos(angle), std::sin(angle)} * radius, h.centre, h.ccw), z});
    };
    if (remainder > 1e-9)
        step(remainder);
    for (int i = 0; i < halves; ++i)
        step(half);
    if (!h.arcs.empty()) {
        h.arcs.back().first.end = end;
        h.arcs.back().second = zEnd;
    }
    return h;
}

}  // namespace camwb::ops::contour
