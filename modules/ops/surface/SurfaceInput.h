// What the 3D operations (3D pocket, waterline, parallel finishing) are computed from: the part as
// a triangle mesh in work coordinates, the area the tool centre may use, the stock, the heights of
// the part's flat floors (so that a level lands exactly on each) and, for rest machining, the
// stock as the previous operations left it. Filled by the document layer from the job and model.
#pragma once

#include "base/Vec.h"
#include "geom/Region.h"
#include "sim/HeightField.h"
#include "sim/TriangleMesh.h"

#include <vector>

namespace camwb::ops {

struct SurfaceInput {
    const sim::TriangleMesh* model = nullptr;  // the part (closed, outward triangles), work coordinates
    // Where the tool centre may go, seen from above (the silhouette of the selected faces); empty:
    // anywhere over the stock box.
    std::vector<geom::Region> boundary;
    base::Box3 stock;  // the raw material's box
    // Z of the part's horizontal, upward-facing faces (pocket floors, tops of bosses), exact from
    // the B-rep where there is one; levels are forced onto these.
    std::vector<double> flatLevels;
    // Rest machining: the stock as the operations before this one left it (null: the stock box,
    // uncut). Levels cut only where this still has material.
    const sim::HeightField* restStock = nullptr;
};

}  // namespace camwb::ops
