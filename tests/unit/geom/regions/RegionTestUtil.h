// Shapes and checks shared by the region tests: loops sampled exactly (arcs by pointAt) and the
// distance from a point to a polyline, for checking fits and offsets against their inputs.
#pragma once

#include "../GeomTestUtil.h"
#include "geom/Region.h"

#include <limits>
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
        best = std::min(best, test::distanceToSegment(p, Segment::line(pts[i], pts[(i + 1) % n])));
    return best;
}

inline Region roundedRectWithCircle(double w, double h, double r, Vec2 c, double holeRadius)
{
    return Region{roundedRectangle(0, 0, w, h, r), {circle(c, holeRadius).reversed()}};
}

inline std::size_t countLines(const Profile& p) { return p.segments.size() - countArcs(p); }

}  // namespace camwb::geom::test
