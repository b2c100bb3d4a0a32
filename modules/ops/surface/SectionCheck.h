// A second, independent look at the roughing's tool-centre regions: the model's sections (the mesh
// slicer) against the regions the shadows gave. Where the cutter has its full radius, the model's
// section must stay that radius plus the side stock from every point of the region; two algorithms
// on one mesh that disagree mean a bug, which the operation reports instead of cutting.
#pragma once

#include "geom/Region.h"
#include "sim/TriangleMesh.h"

#include <optional>
#include <vector>

namespace camwb::ops::surface {

struct SectionClearance {
    double radiusMm = 0;            // the cutter's full radius + the side stock
    double fullRadiusHeightMm = 0;  // above the tip, where the cutter has that radius
    double bottomStockMm = 0;
    double toleranceMm = 0.01;
};

// The first level (index) whose region comes closer than the clearance less twice the tolerance to
// the model's section a tolerance above the level - bottom stock + the full-radius height; none:
// all keep clear.
std::optional<std::size_t> firstLevelTouchingSection(const sim::TriangleMesh& model, const std::vector<double>& levels,
                                                     const std::vector<std::vector<geom::Region>>& regions,
                                                     const SectionClearance& clearance);

}  // namespace camwb::ops::surface
