// The geometry of a CL Arc, written once for every module: plane, sweep, length, splitting into
// pieces of bounded sweep (the post kernel's arc policy), linearisation within a chord tolerance
// (posts that cannot write an arc, the backplot, round trips) and exact extents (machine checks,
// program statistics). An arc runs from the current position `start` to `arc.to`; an end on the
// start (in the arc's plane) is a full circle, `turns` adds revolutions, and the height along the
// normal and the radius change linearly with the angle (helices; NC whose radii disagree a little).
#pragma once

#include "toolpath/ClRecords.h"

#include <string>
#include <vector>

namespace camwb::toolpath {

struct ArcPiece {
    Vec3 start, end, center;
    Vec3 normal;             // canonical: +Z, +Y or +X for the principal planes
    bool clockwise = false;  // seen looking against `normal`
    double sweepDeg = 0;     // > 0
    double radius = 0;       // at the start
    bool helical = false;    // the end leaves the start's plane
};

// "XY", "ZX", "YZ" for normals along Z, Y, X (either sign), "" for any other plane.
std::string arcPlane(const Vec3& normal);

// Total sweep of `arc` from `start` in degrees (counting `turns`; start == end is a full circle);
// 0 for a degenerate arc (start or end on the axis).
double arcSweepDeg(const Vec3& start, const Arc& arc);

// Length of the path along the arc (a helix's slope included); the chord for a degenerate arc.
double arcLength(const Vec3& start, const Arc& arc);

// Angle in [0, 2*pi) travelled from `from` to `to` round `arc`'s centre in `arc`'s direction, both
// points projected into the arc's plane (0 when they coincide there).
double forwardAngle(const Arc& arc, const Vec3& from, const Vec3& to);

// Tangent (not normalised) at the end of `arc` in its direction of travel, in its plane.
Vec3 arcEndTangent(const Arc& arc);

// Splits `arc` starting at `start` into equal pieces of at most maxSweepDeg each. Normals along a
// negative principal axis are flipped, with the direction, so that `clockwise` always means G2 for
// G17/G18/G19. Empty for a degenerate arc.
std::vector<ArcPiece> splitArc(const Vec3& start, const Arc& arc, double maxSweepDeg);

// Points along the arc (not the start, ending exactly at arc.to) such that no chord strays more
// than toleranceMm from the arc, nor spans more than maxStepDeg; at most maxPoints (0: no limit)
// where a display must bound its work. Helices and spirals keep their pitch and radius change.
// A degenerate arc is its end point alone.
std::vector<Vec3> linearizeArc(const Vec3& start, const Arc& arc, double toleranceMm, double maxStepDeg = 360,
                               int maxPoints = 0);

// How many points linearizeArc() gives for the same arguments, without making them.
int linearizedPointCount(const Vec3& start, const Arc& arc, double toleranceMm, double maxStepDeg = 360,
                         int maxPoints = 0);

// Grows [min, max] to hold the whole arc: exactly for arcs and helices in the principal planes
// (the extreme points of the circle inside the sweep), within 1e-5 of the radius otherwise.
void extendByArc(Vec3& min, Vec3& max, const Vec3& start, const Arc& arc);

}  // namespace camwb::toolpath
