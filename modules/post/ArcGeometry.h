// Arc geometry for the post kernel's arc policy: plane classification, sweep, splitting of a CL
// Arc into pieces of bounded sweep (full circles and multi-turn helices become several pieces),
// linearisation within a chord tolerance, and the extents of an arc.
#pragma once

#include "toolpath/ClRecords.h"

#include <string>
#include <vector>

namespace camwb::post {

struct ArcPiece {
    toolpath::Vec3 start, end, center;
    toolpath::Vec3 normal;   // canonical: +Z, +Y or +X for the principal planes
    bool clockwise = false;  // seen looking against `normal`
    double sweepDeg = 0;     // > 0
    double radius = 0;       // at the start
    bool helical = false;    // the end leaves the start's plane
};

// "XY", "ZX", "YZ" for normals along Z, Y, X (either sign), "" for any other plane.
std::string arcPlane(const toolpath::Vec3& normal);

// Total sweep of `arc` from `start` in degrees (counting `turns`; start == end is a full circle);
// 0 for a degenerate arc (start or end on the axis).
double arcSweepDeg(const toolpath::Vec3& start, const toolpath::Arc& arc);

// Splits `arc` starting at `start` into equal pieces of at most maxSweepDeg each. Normals along a
// negative principal axis are flipped, with the direction, so that `clockwise` always means G2 for
// G17/G18/G19. Empty for a degenerate arc.
std::vector<ArcPiece> splitArc(const toolpath::Vec3& start, const toolpath::Arc& arc, double maxSweepDeg);

// Points along the arc (not the start, ending exactly at arc.to) such that no chord strays more
// than toleranceMm from the arc. Helices and spirals keep their pitch and radius change.
std::vector<toolpath::Vec3> linearizeArc(const toolpath::Vec3& start, const toolpath::Arc& arc, double toleranceMm);

// Grows [min, max] to hold the whole arc: exactly for arcs and helices in the principal planes
// (the extreme points of the circle inside the sweep), within 1e-5 of the radius otherwise.
void extendByArc(toolpath::Vec3& min, toolpath::Vec3& max, const toolpath::Vec3& start, const toolpath::Arc& arc);

}  // namespace camwb::post
