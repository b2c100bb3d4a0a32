// Shapes shared by the geom and ops unit tests (distances: geom::distanceToProfile in Region.h).
#pragma once

#include "geom/Profile.h"
#include "geom/Region.h"  // geom::distanceToSegment / distanceToProfile, used with these shapes

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace camwb::geom::test {

// Closed polygon of lines through the points, in the order given.
inline Profile polygon(const std::vector<Vec2>& pts)
{
    Profile p;
    for (std::size_t i = 0; i < pts.size(); ++i)
        p.segments.push_back(Segment::line(pts[i], pts[(i + 1) % pts.size()]));
    return p;
}

inline Profile rectangle(double x0, double y0, double w, double h)
{
    return polygon({{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}});
}

// Counter-clockwise rectangle with corner arcs of radius r, lower-left corner at (x0, y0).
inline Profile roundedRectangle(double x0, double y0, double w, double h, double r)
{
    const double x1 = x0 + w, y1 = y0 + h;
    Profile p;
    p.segments = {
        Segment::line({x0 + r, y0}, {x1 - r, y0}), Segment::arc({x1 - r, y0}, {x1, y0 + r}, {x1 - r, y0 + r}, true),
        Segment::line({x1, y0 + r}, {x1, y1 - r}), Segment::arc({x1, y1 - r}, {x1 - r, y1}, {x1 - r, y1 - r}, true),
        Segment::line({x1 - r, y1}, {x0 + r, y1}), Segment::arc({x0 + r, y1}, {x0, y1 - r}, {x0 + r, y1 - r}, true),
        Segment::line({x0, y1 - r}, {x0, y0 + r}), Segment::arc({x0, y0 + r}, {x0 + r, y0}, {x0 + r, y0 + r}, true),
    };
    return p;
}

inline Profile circle(Vec2 c, double r)
{
    Profile p;
    p.segments = {Segment::arc(c + Vec2{r, 0}, c + Vec2{r, 0}, c, true)};
    return p;
}

inline std::size_t countArcs(const Profile& p)
{
    return static_cast<std::size_t>(
        std::count_if(p.segments.begin(), p.segments.end(), [](const Segment& s) { return s.isArc(); }));
}

}  // namespace camwb::geom::test
