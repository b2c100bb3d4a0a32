// A triangle mesh in plain arrays: the design model the simulator compares with (from occ's
// meshing or an STL), and the cut stock it shows and exports. No OCCT, no VTK.
#pragma once

#include "base/Result.h"
#include "base/Vec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::sim {

struct TriangleMesh {
    std::vector<float> positions;          // x, y, z per vertex
    std::vector<std::uint32_t> triangles;  // three vertex indices per triangle, counter-clockwise from outside

    std::size_t vertexCount() const { return positions.size() / 3; }
    std::size_t triangleCount() const { return triangles.size() / 3; }
    base::Vec3 vertex(std::size_t i) const { return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]}; }
    bool empty() const { return triangles.empty(); }
    base::Box3 bounds() const;
    // Enclosed volume (divergence theorem); meaningful for a closed, consistently oriented mesh.
    double volumeMm3() const;
};

// The mesh with vertices closer than `toleranceMm` (on a grid of that size) made one: OCCT meshes
// each face on its own, so a model's mesh repeats the vertices along every edge; welded, the
// triangles of neighbouring faces share them and a section can follow the surface across edges.
TriangleMesh weldVertices(const TriangleMesh& mesh, double toleranceMm = 1e-5);

// A closed cylinder along Z inside `box` (diameter = its x size, about its centre, from min.z to
// max.z): a job's round stock as the simulator cuts it. Its vertices lie on the circle, so the
// sides fall inside it by at most `chordToleranceMm`.
TriangleMesh cylinderMesh(const base::Box3& box, double chordToleranceMm = 0.001);

// Binary STL, written atomically (nothing half-written on failure).
// (Reading STL is occ's: a model or a stock from a mesh file comes through occ::Model.)
base::Status writeStl(const TriangleMesh& mesh, const std::string& path, const std::string& header = "camwb");

}  // namespace camwb::sim
