// The exact (arc-aware, no discretisation) parts of RegionOps.h: segmentInside, clipPolylines and
// regionsFromLoops. They only cut segments at exact loop crossings and test containment.
#include "geom/RegionOps.h"
#include "geom/detail/RegionLocator.h"

#include <algorithm>
#include <cmath>

namespace camwb::geom {

namespace {

using detail::Box;

Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + (b - a) * t; }

void appendPoint(std::vector<Vec2>& piece, Vec2 p)
{
    if (piece.empty() || distance(piece.back(), p) > 1e-12)
        piece.push_back(p);
}

}  // namespace

bool segmentInside(Vec2 a, Vec2 b, const std::vector<Region>& regions)
{
    // One query: a plain scan over the loops beats building a RegionLocator (RegionIndex does, for
    // many).
    if (regions.empty())
        return false;
    std::vector<double> ts{0.0, 1.0};
    const Box box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    auto scan = [&](const Profile& loop) {
        for (const Segment& s : loop.segments) {
            if (!s.isArc() && !detail::boxOf(s).overlaps(box, detail::kOnBoundary))
                continue;
            detail::appendCrossings(a, b, s, ts);
        }
    };
    for (const Region& region : regions) {
        scan(region.outer);
        for (const Profile& hole : region.holes)
            scan(hole);
    }
    std::sort(ts.begin(), ts.end());
    return detail::segmentWithin(a, b, ts, [&regions](Vec2 p) { return anyContains(regions, p); });
}

std::vector<std::vector<Vec2>> clipPolylines(const std::vector<std::vector<Vec2>>& polylines,
                                             const std::vector<Region>& regions, double tolerance)
{
    std::vector<std::vector<Vec2>> out;
    if (regions.empty())
        return out;
    const detail::RegionLocator index(regions);
    auto flush = [&out](std::vector<Vec2>& piece) {
        if (piece.size() >= 2)
            out.push_back(std::move(piece));
        piece.clear();
    };
    for (const std::vector<Vec2>& polyline : polylines) {
        if (polyline.size() == 1 && index.contains(polyline[0]))
            out.push_back(polyline);
        std::vector<Vec2> piece;
        // Whether the previous edge ended inside, known when its end touched no loop: an edge
        // that touches no loop then lies wholly on that side (saves containment tests).
        bool carried = false;
        bool carriedInside = false;
        for (std::size_t e = 0; e + 1 < polyline.size(); ++e) {
            const Vec2 a = polyline[e], b = polyline[e + 1];
            if (distance(a, b) <= 0)
                continue;
            bool touched = true;
            const std::vector<double> ts = index.breakpoints(a, b, &touched);
            bool inside = false;
            for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
                inside = carried && !touched ? carriedInside : index.contains(lerp(a, b, 0.5 * (ts[i] + ts[i + 1])));
                if (inside) {
                    appendPoint(piece, lerp(a, b, ts[i]));
                    appendPoint(piece, i + 2 == ts.size() ? b : lerp(a, b, ts[i + 1]));
                } else {
                    flush(piece);
                }
            }
            carried = !touched;
            carriedInside = inside;
        }
        flush(piece);
    }
    return out;
}

std::vector<Region> regionsFromLoops(const std::vector<Profile>& loops, double tolerance)
{
    struct Entry {
        const Profile* loop;
        double area;
        Box box;
        Vec2 probe;
    };
    std::vector<Entry> entries;
    for (const Profile& loop : loops) {
        const double area = std::abs(loop.signedArea());
        if (loop.segments.empty() || !(area > tolerance * tolerance * 1e-3))
            continue;
        Box box = detail::boxOf(loop.segments.front());
        const Segment* longest = &loop.segments.front();
        for (const Segment& s : loop.segments) {
            const Box b = detail::boxOf(s);
            box = {std::min(box.minX, b.minX), std::min(box.minY, b.minY), std::max(box.maxX, b.maxX),
                   std::max(box.maxY, b.maxY)};
            if (s.length() > longest->length())
                longest = &s;
        }
        entries.push_back({&loop, area, box, longest->pointAt(0.5)});
    }
    // Larger loops first: a loop's containers all come before it, the innermost one last.
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) { return x.area > y.area; });
    std::vector<int> depth(entries.size(), 0);
    std::vector<int> parent(entries.size(), -1);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Box& inner = entries[i].box;
        for (std::size_t j = 0; j < i; ++j) {
            const Box& outer = entries[j].box;
            if (outer.minX > inner.minX || outer.minY > inner.minY || outer.maxX < inner.maxX ||
                outer.maxY < inner.maxY)
                continue;
            if (detail::insideLoop(*entries[j].loop, entries[i].probe)) {
                ++depth[i];
                parent[i] = static_cast<int>(j);
            }
        }
    }
    std::vector<Region> regions;
    std::vector<int> regionOf(entries.size(), -1);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (depth[i] % 2 == 0) {
            regionOf[i] = static_cast<int>(regions.size());
            regions.push_back(Region{*entries[i].loop, {}});
        } else if (parent[i] >= 0 && regionOf[static_cast<std::size_t>(parent[i])] >= 0) {
            regions[static_cast<std::size_t>(regionOf[static_cast<std::size_t>(parent[i])])].holes.push_back(
                *entries[i].loop);
        }
    }
    for (Region& region : regions)
        region = region.normalized();
    return regions;
}

}  // namespace camwb::geom
