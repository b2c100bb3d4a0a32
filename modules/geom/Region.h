// A planar region bounded by line/arc loops: one outer loop (counter-clockwise) and any number of
// holes (clockwise) inside it. Pocket floors with islands, offset results and uncut areas are
// regions; a set of disjoint regions is std::vector<Region>.
#pragma once

#include "geom/Profile.h"

#include <vector>

namespace camwb::geom {

struct Region {
    Profile outer;               // closed, counter-clockwise
    std::vector<Profile> holes;  // closed, clockwise, inside outer, disjoint

    // Outer area minus the holes' areas (mm^2), arcs exact.
    double area() const;
    // Strictly inside the outer loop and outside every hole (points on a loop count as inside).
    bool contains(Vec2 p) const;
    // Shortest distance from p to any loop of the region.
    double distanceToBoundary(Vec2 p) const;
    // Orients the loops (outer ccw, holes cw); does not check nesting.
    Region normalized() const;
};

// Shortest distance from p to the segment (line or arc).
double distanceToSegment(Vec2 p, const Segment& s);
// Shortest distance from p to any segment of the profile.
double distanceToProfile(Vec2 p, const Profile& profile);

double totalArea(const std::vector<Region>& regions);
bool anyContains(const std::vector<Region>& regions, Vec2 p);

}  // namespace camwb::geom
