// Private helpers of the region kit: exact point-in-loop parity and segment/loop crossings with
// lines and arcs, shared by Region.cpp and RegionOps.cpp. Not part of the geom interface.
#pragma once

#include "geom/Profile.h"

#include <vector>

namespace camwb::geom::detail {

// Points closer than this (mm) to a loop count as on it (inside, for regions).
inline constexpr double kOnBoundary = 1e-9;

// Parity of the crossings of the ray from p towards +x with the closed loop (either
// orientation), arcs exact. Undefined for points on the loop; callers test that first.
bool insideLoop(const Profile& loop, Vec2 p);

// Whether p lies within kOnBoundary of the loop (cheap rejections first: contains() asks this of
// every point it tests).
bool onLoop(const Profile& loop, Vec2 p);

// Appends the parameters t in [0, 1] where the segment a + t (b - a) meets `s` (crossings,
// touches, the ends of a collinear overlap), within kOnBoundary.
void appendCrossings(Vec2 a, Vec2 b, const Segment& s, std::vector<double>& ts);

struct Box {
    double minX, minY, maxX, maxY;
    bool overlaps(const Box& o, double margin) const
    {
        return minX <= o.maxX + margin && o.minX <= maxX + margin && minY <= o.maxY + margin && o.minY <= maxY + margin;
    }
};

// A box around the segment (arcs: their whole circle, which is enough for rejection tests).
Box boxOf(const Segment& s);

}  // namespace camwb::geom::detail
