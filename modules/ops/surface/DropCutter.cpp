#include "ops/surface/DropCutter.h"

#include "ops/surface/CutterProfile.h"
#include "ops/surface/TriangleGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace camwb::ops::surface {

namespace {

using base::Vec2;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct P3 {
    double x, y, z;
};

// The highest tip from the triangle's facet: where the cutter's slope is the plane's, if that
// point lies inside the triangle (else an edge or a vertex gives the contact).
double facetContact(const CutterProfile& profile, Vec2 c, const P3& a, const P3& b, const P3& d)
{
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = d.x - a.x, vy = d.y - a.y, vz = d.z - a.z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double nxy = std::sqrt(nx * nx + ny * ny);
    if (std::abs(nz) <= 1e-12 * std::max(nxy, 1e-300))
        return -kInf;  // vertical: its edges and vertices stand for it
    // z = a.z + gx (x - a.x) + gy (y - a.y) on the plane; it rises along (gx, gy).
    const double gx = -nx / nz, gy = -ny / nz, g = std::sqrt(gx * gx + gy * gy);
    const double r = profile.planeContact(g);
    const double px = c.x + (g > 0 ? gx / g * r : 0), py = c.y + (g > 0 ? gy / g * r : 0);
    // Inside the triangle (in XY)?
    const double det = ux * vy - uy * vx;
    const double s = ((px - a.x) * vy - (py - a.y) * vx) / det, t = (ux * (py - a.y) - uy * (px - a.x)) / det;
    if (s < 0 || t < 0 || s + t > 1)
        return -kInf;
    return a.z + gx * (px - a.x) + gy * (py - a.y) - profile.height(r);
}

double vertexContact(const CutterProfile& profile, Vec2 c, const P3& p)
{
    const double dx = p.x - c.x, dy = p.y - c.y;
    return p.z - profile.height(std::sqrt(dx * dx + dy * dy));  // std::hypot is several times slower
}

// The highest tip from the edge a-b. Along the edge, z(t) - height(|xy(t) - c|) is concave (a
// convex non-decreasing height of a convex distance), so the part of the edge under the cutter
// has a single best point: closed forms for the flat and the sphere, a golden-section search else.
double edgeContact(const CutterProfile& profile, Vec2 c, const P3& a, const P3& b, double best)
{
    if (std::max(a.z, b.z) - profile.lowest() <= best)
        return -kInf;
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const double l2 = dx * dx + dy * dy;
    if (l2 < 1e-18)
        return -kInf;  // vertical: its vertices stand for it
    const double wx = a.x - c.x, wy = a.y - c.y;
    // The t where the edge is under the cutter: |w + t d|^2 <= R^2.
    const double R = profile.radius(), p = wx * dx + wy * dy, q = wx * wx + wy * wy - R * R;
    const double disc = p * p - l2 * q;
    if (disc < 0)
        return -kInf;
    const double root = std::sqrt(disc);
    const double t0 = std::max(0.0, (-p - root) / l2), t1 = std::min(1.0, (-p + root) / l2);
    if (t0 > t1)
        return -kInf;
    if (std::max(a.z + dz * t0, a.z + dz * t1) - profile.lowest() <= best)
        return -kInf;
    auto at = [&](double t) {
        const double ex = wx + dx * t, ey = wy + dy * t;
        const double d = std::min(R, std::sqrt(ex * ex + ey * ey));
        return a.z + dz * t - profile.height(d);
    };
    if (profile.isFlat())
        return std::max(at(t0), at(t1));
    if (profile.isSphere()) {
        // The sphere's centre C lowered until the line's distance to it is its radius:
        // |w'|^2 - (w'.D)^2 / |D|^2 = r^2 with w' = A - C, solved for u = a.z - C.z (the upper root).
        const double r = profile.sphereRadius(), L2 = l2 + dz * dz;
        const double qa = l2 / L2, qb = -2 * p * dz / L2, qc = wx * wx + wy * wy - p * p / L2 - r * r;
        const double qd = qb * qb - 4 * qa * qc;
        if (qd < 0)
            return std::max(at(t0), at(t1));
        const double u = (-qb - std::sqrt(qd)) / (2 * qa);
        const double t = -(p + u * dz) / L2;
        if (t < t0 || t > t1)
            return std::max(at(t0), at(t1));
        return a.z - u - profile.sphereCentre();
    }
    // Golden section to a hundredth of a micrometre along the edge, the ends evaluated too (the
    // best may sit on the rim, where the height's slope is infinite).
    constexpr double kPhi = 0.6180339887498949;
    const double stop = 1e-8 / std::sqrt(l2);
    double lo = t0, hi = t1, x1 = hi - kPhi * (hi - lo), x2 = lo + kPhi * (hi - lo);
    double f1 = at(x1), f2 = at(x2);
    while (hi - lo > stop) {
        if (f1 < f2) {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + kPhi * (hi - lo), f2 = at(x2);
        } else {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - kPhi * (hi - lo), f1 = at(x1);
        }
    }
    return std::max({f1, f2, at(t0), at(t1)});
}

}  // namespace

struct DropCutter::Index {
    CutterProfile profile;
    TriangleGrid grid;
    Index(const sim::TriangleMesh& mesh, const toolpath::Tool& tool, double stockMm) :
        profile(sim::ToolShape(tool), stockMm),
        grid(mesh, profile.radius())
    {
    }

    // The best tip of one triangle, or `best` where it gives nothing higher.
    double triangle(std::uint32_t id, base::Vec2 c, double best) const
    {
        const float* v = grid.vertices(id);
        const P3 a{v[0], v[1], v[2]}, b{v[3], v[4], v[5]}, d{v[6], v[7], v[8]};
        best =
            std::max({best, vertexContact(profile, c, a), vertexContact(profile, c, b), vertexContact(profile, c, d)});
        best = std::max(best, facetContact(profile, c, a, b, d));
        best = std::max(best, edgeContact(profile, c, a, b, best));
        best = std::max(best, edgeContact(profile, c, b, d, best));
        return std::max(best, edgeContact(profile, c, d, a, best));
    }

    double drop(base::Vec2 c, double floorZ) const
    {
        double best = floorZ;
        grid.visit(
            c, profile.radius(), [&](double d) { return profile.height(d); }, best,
            [&](std::uint32_t id) { best = triangle(id, c, best); });
        return best;
    }
};

DropCutter::DropCutter(const sim::TriangleMesh& mesh, const toolpath::Tool& tool, double stockMm) :
    m_index(std::make_unique<Index>(mesh, tool, stockMm))
{
}

DropCutter::~DropCutter() = default;
DropCutter::DropCutter(DropCutter&&) noexcept = default;

double DropCutter::dropZ(base::Vec2 xy, double floorZ) const { return m_index->drop(xy, floorZ); }

std::vector<double> DropCutter::dropZ(const std::vector<base::Vec2>& points, double floorZ, int threads) const
{
    std::vector<double> out(points.size());
    const int cores = std::max(1u, std::thread::hardware_concurrency());
    constexpr std::size_t kChunk = 256;
    const int workers =
        static_cast<int>(std::min<std::size_t>(threads > 0 ? threads : cores, (points.size() + kChunk - 1) / kChunk));
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t from; (from = next.fetch_add(kChunk)) < points.size();)
            for (std::size_t i = from; i < std::min(points.size(), from + kChunk); ++i)
                out[i] = m_index->drop(points[i], floorZ);
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < workers; ++i)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    return out;
}

}  // namespace camwb::ops::surface
