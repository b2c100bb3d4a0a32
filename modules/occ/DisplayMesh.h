// Triangles and feature edges of a model for display, in plain arrays so that the 3D view
// never sees an OCCT type. Produced by occ::Model::mesh().
#pragma once

#include "base/Vec.h"

#include <cstdint>
#include <vector>

namespace camwb::occ {

struct DisplayMesh {
    std::vector<float> positions;                       // x, y, z per vertex
    std::vector<float> normals;                         // x, y, z per vertex (same count as positions)
    std::vector<std::uint32_t> triangles;               // three vertex indices per triangle
    std::vector<int> triangleFace;                      // model face index (1-based) of each triangle
    std::vector<std::vector<base::Vec3>> featureEdges;  // polylines of the model's edges
    base::Vec3 boundsMin;
    base::Vec3 boundsMax;

    bool empty() const { return triangles.empty() && featureEdges.empty(); }
};

}  // namespace camwb::occ
