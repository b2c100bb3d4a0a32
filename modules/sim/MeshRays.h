// Where a triangle mesh crosses a grid of parallel rays: a design model's top heights over a
// height field's columns, a blank's inside along each dexel. One rasteriser for both, with a
// tie rule that counts a ray through a shared edge or vertex exactly once.
#pragma once

#include "sim/TriangleMesh.h"

#include <functional>

namespace camwb::sim {

// Rays along +axis (0 x, 1 y, 2 z) through the centres of an nu x nv grid of cells in the two
// other coordinates, taken in cyclic order (z: u = x, v = y; x: u = y, v = z; y: u = z, v = x).
struct RayGrid {
    int axis = 2;
    double u0 = 0, v0 = 0;  // the grid's corner
    double du = 1, dv = 1;  // cell sizes
    int nu = 0, nv = 0;
    double uAt(int i) const { return u0 + (i + 0.5) * du; }
    double vAt(int j) const { return v0 + (j + 0.5) * dv; }
};

// Calls `crossing(i, j, t, entering)` for each ray (i, j) and triangle it crosses: t the
// coordinate along the axis, entering when the triangle faces against the ray (outward normals).
void forEachCrossing(const TriangleMesh& mesh, const RayGrid& grid,
                     const std::function<void(int i, int j, double t, bool entering)>& crossing);

}  // namespace camwb::sim
