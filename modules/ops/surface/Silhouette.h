// A mesh seen from above: the union of its triangles projected onto XY. The area a 3D operation
// keeps its tool centre in when the user selects faces (the cavity's opening, a boss' footprint).
#pragma once

#include "geom/Region.h"
#include "sim/TriangleMesh.h"

#include <vector>

namespace camwb::ops::surface {

// The projected triangles united (vertical triangles, which project to a line, add nothing), as
// regions with their loops within `toleranceMm` of the exact outline.
std::vector<geom::Region> silhouette(const sim::TriangleMesh& mesh, double toleranceMm);

}  // namespace camwb::ops::surface
