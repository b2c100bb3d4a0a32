// The exact distance from a point to a triangle mesh (the design model): how deep a point the
// stock's rays say is inside the model really is. A ray measures along itself, which at a surface
// it grazes (a hole's floor seen along X at 30 degrees) reads several times the true depth; the
// gouge checks confirm a depth with this before they call it a gouge.
#pragma once

#include "sim/TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace camwb::sim {

class MeshDistance {
public:
    MeshDistance() = default;
    explicit MeshDistance(const TriangleMesh& mesh);

    bool empty() const { return m_triangles.empty(); }
    // The distance from `p` to the nearest triangle, or `within` if none is nearer than that
    // (the search visits only the grid cells within that distance of p).
    double distance(const base::Vec3& p, double within) const;

private:
    double nearestWithin(const base::Vec3& p, double radius) const;  // +infinity: no triangle in the box

    struct Triangle {
        base::Vec3 a, b, c;
    };
    std::vector<Triangle> m_triangles;
    // A uniform grid over the mesh's box: per cell, the triangles whose box overlaps it (CSR).
    base::Vec3 m_origin;
    double m_cell = 1;
    int m_n[3] = {1, 1, 1};
    std::vector<std::uint32_t> m_start, m_items;
};

// The point of triangle (a, b, c) nearest to p.
base::Vec3 closestOnTriangle(const base::Vec3& p, const base::Vec3& a, const base::Vec3& b, const base::Vec3& c);

}  // namespace camwb::sim
