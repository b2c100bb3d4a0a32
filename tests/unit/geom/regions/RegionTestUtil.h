// Shapes and checks shared by the region tests: loops sampled exactly (arcs by pointAt), the
// distance from a point to a polyline, and generated regions (rounded rectangles and star polygons
// with bulged arc edges, islands of circles and rounded rectangles) for the property tests.
#pragma once

#include "../GeomTestUtil.h"
#include "geom/Region.h"

#include <limits>
#include <random>
#include <vector>

namespace camwb::geom::test {

// Points along every segment, `perSegment` intervals each, arcs exactly on the circle.
inline std::vector<Vec2> samples(const Profile& p, int perSegment)
{
    std::vector<Vec2> out;
    for (const Segment& s : p.segments)
        for (int i = 0; i <= perSegment; ++i)
            out.push_back(s.pointAt(static_cast<double>(i) / perSegment));
    return out;
}

inline double distanceToPolyline(Vec2 p, const std::vector<Vec2>& pts, bool closed)
{
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i)
        best = std::min(best, geom::distanceToSegment(p, Segment::line(pts[i], pts[(i + 1) % n])));
    return best;
}

inline Region roundedRectWithCircle(double w, double h, double r, Vec2 c, double holeRadius)
{
    return Region{roundedRectangle(0, 0, w, h, r), {circle(c, holeRadius).reversed()}};
}

inline std::size_t countLines(const Profile& p) { return p.segments.size() - countArcs(p); }

// The arc from a through m to b (m strictly between them along the arc).
inline Segment arcThrough(Vec2 a, Vec2 m, Vec2 b)
{
    const Vec2 ab = m - a, ac = b - a;
    const double d = 2 * ab.cross(ac);
    const Vec2 c = a + Vec2{(ac.y * ab.dot(ab) - ab.y * ac.dot(ac)) / d, (ab.x * ac.dot(ac) - ac.x * ab.dot(ab)) / d};
    return Segment::arc(a, b, c, d > 0);
}

// Star-shaped polygon around (50, 50) whose edges are lines or arcs bulging in or out.
inline Profile bulgedStar(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    const int n = 5 + static_cast<int>(unit(rng) * 5);
    std::vector<Vec2> pts;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * (i + 0.3 * unit(rng)) / n;
        const double r = 28 + 12 * unit(rng);
        pts.push_back({50 + r * std::cos(a), 50 + r * std::sin(a)});
    }
    Profile p;
    for (int i = 0; i < n; ++i) {
        const Vec2 a = pts[i], b = pts[(i + 1) % n];
        const double bulge = (unit(rng) - 0.5) * 0.3 * distance(a, b);
        if (unit(rng) < 0.3 || std::abs(bulge) < 0.5) {
            p.segments.push_back(Segment::line(a, b));
            continue;
        }
        const Vec2 m = (a + b) * 0.5 + (b - a).normalized().rightNormal() * bulge;
        p.segments.push_back(arcThrough(a, m, b));
    }
    return p;
}

inline Profile randomIsland(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec2 c{30 + 40 * unit(rng), 30 + 40 * unit(rng)};
    if (unit(rng) < 0.5)
        return circle(c, 2 + 4 * unit(rng)).reversed();
    const double w = 4 + 8 * unit(rng), h = 4 + 8 * unit(rng);
    return roundedRectangle(c.x - w / 2, c.y - h / 2, w, h, std::min(w, h) * 0.45 * unit(rng)).reversed();
}

inline bool loopClear(const Profile& loop, const Region& region, double clearance)
{
    for (const Vec2& p : samples(loop, 32))
        if (!region.contains(p) || region.distanceToBoundary(p) < clearance)
            return false;
    return true;
}

inline Region randomRegion(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    Region region;
    if (unit(rng) < 0.4) {
        const double w = 40 + 40 * unit(rng), h = 40 + 40 * unit(rng);
        region.outer = roundedRectangle(50 - w / 2, 50 - h / 2, w, h, std::min(w, h) * 0.4 * unit(rng));
    } else {
        region.outer = bulgedStar(rng);
    }
    const int islands = static_cast<int>(unit(rng) * 4);
    for (int i = 0; i < 20 && static_cast<int>(region.holes.size()) < islands; ++i) {
        const Profile island = randomIsland(rng);
        if (loopClear(island, region, 1.0))
            region.holes.push_back(island);
    }
    return region;
}

}  // namespace camwb::geom::test
