// Arc geometry for the post kernel's arc policy: plane classification, sweep and splitting of a CL
// Arc into pieces of bounded sweep (full circles and multi-turn helices become several pieces).
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
    bool helical = false;    // the end leaves the start's plane
};

// "XY", "ZX", "YZ" for normals along Z, Y, X (either sign), "" for any other plane.
std::string arcPlane(const toolpath::Vec3& normal);

// Splits `arc` starting at `start` into equal pieces of at most maxSweepDeg each (the sweep counts
// `turns`; start == end is a full circle). Normals along a negative principal axis are flipped,
// with the direction, so that `clockwise` always means G2 for G17/G18/G19.
std::vector<ArcPiece> splitArc(const toolpath::Vec3& start, const toolpath::Arc& arc, double maxSweepDeg);

}  // namespace camwb::post
