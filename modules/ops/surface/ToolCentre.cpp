// The obstacle at a level, tip at z (zt = z - bottom stock): material above zt + H (H: the height
// where the tool reaches its full radius; 0 for a flat end mill) grown by the full radius, and
// the material within [zt, zt + H] in thin bands, each grown by the tool's radius at the band's
// top (never less than at any point of the band, so never a gouge). The error is on the safe
// side: the tool may stand up to one band (max(tolerance, H / 40): 0.075 mm for a 6 mm ball) off
// the model along the contact normal (each band costs
// an offset and a union per level: 40 bounds the time). A ball needs no bands: each triangle's
// piece within [zt, zt + R] grown by the sphere itself is one convex polygon (BallReach.h), exact
// to the chord whatever the band setting. Every offset is grown by the fit and chord errors so
// that the regions handed back stay clear.
#include "ops/surface/ToolCentre.h"

#include "ops/surface/BallReach.h"
#include "ops/surface/MeshShadow.h"
#include "sim/ToolShape.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops::surface {

struct ToolCentreRegions::Data {
    Data(const sim::TriangleMesh& model, const toolpath::Tool& tool, const ToolCentreSettings& s) :
        shadow(model),
        shape(tool),
        settings(s)
    {
    }
    MeshShadow shadow;
    sim::ToolShape shape;
    ToolCentreSettings settings;
    double radius = 0, fullHeight = 0, band = 0;

    double tol() const { return std::max(settings.toleranceMm, 1e-4); }
    // A ball end mill: its cutter is a sphere, so the material under its equator is taken exactly,
    // triangle by triangle (ballReach), instead of in bands.
    bool exactBall() const
    {
        return fullHeight > 0 && shape.coneSlope() == 0 && shape.cornerRadiusMm() >= radius - 1e-9;
    }
    // The tool's radius at height dz (>= 0) above its tip.
    double reach(double dz) const { return dz >= fullHeight ? radius : std::min(radius, shape.profileRadius(dz)); }
    ClipperLib::Paths obstacle(double z) const;
    // The band's height from dz: material in it stands at most `band` off the tool along the
    // normal where the cutter would touch it (a vertical lift t moves the cutter t cos(a) off a
    // contact whose normal is a from the axis, and the cutter's slope there is tan(a) = dz/dr), so
    // bands thicken as the cutter steepens towards its full radius (at most 20 times).
    double bandAt(double dz) const
    {
        const double h = 1e-3, slope = (reach(dz + h) - reach(dz)) / h;  // dr/dz
        const double cosA = slope / std::sqrt(slope * slope + 1);
        return band / std::max(cosA, 0.05);
    }
};

ToolCentreRegions::ToolCentreRegions(const sim::TriangleMesh& model, const toolpath::Tool& tool,
                                     const ToolCentreSettings& settings) :
    m_data(std::make_unique<Data>(model, tool, settings))
{
    Data& d = *m_data;
    d.radius = d.shape.radiusMm();
    if (!d.shape.flatBottomed()) {
        // The lowest height where the cutter is at its full radius (ball: R, bull-nose: its corner).
        double lo = 0, hi = std::max(d.shape.fluteLengthMm(), d.radius);
        for (int i = 0; i < 60; ++i) {
            const double mid = (lo + hi) / 2;
            (d.shape.profileRadius(mid) >= d.radius - 1e-9 ? hi : lo) = mid;
        }
        d.fullHeight = hi;
    }
    d.band = std::max(d.tol(), d.fullHeight / 40);
}

ToolCentreRegions::~ToolCentreRegions() = default;

ClipperLib::Paths ToolCentreRegions::Data::obstacle(double z) const
{
    // Material closer above the tip than a quarter tolerance does not count: a flat floor exactly at
    // the tip's level (floats of a tessellation) is touched, not cut.
    const double tip = z - settings.bottomStockMm;
    const double ignore = tol() / 4, chord = tol() / 4, fit = tol() / 2;
    const double grow = settings.sideStockMm + fit;
    std::vector<ClipperLib::Paths> parts{
        growPaths(shadow.above(tip + std::max(fullHeight, ignore)), radius + grow, chord)};
    if (exactBall()) {
        // The ball with its tip lowered by the bottom stock and grown by the side stock, as the
        // bands grow it: one polygon per piece of the material under its equator, exact to the chord.
        ClipperLib::Paths group;
        shadow.pieces(tip + ignore, tip + fullHeight, [&](const std::vector<base::Vec3>& piece) {
            ClipperLib::Path path;
            for (const base::Vec2& p : ballReach(piece, tip + radius, radius, grow, chord))
                path.push_back(toClipper(p));
            if (path.size() < 3)
                return;
            group.push_back(std::move(path));
            // United in groups of 64 in the mesh's order, then in pairs below. The order decides
            // Clipper's rounding of crossings (nanometres), and the contours' fit follows it:
            // uniteNear's groups of near neighbours are quicker on large models (1M triangles:
            // half the time) but move the fitted points within the tolerance and the ends of
            // steep runs where a wall is at the slope limit, so the goldens would change.
            if (group.size() == 64)
                parts.push_back(unitePaths(group)), group.clear();
        });
        if (!group.empty())
            parts.push_back(unitePaths(group));
    } else {
        for (double lo = tip, hi = tip; lo < tip + fullHeight; lo = hi) {
            hi = std::min(lo + bandAt(lo - tip), tip + fullHeight);
            ClipperLib::Paths pieces = shadow.band(std::max(lo, tip + ignore), hi);
            if (pieces.empty())
                continue;
            parts.push_back(growPaths(pieces, reach(hi - tip) + grow, chord));
        }
    }
    // United in pairs: the bands' grown rings overlap their neighbours almost wholly, and one
    // union of them all would cross every ring with every other.
    return uniteInPairs(std::move(parts));
}

std::vector<geom::Region> ToolCentreRegions::at(double z, const std::vector<geom::Region>& area) const
{
    const double tol = m_data->tol();
    return toRegions(clipPaths(toPaths(area, tol / 4), m_data->obstacle(z), ClipperLib::ctDifference), tol / 2);
}

std::vector<geom::Region> ToolCentreRegions::obstacle(double z) const
{
    return toRegions(m_data->obstacle(z), m_data->tol() / 2);
}

double ToolCentreRegions::fullRadiusHeightMm() const { return m_data->fullHeight; }

std::vector<geom::Region> toolCentreArea(const SurfaceInput& in)
{
    if (!in.boundary.empty())
        return in.boundary;
    const base::Vec2 a{in.stock.min.x, in.stock.min.y}, b{in.stock.max.x, in.stock.min.y};
    const base::Vec2 c{in.stock.max.x, in.stock.max.y}, d{in.stock.min.x, in.stock.max.y};
    geom::Region box;
    box.outer.segments = {geom::Segment::line(a, b), geom::Segment::line(b, c), geom::Segment::line(c, d),
                          geom::Segment::line(d, a)};
    return {box};
}

base::Status checkSurfaceInput(const std::string& what, const SurfaceInput& in, const std::string& verb)
{
    if (!in.model || in.model->empty())
        return opError(what, "no model to " + verb + " (the part's mesh is empty)");
    const bool box = !in.stock.empty && in.stock.max.x > in.stock.min.x && in.stock.max.y > in.stock.min.y;
    if (in.boundary.empty() && !box)
        return opError(what, "no boundary and no stock box: nowhere to " + verb);
    return base::Status::success();
}

}  // namespace camwb::ops::surface
