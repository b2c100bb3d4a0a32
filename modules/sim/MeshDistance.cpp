#include "sim/MeshDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::sim {

using base::Vec3;

// By the region of the triangle's plane the projection of p falls in (its three vertex regions,
// three edge regions, or the face), from the barycentric signs.
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + ab * (d1 / (d1 - d3));
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

namespace {

double comp(const Vec3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }

}  // namespace

MeshDistance::MeshDistance(const TriangleMesh& mesh)
{
    if (mesh.empty())
        return;
    m_triangles.reserve(mesh.triangleCount());
    double edges = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Triangle tri{mesh.vertex(mesh.triangles[3 * t]), mesh.vertex(mesh.triangles[3 * t + 1]),
                           mesh.vertex(mesh.triangles[3 * t + 2])};
        m_triangles.push_back(tri);
        edges += (tri.b - tri.a).length() + (tri.c - tri.b).length() + (tri.a - tri.c).length();
    }
    // Cells about twice a typical edge: a triangle overlaps a few cells, a cell holds a few triangles.
    const base::Box3 box = mesh.bounds();
    const double extent = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z, 1e-6});
    m_cell = std::max({2 * edges / (3.0 * m_triangles.size()), extent / 256, 1e-6});
    m_origin = box.min;
    for (int k = 0; k < 3; ++k)
        m_n[k] = std::max(1, int(std::ceil((comp(box.max, k) - comp(box.min, k)) / m_cell)));
    const auto cellOf = [&](const Vec3& p, int k) {
        return std::clamp(int(std::floor((comp(p, k) - comp(m_origin, k)) / m_cell)), 0, m_n[k] - 1);
    };
    const std::size_t cells = std::size_t(m_n[0]) * m_n[1] * m_n[2];
    m_start.assign(cells + 1, 0);
    // Two passes over the triangles' cell ranges: count per cell, then fill.
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> fill;
        if (pass == 1) {
            for (std::size_t c = 0; c < cells; ++c)
                m_start[c + 1] += m_start[c];
            m_items.resize(m_start[cells]);
            fill.assign(m_start.begin(), m_start.end() - 1);
        }
        for (std::uint32_t t = 0; t < m_triangles.size(); ++t) {
            const Triangle& tri = m_triangles[t];
            base::Box3 reach;
            for (const Vec3& corner : {tri.a, tri.b, tri.c})
                reach.add(corner);
            int lo[3], hi[3];
            for (int k = 0; k < 3; ++k)
                lo[k] = cellOf(reach.min, k), hi[k] = cellOf(reach.max, k);
            for (int z = lo[2]; z <= hi[2]; ++z)
                for (int y = lo[1]; y <= hi[1]; ++y)
                    for (int x = lo[0]; x <= hi[0]; ++x) {
                        const std::size_t c = (std::size_t(z) * m_n[1] + y) * m_n[0] + x;
                        if (pass == 0)
                            ++m_start[c + 1];
                        else
                            m_items[fill[c]++] = t;
                    }
        }
    }
}

double MeshDistance::distance(const Vec3& p, double within) const
{
    // Boxes of growing radius around p: a triangle nearer than the radius lies in the cells the
    // box covers, so the first radius that finds one under it has found the nearest. A deep
    // point far from every surface costs a few doublings, not the whole grid at once.
    for (double radius = std::min(m_cell, within);; radius = std::min(2 * radius, within)) {
        const double found = nearestWithin(p, radius);
        if (found <= radius || radius >= within)
            return std::min(found, within);
    }
}

double MeshDistance::nearestWithin(const Vec3& p, double radius) const
{
    const double none = std::numeric_limits<double>::infinity();
    if (m_triangles.empty())
        return none;
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        const double rel = (comp(p, k) - comp(m_origin, k)) / m_cell;
        lo[k] = std::max(0, int(std::floor(rel - radius / m_cell)));
        hi[k] = std::min(m_n[k] - 1, int(std::floor(rel + radius / m_cell)));
        if (lo[k] > hi[k])
            return none;  // the search box misses the mesh's box
    }
    // A triangle spanning several cells is met once per cell: measuring it again is cheaper than
    // remembering it, at the few cells a search within a fraction of a millimetre visits.
    double best = none;
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) {
                const std::size_t c = (std::size_t(z) * m_n[1] + y) * m_n[0] + x;
                for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k) {
                    const Triangle& t = m_triangles[m_items[k]];
                    const Vec3 d = p - closestOnTriangle(p, t.a, t.b, t.c);
                    best = std::min(best, d.dot(d));
                }
            }
    return std::sqrt(best);
}

}  // namespace camwb::sim
