// Helpers of the slicing tests: analytic meshes whose sections are known (a sphere, a drafted
// frustum, a torus, all closed and oriented outwards), and measures of how far two sets of loops
// lie from each other (the one-sided distances of a Hausdorff distance) and their areas.
#pragma once

#include "base/Vec.h"
#include "sim/TriangleMesh.h"

#include <vector>

namespace camwb::ops::surface::test {

using Loops = std::vector<std::vector<base::Vec2>>;

// A UV sphere of `radius` about `centre`: `rings` latitude bands (ring Z at centre.z - radius *
// cos(pi * i / rings)), `segments` around. `soup`: every triangle with its own three vertices, as
// an STL gives them (the slicer must weld them).
sim::TriangleMesh sphereMesh(base::Vec3 centre, double radius, int rings, int segments, bool soup = false);

// A closed frustum about the Z axis: radius r0 at z0 and r1 at z1 (a drafted wall), flat floor and
// top, `segments` around and `bands` bands up the wall.
sim::TriangleMesh frustumMesh(double r0, double z0, double r1, double z1, int segments, int bands);

// A torus about the Z axis: the tube's centre circle of radius `major` at Z 0, tube radius `minor`.
sim::TriangleMesh torusMesh(double major, double minor, int around, int tube);

// The mesh with its triangles [first, first + count) left out (an open mesh).
sim::TriangleMesh withoutTriangles(const sim::TriangleMesh& mesh, std::size_t first, std::size_t count);

// The largest distance from a point of `from` to the segments of `to`'s loops (infinite when `to`
// is empty and `from` is not).
double oneSidedDistance(const Loops& from, const Loops& to);
// max(oneSidedDistance(a, b), oneSidedDistance(b, a)).
double hausdorff(const Loops& a, const Loops& b);

double signedArea(const std::vector<base::Vec2>& loop);
// The sum of the loops' signed areas: the material's area when outer loops run counter-clockwise
// and holes clockwise.
double signedArea(const Loops& loops);
double perimeter(const Loops& loops);

}  // namespace camwb::ops::surface::test
