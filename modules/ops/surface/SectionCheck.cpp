#include "ops/surface/SectionCheck.h"

#include "geom/RegionOps.h"
#include "ops/surface/MeshSlicer.h"

namespace camwb::ops::surface {

std::optional<std::size_t> firstLevelTouchingSection(const sim::TriangleMesh& model, const std::vector<double>& levels,
                                                     const std::vector<std::vector<geom::Region>>& regions,
                                                     const SectionClearance& c)
{
    std::vector<double> heights;
    for (double z : levels)
        // A tolerance above where the cutter is full: the shadows may let material within a quarter
        // of it above the tip touch (a level on a floor meets the fillets that rise from it).
        heights.push_back(z - c.bottomStockMm + c.fullRadiusHeightMm + c.toleranceMm);
    const std::vector<MeshSection> sections = sliceMesh(model, heights);
    const double grow = c.radiusMm - 2 * c.toleranceMm;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (regions[i].empty() || sections[i].loops.empty() || grow <= 0)
            continue;
        const std::vector<geom::Region> near =
            geom::offsetRegions(sectionRegions(sections[i], c.toleranceMm), grow, c.toleranceMm);
        if (geom::totalArea(geom::intersect(regions[i], near, c.toleranceMm)) > c.toleranceMm * c.toleranceMm)
            return i;
    }
    return std::nullopt;
}

}  // namespace camwb::ops::surface
