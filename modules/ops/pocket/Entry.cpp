#include "ops/pocket/Entry.h"

#include "base/NumberFormat.h"
#include "geom/RegionOps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::ops::pocket {

namespace {

constexpr double kPi = std::numbers::pi;

Vec2 onCircle(Vec2 centre, double radius, double angle)
{
    return centre + Vec2{std::cos(angle), std::sin(angle)} * radius;
}

// Arcs round `centre` from angle a0 turning by `sweep` (signed), z from z0 to z1, at most half a
// turn per record.
void writeTurns(PathWriter& out, Vec2 centre, double radius, double a0, double sweep, double z0, double z1, Feed feed)
{
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / kPi - 1e-9)));
    for (int i = 0; i < pieces; ++i) {
        const double b0 = a0 + sweep * i / pieces, b1 = a0 + sweep * (i + 1) / pieces;
        const Segment s = Segment::arc(onCircle(centre, radius, b0), onCircle(centre, radius, b1), centre, sweep > 0);
        out.segment(s, z0 + (z1 - z0) * i / pieces, z0 + (z1 - z0) * (i + 1) / pieces, feed);
    }
}

void writeHelix(PathWriter& out, const EntryPlan& plan, const Cut& cut, double top, double level,
                const EntrySettings& st)
{
    const double r = st.helixRadius;
    const double sign = st.ccw ? 1.0 : -1.0;
    const Vec2 c = plan.helixCentre;
    const double startAngle = std::atan2(plan.start.y - c.y, plan.start.x - c.x);
    // Whole half turns at exactly pitch/2 each, then the rest at the same pitch.
    const double depth = std::max(0.0, top - level);
    const double halfTurns = 2 * depth / st.helixPitch;
    const int whole = static_cast<int>(std::floor(halfTurns + 1e-9));
    double angle = startAngle, z = top;
    for (int i = 0; i < whole; ++i) {
        const double z1 = std::max(level, z - st.helixPitch / 2);
        writeTurns(out, c, r, angle, sign * kPi, z, z1, st.rampFeed);
        angle += sign * kPi;
        z = z1;
    }
    if (z > level + 1e-12) {
        const double sweep = 2 * kPi * (z - level) / st.helixPitch;
        writeTurns(out, c, r, angle, sign * sweep, z, level, st.rampFeed);
        angle += sign * sweep;
    }
    // A flat full circle at the level, continued round to the helix start (the link's end).
    double back = std::fmod(sign * (startAngle - angle) + 4 * kPi, 2 * kPi);
    if (back > 2 * kPi - 1e-9)
        back = 0;  // a whole number of turns: already back at the start
    writeTurns(out, c, r, angle, sign * (2 * kPi + back), level, level, st.cuttingFeed);
    out.feed({cut.start().x, cut.start().y, level}, st.cuttingFeed);
}

// Down along the cut at the ramp angle (closed cuts round and round, open ones back and forth),
// then at the level back to the cut start.
void writeRamp(PathWriter& out, const Cut& cut, double top, double level, const EntrySettings& st)
{
    const double slope = std::tan(st.rampAngleDeg * kPi / 180.0);
    const double length = cut.length();
    if (top - level <= 1e-12)
        return;
    if (length < 1e-6 || (top - level) / slope > 1e4 * length) {
        out.feed({cut.start().x, cut.start().y, level}, st.plungeFeed);  // nothing to ramp along
        return;
    }
    std::vector<Segment> backward;
    for (auto it = cut.path.rbegin(); it != cut.path.rend(); ++it)
        backward.push_back(it->reversed());
    double z = top;
    for (int pass = 0;; ++pass) {
        const bool forward = cut.closed || pass % 2 == 0;
        const std::vector<Segment>& walk = forward ? cut.path : backward;
        for (std::size_t k = 0; k < walk.size(); ++k) {
            const double dz = walk[k].length() * slope;
            if (z - dz > level + 1e-12) {
                out.segment(walk[k], z, z - dz, st.rampFeed);
                z -= dz;
                continue;
            }
            const double t = dz > 0 ? (z - level) / dz : 1.0;
            out.segment(subSegment(walk[k], 0, t), z, level, st.rampFeed);
            // Back to the start at the level: a closed cut or a backward pass goes on to the end
            // of this pass; a forward pass of an open cut retraces what it walked.
            if (forward && !cut.closed) {
                out.segment(subSegment(walk[k], 0, t).reversed(), level, level, st.cuttingFeed);
                for (std::size_t i = k; i-- > 0;)
                    out.segment(walk[i].reversed(), level, level, st.cuttingFeed);
            } else {
                if (t < 1)
                    out.segment(subSegment(walk[k], t, 1), level, level, st.cuttingFeed);
                for (std::size_t i = k + 1; i < walk.size(); ++i)
                    out.segment(walk[i], level, level, st.cuttingFeed);
            }
            return;
        }
    }
}

double helixDiameterOr(double requestedMm, double toolDiameterMm)
{
    return requestedMm > 0 ? requestedMm : 0.9 * toolDiameterMm;
}

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

}  // namespace

base::Status checkEntry(const std::string& what, const EntryRequest& r, const ToolController& tc)
{
    const double d = tc.tool.diameterMm;
    if (!(r.rampAngleDeg > 0) || r.rampAngleDeg > 90)
        return opError(what, "ramp angle must be in (0, 90] degrees, got " + fmt(r.rampAngleDeg));
    if (r.kind == EntryKind::Plunge && !tc.tool.centreCutting)
        return opError(what, "tool " + std::to_string(tc.tool.number) +
                                 " is not centre cutting and cannot plunge; use a helix or ramp entry");
    if (r.kind == EntryKind::Helix) {
        if (r.helixDiameterMm < 0 || helixDiameterOr(r.helixDiameterMm, d) > d + 1e-9)
            return opError(what, "helix diameter " + fmt(r.helixDiameterMm) +
                                     " mm must be positive and at most the tool diameter " + fmt(d) +
                                     " mm (a larger helix leaves a core standing)");
        if (!(r.helixPitchMm > 0))
            return opError(what, "helix pitch must be positive, got " + fmt(r.helixPitchMm) + " mm");
    }
    return base::Status::success();
}

EntrySettings entrySettings(const EntryRequest& r, const ToolController& tc)
{
    EntrySettings entry;
    entry.kind = r.kind;
    entry.helixRadius = helixDiameterOr(r.helixDiameterMm, tc.tool.diameterMm) / 2;
    entry.helixPitch = r.helixPitchMm;
    entry.rampAngleDeg = r.rampAngleDeg;
    entry.ccw = r.climb;
    entry.toleranceMm = r.toleranceMm;
    entry.rampFeed = feedOf(tc, toolpath::FeedKind::Entry);
    entry.plungeFeed = feedOf(tc, toolpath::FeedKind::Plunge);
    entry.cuttingFeed = feedOf(tc, toolpath::FeedKind::Cutting);
    return entry;
}

EntryPlanner::EntryPlanner(const geom::RegionIndex& region, const EntrySettings& settings) :
    m_region(region),
    m_settings(settings)
{
    if (settings.kind == EntryKind::Helix)
        m_helixCentres =
            geom::offsetRegions(region.regions(), -(settings.helixRadius + settings.toleranceMm), settings.toleranceMm);
}

EntryPlan EntryPlanner::plan(const Cut& cut)
{
    const Vec2 p = cut.start();
    if (m_settings.kind != EntryKind::Helix)
        return {m_settings.kind, p, {}};
    // Candidate centres: the cut start itself when a circle round it fits, else the nearest
    // point of each loop of the centre area; the first whose link to the start stays inside.
    std::vector<Vec2> candidates;
    if (geom::anyContains(m_helixCentres, p))
        candidates.push_back(p);
    std::vector<PathPoint> nearest;
    for (const geom::Region& r : m_helixCentres) {
        nearest.push_back(nearestOnPath(r.outer.segments, p));
        for (const geom::Profile& hole : r.holes)
            nearest.push_back(nearestOnPath(hole.segments, p));
    }
    std::sort(nearest.begin(), nearest.end(),
              [](const PathPoint& a, const PathPoint& b) { return a.distance < b.distance; });
    for (std::size_t i = 0; i < nearest.size() && i < 8; ++i)
        candidates.push_back(nearest[i].point);
    const double maxLink = 2 * m_settings.helixRadius + 2 * m_settings.toleranceMm + 1e-6;
    for (const Vec2& c : candidates) {
        const Vec2 toStart = p - c;
        const Vec2 dir = toStart.length() > 1e-9 ? toStart.normalized() : Vec2{1, 0};
        const Vec2 h = c + dir * m_settings.helixRadius;
        if (distance(h, p) <= maxLink && m_region.segmentInside(h, p))
            return {EntryKind::Helix, h, c};
    }
    ++m_fallbacks;
    return {EntryKind::Ramp, p, {}};
}

void writeEntry(PathWriter& out, const EntryPlan& plan, const Cut& cut, double top, double level,
                const EntrySettings& settings)
{
    switch (plan.kind) {
    case EntryKind::Plunge:
        out.feed({cut.start().x, cut.start().y, level}, settings.plungeFeed);
        break;
    case EntryKind::Ramp:
        writeRamp(out, cut, top, level, settings);
        break;
    case EntryKind::Helix:
        writeHelix(out, plan, cut, top, level, settings);
        break;
    }
}

}  // namespace camwb::ops::pocket
