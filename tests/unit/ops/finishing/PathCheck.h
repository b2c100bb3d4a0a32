// What the parallel finishing tests measure on a computed toolpath, independently of the
// drop-cutter: the feed moves, how deep the tool's lower surface (sim::ToolShape's, grown by the
// stock) reaches into a dense point cloud of the model anywhere along them, and how far a point
// lies from the nearest cut.
#pragma once

#include "TestMeshes.h"
#include "toolpath/Toolpath.h"

#include <variant>
#include <vector>

namespace camwb::ops::test {

struct Segment {
    base::Vec3 a, b;
};

// The feed moves (Linear) of the toolpath, from where the tool was.
inline std::vector<Segment> feedMoves(const toolpath::Toolpath& path)
{
    std::vector<Segment> out;
    base::Vec3 at{};
    bool known = false;
    for (const toolpath::Record& r : path.records()) {
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            at = rapid->to, known = true;
        } else if (const auto* line = std::get_if<toolpath::Linear>(&r)) {
            if (known)
                out.push_back({at, line->to});
            at = line->to, known = true;
        }
    }
    return out;
}

// The model as points on its triangles about `spacing` apart, in a bucket grid.
class PointCloud {
public:
    PointCloud(const sim::TriangleMesh& mesh, double spacing, double cell) : m_cell(cell)
    {
        const base::Box3 box = mesh.bounds();
        m_x0 = box.min.x, m_y0 = box.min.y;
        m_nx = int((box.max.x - m_x0) / cell) + 1, m_ny = int((box.max.y - m_y0) / cell) + 1;
        m_cells.resize(std::size_t(m_nx) * m_ny);
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const base::Vec3 a = mesh.vertex(mesh.triangles[3 * t]), b = mesh.vertex(mesh.triangles[3 * t + 1]),
                             c = mesh.vertex(mesh.triangles[3 * t + 2]);
            const int n =
                std::max(1, int(std::ceil(std::max({distance(a, b), distance(b, c), distance(c, a)}) / spacing)));
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n - i; ++j)
                    add(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n));
        }
    }
    // How far the tool's lower surface `h` (radius `radius`) with its tip at p reaches below the
    // highest point under it (> 0: into the model).
    template <class H> double penetration(const base::Vec3& p, const H& h, double radius) const
    {
        double worst = -std::numeric_limits<double>::infinity();
        const int i0 = std::max(0, int((p.x - radius - m_x0) / m_cell)),
                  i1 = std::min(m_nx - 1, int((p.x + radius - m_x0) / m_cell));
        const int j0 = std::max(0, int((p.y - radius - m_y0) / m_cell)),
                  j1 = std::min(m_ny - 1, int((p.y + radius - m_y0) / m_cell));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
                for (const base::Vec3& q : m_cells[std::size_t(j) * m_nx + i]) {
                    const double d = std::hypot(q.x - p.x, q.y - p.y);
                    if (d <= radius)
                        worst = std::max(worst, q.z - (p.z + h(d)));
                }
        return worst;
    }

private:
    void add(const base::Vec3& p)
    {
        const int i = std::clamp(int((p.x - m_x0) / m_cell), 0, m_nx - 1),
                  j = std::clamp(int((p.y - m_y0) / m_cell), 0, m_ny - 1);
        m_cells[std::size_t(j) * m_nx + i].push_back(p);
    }
    double m_cell, m_x0 = 0, m_y0 = 0;
    int m_nx = 1, m_ny = 1;
    std::vector<std::vector<base::Vec3>> m_cells;
};

inline double distanceToSegmentXY(base::Vec2 p, const Segment& s)
{
    const base::Vec2 a{s.a.x, s.a.y}, b{s.b.x, s.b.y}, ab = b - a;
    const double l2 = ab.dot(ab);
    const double f = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (p - (a + ab * f)).length();
}

}  // namespace camwb::ops::test
