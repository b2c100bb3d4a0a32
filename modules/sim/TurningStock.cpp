#include "sim/TurningStock.h"

#include "geom/Profile.h"
#include "geom/RegionOps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::sim {

namespace {

using Loop = std::vector<Vec2>;

std::vector<Loop> loopsOf(const TurningRegion& regions, double tolerance)
{
    std::vector<Loop> out;
    for (const geom::Region& r : regions) {
        out.push_back(geom::discretize(r.outer, tolerance));
        for (const geom::Profile& h : r.holes)
            out.push_back(geom::discretize(h, tolerance));
    }
    return out;
}

geom::Region polygonRegion(const std::vector<Vec2>& ccw)
{
    geom::Region r;
    for (std::size_t i = 0; i < ccw.size(); ++i)
        r.outer.segments.push_back(geom::Segment::line(ccw[i], ccw[(i + 1) % ccw.size()]));
    return r;
}

// Sorted X of the loops' crossings with the vertical line at `z` (even-odd: pairs are chords).
std::vector<double> crossings(const std::vector<Loop>& loops, double z)
{
    std::vector<double> xs;
    for (const Loop& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
            if ((a.x <= z) != (b.x <= z))
                xs.push_back(a.y + (b.y - a.y) * (z - a.x) / (b.x - a.x));
        }
    std::sort(xs.begin(), xs.end());
    return xs;
}

double highestX(const TurningRegion& regions)
{
    double top = 0;
    for (const geom::Region& r : regions)
        for (const geom::Segment& s : r.outer.segments)
            top = std::max({top, s.start.y, s.end.y, s.isArc() ? s.center.y + s.radius() : 0.0});
    return top;
}

void appendCorner(Loop& out, Vec2 center, double radius, double fromAngle, double tolerance)
{
    const int n = geom::chordCount(radius, std::numbers::pi / 2, tolerance);
    for (int i = 0; i <= n; ++i) {
        const double a = fromAngle + (std::numbers::pi / 2) * i / n;
        out.push_back(center + Vec2{std::cos(a), std::sin(a)} * radius);
    }
}

}  // namespace

std::vector<Vec2> insertOutline(const Insert& insert, Vec2 at, double length, double tolerance)
{
    const double w = insert.widthMm;
    const double r = std::clamp(insert.cornerRadiusMm, 0.0, std::min(w / 2, length));
    Loop out;
    if (r > 0) {
        appendCorner(out, at + Vec2{r, r}, r, std::numbers::pi, tolerance);            // left corner
        appendCorner(out, at + Vec2{w - r, r}, r, 1.5 * std::numbers::pi, tolerance);  // right corner
    } else {
        out.push_back(at);
        out.push_back(at + Vec2{w, 0});
    }
    out.push_back(at + Vec2{w, length});
    out.push_back(at + Vec2{0, length});
    return out;
}

std::vector<Vec2> convexHull(std::vector<Vec2> points)
{
    std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (points.size() < 3)
        return points;
    std::vector<Vec2> hull(2 * points.size());
    std::size_t k = 0;
    const auto turn = [&](Vec2 p) { return (hull[k - 1] - hull[k - 2]).cross(p - hull[k - 2]); };
    for (const Vec2 p : points) {  // lower hull
        while (k >= 2 && turn(p) <= 0)
            --k;
        hull[k++] = p;
    }
    const std::size_t lower = k + 1;
    for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper hull
        while (k >= lower && turn(points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);  // the last point is the first again
    return hull;
}

double radialDepth(const TurningRegion& cut, const TurningRegion& material, double tolerance, Vec2& at)
{
    const std::vector<Loop> cutLoops = loopsOf(cut, tolerance);
    const std::vector<Loop> materialLoops = loopsOf(material, tolerance);
    // Only the Z range of `cut` matters; the stock's other vertices would only cost time.
    double low = 1e300, high = -1e300;
    for (const Loop& loop : cutLoops)
        for (const Vec2 p : loop) {
            low = std::min(low, p.x);
            high = std::max(high, p.x);
        }
    std::vector<double> zs;
    for (const auto* loops : {&cutLoops, &materialLoops})
        for (const Loop& loop : *loops)
            for (const Vec2 p : loop)
                if (p.x >= low && p.x <= high)
                    zs.push_back(p.x);
    std::sort(zs.begin(), zs.end());
    zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
    double deepest = 0;
    const double nudge = 1e-7;  // far below any tolerance: the limits either side of a vertex
    for (const double vertexZ : zs)
        for (const double z : {vertexZ - nudge, vertexZ + nudge}) {
            const std::vector<double> c = crossings(cutLoops, z);
            if (c.size() < 2)
                continue;
            const std::vector<double> m = crossings(materialLoops, z);
            for (std::size_t i = 0; i + 1 < c.size(); i += 2)
                for (std::size_t j = 0; j + 1 < m.size(); j += 2)
                    if (c[i] >= m[j] - tolerance && c[i] <= m[j + 1] + tolerance && m[j + 1] - c[i] > deepest) {
                        deepest = m[j + 1] - c[i];
                        at = {z, c[i]};
                    }
        }
    return deepest;
}

TurningStock::TurningStock(TurningRegion stock, TurningRegion design, double toleranceMm) :
    m_stock(std::move(stock)),
    m_design(std::move(design)),
    m_tolerance(toleranceMm),
    m_top(std::max(highestX(m_stock), highestX(m_design)))
{
}

TurningCut TurningStock::cut(Vec2 from, Vec2 to, const Insert& insert)
{
    // A strip insert reaches above everything there is, wherever the move starts.
    const double length = insert.lengthMm > 0 ? insert.lengthMm : m_top - std::min(from.y, to.y) + 1;
    std::vector<Vec2> points = insertOutline(insert, from, length, m_tolerance);
    const std::vector<Vec2> end = insertOutline(insert, to, length, m_tolerance);
    points.insert(points.end(), end.begin(), end.end());
    const TurningRegion swept{polygonRegion(convexHull(std::move(points)))};

    TurningCut result;
    const TurningRegion removed = geom::intersect(m_stock, swept, m_tolerance);
    result.removedMm2 = geom::totalArea(removed);
    if (removed.empty())
        return result;
    result.depthMm = radialDepth(removed, m_stock, m_tolerance, result.depthAt);
    m_stock = geom::subtract(m_stock, swept, m_tolerance);
    // A gouge is part material this move removed: a later move through the gouged gap cuts
    // nothing and is not reported again (the block that did the damage is the one to fix).
    if (!m_design.empty()) {
        const TurningRegion gouge = geom::intersect(removed, m_design, m_tolerance);
        if (!gouge.empty())
            result.gougeMm = radialDepth(gouge, m_design, m_tolerance, result.gougeAt);
    }
    return result;
}

}  // namespace camwb::sim
