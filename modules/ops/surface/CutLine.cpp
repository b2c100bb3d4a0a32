#include "ops/surface/CutLine.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops::surface {

namespace {

using base::Vec2;
using base::Vec3;

double xyDistance(const Vec3& a, const Vec3& b) { return std::hypot(b.x - a.x, b.y - a.y); }

Vec3 dropped(const DropCutter& cutter, const Vec3& a, const Vec3& b, double f)
{
    const Vec2 p{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f};
    return {p.x, p.y, cutter.dropZ(p)};
}

// Adds the points after a up to and including b, bisecting while the straight move would dip more
// than `allowed` below the surface at its quarter points; below `shortest` a jump is climbed or
// descended vertically, the short level move at the top of the samples there.
void refine(const DropCutter& cutter, const Vec3& a, const Vec3& b, double allowed, double shortest,
            std::vector<Vec3>& out)
{
    const Vec3 q[3] = {dropped(cutter, a, b, 0.25), dropped(cutter, a, b, 0.5), dropped(cutter, a, b, 0.75)};
    bool ok = true;
    double top = std::max(a.z, b.z);
    for (int i = 0; i < 3; ++i) {
        ok = ok && q[i].z <= a.z + (b.z - a.z) * 0.25 * (i + 1) + allowed;
        top = std::max(top, q[i].z);
    }
    if (ok) {
        out.push_back(b);
        return;
    }
    if (xyDistance(a, b) > shortest) {
        refine(cutter, a, q[1], allowed, shortest, out);
        refine(cutter, q[1], b, allowed, shortest, out);
        return;
    }
    if (a.z < top)
        out.push_back({a.x, a.y, top});
    out.push_back({b.x, b.y, top});
    if (b.z < top)
        out.push_back(b);
}

}  // namespace

std::vector<Vec3> refineCut(const DropCutter& cutter, const std::vector<Vec3>& points, double toleranceMm)
{
    std::vector<Vec3> out;
    if (points.empty())
        return out;
    out.push_back(points.front());
    const double shortest = std::min(1e-3, toleranceMm / 10);
    for (std::size_t i = 1; i < points.size(); ++i)
        refine(cutter, points[i - 1], points[i], toleranceMm / 4, shortest, out);
    return out;
}

std::vector<Vec3> thinCut(const std::vector<Vec3>& points, double toleranceMm)
{
    if (points.size() < 3)
        return points;
    // Distance along the line from the first point (the XY line is straight).
    std::vector<double> t(points.size(), 0);
    for (std::size_t i = 1; i < points.size(); ++i)
        t[i] = t[i - 1] + xyDistance(points[i - 1], points[i]);
    std::vector<Vec3> out{points.front()};
    std::size_t anchor = 0;
    while (anchor + 1 < points.size()) {
        // The slopes from the anchor that keep the chord within [z_k, z_k + tol] at every k passed.
        double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
        std::size_t end = anchor + 1;
        for (std::size_t k = anchor + 1; k < points.size(); ++k) {
            const double dt = t[k] - t[anchor];
            if (dt < 1e-12)
                break;  // a vertical step: kept as it is
            const double slope = (points[k].z - points[anchor].z) / dt;
            if (slope < lo - 1e-12 || slope > hi + 1e-12)
                break;
            end = k;
            lo = std::max(lo, slope);
            hi = std::min(hi, (points[k].z + toleranceMm - points[anchor].z) / dt);
            if (lo > hi)
                break;
        }
        out.push_back(points[end]);
        anchor = end;
    }
    return out;
}

}  // namespace camwb::ops::surface
