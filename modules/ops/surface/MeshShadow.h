// The model's material seen from above, by height: the upward-facing triangles of a closed mesh
// sorted into height slabs, so that the XY projection of everything above a height (the shadow)
// and of a horizontal slice band are quick to get. Every vertical line through the solid above h
// leaves it through an upward triangle above h, so the union of those triangles' parts above h,
// projected, is exactly the material's projection above h. Clipper integer paths (1 nm units).
#pragma once

#include "geom/Region.h"
#include "sim/TriangleMesh.h"

#include <polyclipping/clipper.hpp>

#include <array>
#include <functional>
#include <vector>

namespace camwb::ops::surface {

class MeshShadow {
public:
    explicit MeshShadow(const sim::TriangleMesh& model);

    // Projection of the upward triangles' parts with lo <= z <= hi (lo may be -inf, hi +inf), as
    // positive (counter-clockwise) polygons, not united.
    ClipperLib::Paths band(double lo, double hi) const;
    // The same parts in 3D: each upward triangle clipped to lo <= z <= hi (a convex polygon), all
    // kept however small their projection (a steep wall's piece is tall, not wide).
    void pieces(double lo, double hi, const std::function<void(const std::vector<base::Vec3>&)>& piece) const;
    // The united projection of all material at or above h.
    ClipperLib::Paths above(double h) const;
    double top() const { return m_top; }
    double bottom() const { return m_bottom; }

private:
    using Tri = std::array<base::Vec3, 3>;
    int slabOf(double z) const;                // slab index (0: the highest), clamped
    std::vector<Tri> m_tris;                   // upward-facing
    std::vector<std::vector<int>> m_slabs;     // triangles overlapping each slab
    std::vector<ClipperLib::Paths> m_shadows;  // m_shadows[j]: united projection above slab j's bottom
    double m_top = 0, m_bottom = 0, m_slab = 1;
};

// A point on Clipper's integer grid (geom::kClipperScale).
ClipperLib::IntPoint toClipper(base::Vec2 p);
// Regions <-> Clipper paths: loops discretised with chord error `chord` (outer loops counter-
// clockwise, holes clockwise); a PolyTree's contours fitted back to lines and arcs within `fit`.
ClipperLib::Paths toPaths(const std::vector<geom::Region>& regions, double chord);
std::vector<geom::Region> toRegions(const ClipperLib::Paths& paths, double fit);
ClipperLib::Paths unitePaths(const ClipperLib::Paths& a, const ClipperLib::Paths& b = {});
// The union of many small polygons, quicker than one call: Clipper's sweep costs about its
// vertices times the edges a scan line meets (and its joins of shared edges about their count
// times the outline), so the polygons are united in groups of near neighbours (along a Morton
// curve of their boxes' centres), whose outlines are then united in pairs, neighbour with
// neighbour. The same set as unitePaths(paths).
ClipperLib::Paths uniteNear(ClipperLib::Paths paths);
// Several sets united in pairs (the first with the second, ...), then the results likewise.
ClipperLib::Paths uniteInPairs(std::vector<ClipperLib::Paths> parts);
ClipperLib::Paths clipPaths(const ClipperLib::Paths& a, const ClipperLib::Paths& b, ClipperLib::ClipType type);
// Grows positive polygons by `delta` mm with round joins whose chords lie outside the true offset
// (so the result contains the exact offset), united.
ClipperLib::Paths growPaths(const ClipperLib::Paths& paths, double delta, double chord);

}  // namespace camwb::ops::surface
