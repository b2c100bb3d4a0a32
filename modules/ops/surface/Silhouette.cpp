#include "ops/surface/Silhouette.h"

#include "geom/ArcFit.h"
#include "geom/ClipperAdapter.h"
#include "geom/RegionOps.h"

#include <cmath>

namespace camwb::ops::surface {

std::vector<geom::Region> silhouette(const sim::TriangleMesh& mesh, double toleranceMm)
{
    std::vector<std::vector<base::Vec2>> pieces;
    pieces.reserve(mesh.triangleCount());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        std::vector<base::Vec2> piece;
        for (int k = 0; k < 3; ++k) {
            const base::Vec3 v = mesh.vertex(mesh.triangles[3 * t + k]);
            piece.push_back({v.x, v.y});
        }
        if (std::abs(geom::polygonArea(piece)) > 1e-12)
            pieces.push_back(std::move(piece));
    }
    std::vector<geom::Profile> loops;
    for (const std::vector<base::Vec2>& polygon : geom::clipperUnion(pieces))
        loops.push_back(geom::fitLinesAndArcs(polygon, true, toleranceMm / 2));
    return geom::regionsFromLoops(loops, toleranceMm);
}

}  // namespace camwb::ops::surface
