// Arc construction shared by the CL importers: normals along a principal axis become exactly +X,
// +Y or +Z (the direction flips with them, so G2 reads "cw" whatever the source wrote), the centre
// moves into the start's plane (so a helix shows in its end alone), and start and end are checked
// against the circle so that inconsistent CL data is reported rather than posted.
#pragma once

#include "toolpath/ArcGeometry.h"
#include "toolpath/ClRecords.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::toolpath {

// `axis` of length > 0; the motion turns counter-clockwise about it by the right-hand rule.
Arc makeArc(const Vec3& start, const Vec3& to, const Vec3& center, const Vec3& axis, bool counterClockwiseAboutAxis,
            int turns, double feed);

// Human-readable problems of an arc from `start`: start or end farther than `toleranceMm` from
// the stated radius, or (with no stated radius) start and end at different distances from the
// axis. Empty when the arc is consistent.
std::vector<std::string> arcRadiusProblems(const Vec3& start, const Arc& arc, std::optional<double> radiusMm,
                                           double toleranceMm);

// The unit vector along `v`, nullopt for a (near) zero vector.
std::optional<Vec3> unitVector(const Vec3& v);

// Whether the unit vector `axis` is +Z (within rounding of the file's digits).
bool isPlusZ(const Vec3& axis);

}  // namespace camwb::toolpath
