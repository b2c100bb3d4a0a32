// Working planes (3+2) from what a user or a program gives, and back: a face's normal, or the
// spatial angles A, B, C (the frame turned about the workpiece's fixed X by A, then its fixed Y by
// B, then its fixed Z by C: R = Rz(C)·Ry(B)·Rx(A)). Operations, posts and interpreters share
// these, so a plane means the same everywhere.
#pragma once

#include "toolpath/ClRecords.h"

#include <array>

namespace camwb::toolpath {

// The plane whose tool axis is `normal` (any length but 0), its x axis the workpiece's X projected
// onto the plane (the workpiece's Y where the normal lies along X), through `origin`.
WorkingPlane planeAlong(const Vec3& normal, const Vec3& origin = {});

WorkingPlane planeFromSpatialAngles(double aDeg, double bDeg, double cDeg, const Vec3& origin = {});
// The angles of `plane`'s rotation: A and C in (-180, 180], B in [-90, 90]; where B is ±90 (A and
// C turn about the same line) A is 0.
std::array<double, 3> spatialAngles(const WorkingPlane& plane);

}  // namespace camwb::toolpath
