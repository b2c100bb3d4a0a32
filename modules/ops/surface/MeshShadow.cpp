#include "ops/surface/MeshShadow.h"

#include "geom/ArcFit.h"
#include "geom/ClipperAdapter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

namespace camwb::ops::surface {

namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The part of a polygon on the side z >= level (keepAbove) or z <= level of a horizontal plane.
std::vector<base::Vec3> clipZ(const std::vector<base::Vec3>& poly, double level, bool keepAbove)
{
    std::vector<base::Vec3> out;
    const auto inside = [&](const base::Vec3& p) { return keepAbove ? p.z >= level : p.z <= level; };
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const base::Vec3& a = poly[i];
        const base::Vec3& b = poly[(i + 1) % poly.size()];
        if (inside(a))
            out.push_back(a);
        if (inside(a) != inside(b)) {
            const double t = (level - a.z) / (b.z - a.z);
            out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), level});
        }
    }
    return out;
}

// Interleaves the low 16 bits of x and y (a Morton code: near codes, near cells).
std::uint32_t morton(std::uint32_t x, std::uint32_t y)
{
    const auto spread = [](std::uint32_t v) {
        v &= 0xffff;
        v = (v | (v << 8)) & 0x00ff00ff;
        v = (v | (v << 4)) & 0x0f0f0f0f;
        v = (v | (v << 2)) & 0x33333333;
        return (v | (v << 1)) & 0x55555555;
    };
    return spread(x) | (spread(y) << 1);
}

}  // namespace

IntPoint toClipper(base::Vec2 p)
{
    return {cInt(std::llround(p.x * geom::kClipperScale)), cInt(std::llround(p.y * geom::kClipperScale))};
}

MeshShadow::MeshShadow(const sim::TriangleMesh& model)
{
    m_top = -kInf;
    m_bottom = kInf;
    for (std::size_t t = 0; t < model.triangleCount(); ++t) {
        const Tri tri{model.vertex(model.triangles[3 * t]), model.vertex(model.triangles[3 * t + 1]),
                      model.vertex(model.triangles[3 * t + 2])};
        const double nz = (tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[1].y - tri[0].y) * (tri[2].x - tri[0].x);
        if (!(nz > 1e-12))  // vertical or facing down: not where material ends upwards
            continue;
        m_tris.push_back(tri);
        for (const base::Vec3& v : tri)
            m_top = std::max(m_top, v.z), m_bottom = std::min(m_bottom, v.z);
    }
    if (m_tris.empty()) {
        m_top = m_bottom = 0;
        return;
    }
    // Slabs of about half a millimetre, at most 256: the cumulative shadows are built once.
    const int count = std::clamp(int(std::ceil((m_top - m_bottom) / 0.5)), 1, 256);
    m_slab = std::max((m_top - m_bottom) / count, 1e-9);
    m_slabs.resize(count);
    for (std::size_t t = 0; t < m_tris.size(); ++t) {
        double lo = kInf, hi = -kInf;
        for (const base::Vec3& v : m_tris[t])
            lo = std::min(lo, v.z), hi = std::max(hi, v.z);
        for (int j = slabOf(hi); j <= slabOf(lo); ++j)
            m_slabs[j].push_back(int(t));
    }
    Paths shadow;
    for (int j = 0; j < count; ++j) {
        shadow = unitePaths(shadow, uniteNear(band(m_top - (j + 1) * m_slab, j == 0 ? kInf : m_top - j * m_slab)));
        m_shadows.push_back(shadow);
    }
}

int MeshShadow::slabOf(double z) const
{
    const int j = int(std::floor((m_top - z) / m_slab));
    return std::clamp(j, 0, int(m_slabs.size()) - 1);
}

void MeshShadow::pieces(double lo, double hi, const std::function<void(const std::vector<base::Vec3>&)>& piece) const
{
    if (m_tris.empty() || lo > hi)
        return;
    std::vector<int> ids;
    for (int j = slabOf(std::min(hi, m_top)); j <= slabOf(std::max(lo, m_bottom)); ++j)
        ids.insert(ids.end(), m_slabs[j].begin(), m_slabs[j].end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (int id : ids) {
        const Tri& tri = m_tris[id];
        std::vector<base::Vec3> poly(tri.begin(), tri.end());
        if (std::isfinite(lo))
            poly = clipZ(poly, lo, true);
        if (std::isfinite(hi) && poly.size() >= 3)
            poly = clipZ(poly, hi, false);
        if (poly.size() >= 3)
            piece(poly);
    }
}

Paths MeshShadow::band(double lo, double hi) const
{
    Paths out;
    pieces(lo, hi, [&](const std::vector<base::Vec3>& poly) {
        Path path;
        for (const base::Vec3& p : poly)
            path.push_back(toClipper({p.x, p.y}));
        if (std::abs(ClipperLib::Area(path)) < 1)  // below 1 nm^2: a sliver of an edge
            return;
        if (!ClipperLib::Orientation(path))
            ClipperLib::ReversePath(path);
        out.push_back(std::move(path));
    });
    return out;
}

Paths MeshShadow::above(double h) const
{
    if (m_tris.empty() || h > m_top)
        return {};
    if (h <= m_bottom)
        return m_shadows.back();
    const int j = slabOf(h);
    const Paths rest = uniteNear(band(h, j == 0 ? kInf : m_top - j * m_slab));
    return j == 0 ? rest : unitePaths(m_shadows[j - 1], rest);
}

Paths toPaths(const std::vector<geom::Region>& regions, double chord)
{
    Paths out;
    const auto add = [&](const geom::Profile& loop) {
        Path path;
        for (const base::Vec2& p : geom::discretize(loop, chord))
            path.push_back(toClipper(p));
        if (path.size() >= 3)
            out.push_back(std::move(path));
    };
    for (const geom::Region& region : regions) {
        const geom::Region r = region.normalized();
        add(r.outer);
        for (const geom::Profile& hole : r.holes)
            add(hole);
    }
    return out;
}

namespace {

geom::Profile fitted(const Path& contour, double fit)
{
    std::vector<base::Vec2> points;
    for (const IntPoint& p : contour)
        points.push_back({double(p.X) / geom::kClipperScale, double(p.Y) / geom::kClipperScale});
    return geom::fitLinesAndArcs(points, true, fit);
}

void collect(const ClipperLib::PolyNode& outer, double fit, std::vector<geom::Region>& out)
{
    // Specks below fit^2 are dropped: the fit alone moves loops by that much.
    if (std::abs(ClipperLib::Area(outer.Contour)) >= fit * fit * geom::kClipperScale * geom::kClipperScale) {
        geom::Region region;
        region.outer = fitted(outer.Contour, fit);
        for (const ClipperLib::PolyNode* hole : outer.Childs)
            region.holes.push_back(fitted(hole->Contour, fit));
        out.push_back(region.normalized());
    }
    for (const ClipperLib::PolyNode* hole : outer.Childs)
        for (const ClipperLib::PolyNode* inner : hole->Childs)
            collect(*inner, fit, out);
}

}  // namespace

std::vector<geom::Region> toRegions(const Paths& paths, double fit)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    std::vector<geom::Region> out;
    for (const ClipperLib::PolyNode* outer : tree.Childs)
        collect(*outer, fit, out);
    return out;
}

Paths unitePaths(const Paths& a, const Paths& b)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptSubject, true);
    Paths out;
    clipper.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

Paths uniteNear(Paths paths)
{
    constexpr std::size_t kGroup = 8;
    if (paths.size() <= kGroup)
        return unitePaths(paths);
    // Sorted along a Morton curve of their boxes' centres, on a grid of 2^16 over their span.
    std::vector<IntPoint> centres;
    IntPoint lo{std::numeric_limits<cInt>::max(), std::numeric_limits<cInt>::max()}, hi{-lo.X, -lo.Y};
    for (const Path& path : paths) {
        IntPoint a = path.empty() ? IntPoint{} : path.front(), b = a;
        for (const IntPoint& p : path)
            a = {std::min(a.X, p.X), std::min(a.Y, p.Y)}, b = {std::max(b.X, p.X), std::max(b.Y, p.Y)};
        centres.push_back({a.X / 2 + b.X / 2, a.Y / 2 + b.Y / 2});
        lo = {std::min(lo.X, centres.back().X), std::min(lo.Y, centres.back().Y)};
        hi = {std::max(hi.X, centres.back().X), std::max(hi.Y, centres.back().Y)};
    }
    const double span = double(std::max<cInt>({hi.X - lo.X, hi.Y - lo.Y, 1}));
    std::vector<std::pair<std::uint32_t, std::size_t>> keys;
    for (std::size_t i = 0; i < centres.size(); ++i)
        keys.emplace_back(morton(std::uint32_t(double(centres[i].X - lo.X) / span * 65535),
                                 std::uint32_t(double(centres[i].Y - lo.Y) / span * 65535)),
                          i);
    std::sort(keys.begin(), keys.end());
    std::vector<Paths> groups;
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (k % kGroup == 0)
            groups.emplace_back();
        groups.back().push_back(std::move(paths[keys[k].second]));
    }
    for (Paths& group : groups)
        group = unitePaths(group);
    return uniteInPairs(std::move(groups));
}

Paths uniteInPairs(std::vector<Paths> parts)
{
    if (parts.empty())
        return {};
    while (parts.size() > 1) {
        std::vector<Paths> merged;
        for (std::size_t i = 0; i + 1 < parts.size(); i += 2)
            merged.push_back(unitePaths(parts[i], parts[i + 1]));
        if (parts.size() % 2)
            merged.push_back(std::move(parts.back()));
        parts = std::move(merged);
    }
    return unitePaths(parts.front());
}

Paths clipPaths(const Paths& a, const Paths& b, ClipperLib::ClipType type)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptClip, true);
    Paths out;
    clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

Paths growPaths(const Paths& paths, double delta, double chord)
{
    if (paths.empty())
        return {};
    if (!(delta > 0))
        return unitePaths(paths);
    // Clipper's round joins are inscribed, their chords up to 2.25 ArcTolerance inside the circle
    // (it rounds the step count): growing by delta + chord with ArcTolerance chord / 2.25 keeps
    // every chord outside the exact offset.
    // United first: offsetting many small overlapping pieces one by one costs far more than
    // offsetting their outline.
    ClipperLib::ClipperOffset offset;
    offset.ArcTolerance = std::max(chord / 2.25 * geom::kClipperScale, 0.25);
    offset.AddPaths(unitePaths(paths), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths out;
    offset.Execute(out, (delta + chord) * geom::kClipperScale);
    return out;
}

}  // namespace camwb::ops::surface
