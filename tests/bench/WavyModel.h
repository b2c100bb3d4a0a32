// The drop-cutter benchmarks' model: a 100 x 100 mm wavy surface with a dome, 708 x 708 squares of
// two triangles (1,002,528 triangles), open (a surface, not a solid), and the 200 x 200 grid of
// points 0.5 mm apart over it where the tool is dropped.
#pragma once

#include "base/Vec.h"
#include "sim/TriangleMesh.h"

#include <vector>

namespace camwb::bench {

const sim::TriangleMesh& wavyModel();
std::vector<base::Vec2> wavyGridPoints();

}  // namespace camwb::bench
