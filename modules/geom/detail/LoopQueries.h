// Private helpers of the region kit: exact point-in-loop parity and segment/loop crossings with
// lines and arcs, shared by Region.cpp and RegionOps.cpp. Not part of the geom interface.
#pragma once

#include "geom/Profile.h"

#include <cmath>
#include <vector>

namespace camwb::geom::detail {

// std::hypot (behind Vec2::length) is several times slower than a plain square root and the
// extra range it protects is not needed at part sizes; these run in every inner loop here.
inline double fastLength(Vec2 v) { return std::sqrt(v.dot(v)); }
inline double fastDistance(Vec2 a, Vec2 b) { return fastLength(a - b); }
inline double radiusOf(const Segment& s) { return fastDistance(s.start, s.center); }

// Points closer than this (mm) to a loop count as on it (inside, for regions).
inline constexpr double kOnBoundary = 1e-9;

// Parity of the crossings of the ray from p towards +x with the closed loop (either
// orientation), arcs exact. Undefined for points on the loop; callers test that first.
bool insideLoop(const Profile& loop, Vec2 p);

// Angle (radians, in [0, 2pi)) from the arc's start to the direction of q seen from its centre,
// measured in the arc's direction of travel: q's direction is within the arc when <= |sweep|.
double angleAlongArc(const Segment& s, Vec2 q);

// Crossings (0, 1 or 2) of the ray from p towards +x with the segment, half-open in y so that
// loop vertices count once; summed over a loop, odd means inside.
int crossingsRight(Vec2 p, const Segment& s);
// Whether p lies within kOnBoundary of the segment (cheap rejection first).
bool nearSegment(Vec2 p, const Segment& s);

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

// The segment's bounding box (arcs exact: their ends and the axis extremes they pass).
Box boxOf(const Segment& s);

}  // namespace camwb::geom::detail
