#include "ops/pocket/Cleanup.h"

#include "geom/RegionOps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace camwb::ops::pocket {

namespace {

constexpr int kRounds = 4;

struct Detour {
    std::size_t segment = 0;
    double t = 0;
    Vec2 at, target;
    std::vector<Segment> loop;  // from the target round and back to it (empty: a point visit)
};

// A point inside the piece: the centroid of its outer loop when that is inside, else the middle
// of an ear (two vertices apart) that is.
Vec2 interiorPoint(const geom::Region& piece, double tolerance)
{
    const std::vector<Vec2> pts = samplePath(piece.outer.segments, tolerance);
    double area2 = 0;
    Vec2 sum;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const Vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
        const double w = a.cross(b);
        area2 += w;
        sum = sum + (a + b) * w;
    }
    if (std::abs(area2) > 1e-15) {
        const Vec2 centroid = sum * (1.0 / (3.0 * area2));
        if (piece.contains(centroid))
            return centroid;
    }
    for (std::size_t i = 0; i + 2 < pts.size() + 2 && pts.size() >= 3; ++i) {
        const Vec2 mid = (pts[i % pts.size()] + pts[(i + 2) % pts.size()]) * 0.5;
        if (piece.contains(mid))
            return mid;
    }
    return pts.empty() ? Vec2{} : pts.front();
}

// Where to send the tool for one uncut piece: round the part of the piece the tool centre may
// enter when the piece is long (a sliver between passes), else to one point inside it, clamped
// into the tool-centre region (a cusp, a corner between rings).
Detour plan(const geom::Region& piece, const std::vector<geom::Region>& toolCentre,
            const std::vector<geom::Region>& innerCentre, double radius, double tolerance)
{
    Detour detour;
    const Vec2 q = interiorPoint(piece, tolerance);
    double x0 = q.x, x1 = q.x, y0 = q.y, y1 = q.y;
    for (const Vec2& p : samplePath(piece.outer.segments, tolerance)) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    if (std::hypot(x1 - x0, y1 - y0) > radius) {
        // Against the tool-centre region shrunk by the tolerance: the fitted loop may stray that far.
        const std::vector<geom::Region> enterable = geom::intersect({piece}, innerCentre, tolerance);
        const geom::Region* largest = nullptr;
        for (const geom::Region& r : enterable)
            if (!largest || r.area() > largest->area())
                largest = &r;
        if (largest && !largest->outer.segments.empty()) {
            detour.loop = loopNearest(largest->outer.segments, q);
            detour.target = detour.loop.front().start;
            return detour;
        }
    }
    detour.target = geom::anyContains(toolCentre, q) ? q : nearestOnRegions(toolCentre, q).point;
    return detour;
}

// The detours of one round, applied cut by cut: each path segment split at its detour points.
void applyDetours(std::vector<Cut>& cuts, std::map<std::size_t, std::vector<Detour>>& byCut)
{
    for (auto& [cutIndex, detours] : byCut) {
        std::sort(detours.begin(), detours.end(), [](const Detour& a, const Detour& b) {
            return a.segment != b.segment ? a.segment < b.segment : a.t < b.t;
        });
        const std::vector<Segment>& old = cuts[cutIndex].path;
        std::vector<Segment> path;
        std::size_t d = 0;
        for (std::size_t i = 0; i < old.size(); ++i) {
            double t0 = 0;
            for (; d < detours.size() && detours[d].segment == i; ++d) {
                if (detours[d].t > t0 + 1e-12) {
                    path.push_back(subSegment(old[i], t0, detours[d].t));
                    t0 = detours[d].t;
                }
                const Vec2 at = path.empty() ? old[i].start : path.back().end;
                appendLine(path, at, detours[d].target);
                path.insert(path.end(), detours[d].loop.begin(), detours[d].loop.end());
                appendLine(path, detours[d].target, at);
            }
            if (t0 < 1 - 1e-12)
                path.push_back(subSegment(old[i], t0, 1));
        }
        cuts[cutIndex].path = std::move(path);
    }
}

}  // namespace

std::vector<std::vector<Vec2>> cutPolylines(const std::vector<Cut>& cuts, double tolerance)
{
    std::vector<std::vector<Vec2>> lines;
    lines.reserve(cuts.size());
    for (const Cut& cut : cuts)
        lines.push_back(samplePath(cut.path, tolerance));
    return lines;
}

CleanupResult addCleanup(std::vector<Cut>& cuts, const std::vector<geom::Region>& toolCentre, double radius,
                         double spacing, double tolerance)
{
    CleanupResult result;
    // The footprints are compared coarsely where they overlap a lot (small stepovers: the union of
    // many overlapping footprints is the expensive part) and finely where they barely touch.
    const double overlap = 2 * radius - spacing;
    const double sweepTol = std::clamp(overlap / 4, tolerance, std::max(tolerance, 0.05));
    // Reach less the sampling margins: the wall loop is the tool-centre boundary itself, so the
    // band between its exact and its sampled footprint is not material left behind.
    const std::vector<geom::Region> reach = geom::offsetRegions(toolCentre, radius - 2 * sweepTol, tolerance);
    std::vector<geom::Region> uncut =
        geom::subtract(reach, geom::sweptArea(cutPolylines(cuts, sweepTol), radius, sweepTol), sweepTol);
    const double minArea = std::max(1e-3, 10 * tolerance * tolerance);
    std::vector<geom::Region> innerCentre;
    for (int round = 0; round < kRounds; ++round) {
        std::vector<geom::Region> pieces;
        for (geom::Region& piece : uncut)
            if (piece.area() > minArea)
                pieces.push_back(std::move(piece));
        uncut.clear();
        if (pieces.empty())
            break;
        std::map<std::size_t, std::vector<Detour>> byCut;
        std::vector<std::vector<Vec2>> added;
        for (const geom::Region& piece : pieces) {
            if (innerCentre.empty())
                innerCentre = geom::offsetRegions(toolCentre, -tolerance, tolerance);
            Detour detour = plan(piece, toolCentre, innerCentre, radius, tolerance);
            // The nearest pattern point whose link stays inside (nearest points per cut, in order).
            std::vector<std::pair<PathPoint, std::size_t>> near;
            for (std::size_t c = 0; c < cuts.size(); ++c)
                near.push_back({nearestOnPath(cuts[c].path, detour.target), c});
            std::sort(near.begin(), near.end(),
                      [](const auto& a, const auto& b) { return a.first.distance < b.first.distance; });
            for (std::size_t i = 0; i < near.size() && i < 4; ++i) {
                const PathPoint& at = near[i].first;
                if ((at.distance < 1e-9 && detour.loop.empty()) ||
                    !geom::segmentInside(at.point, detour.target, toolCentre))
                    continue;
                detour.segment = at.segment;
                detour.t = at.t;
                detour.at = at.point;
                std::vector<Vec2> swept{at.point};
                for (const Vec2& p : samplePath(detour.loop, tolerance))
                    swept.push_back(p);
                swept.push_back(detour.target);
                added.push_back(std::move(swept));
                byCut[near[i].second].push_back(std::move(detour));
                ++result.detours;
                break;
            }
        }
        if (added.empty()) {
            uncut = std::move(pieces);
            break;
        }
        applyDetours(cuts, byCut);
        uncut = geom::subtract(pieces, geom::sweptArea(added, radius, sweepTol), sweepTol);
    }
    for (const geom::Region& piece : uncut)
        if (piece.area() > minArea)
            result.uncutArea += piece.area();
    return result;
}

}  // namespace camwb::ops::pocket
