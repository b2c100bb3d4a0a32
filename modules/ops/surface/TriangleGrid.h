// The drop-cutter's index: a uniform grid of square cells in XY, each listing the triangles whose
// XY box meets it, highest first, with the box and the top of what it lists, so that a query
// visits cells and triangles in falling order of the best tip they could give and stops early.
#pragma once

#include "base/Vec.h"
#include "sim/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace camwb::ops::surface {

class TriangleGrid {
public:
    // Cells sized for a tool of radius `radius` (about a few per radius, a dozen triangles each).
    TriangleGrid(const sim::TriangleMesh& mesh, double radius);

    const float* vertices(std::uint32_t id) const { return &m_tris[std::size_t(id) * kStride]; }
    double cellSize() const { return m_cell; }

    // Calls triangle(id) for each triangle within `radius` of c whose best tip could beat `best`
    // (which triangle() raises): its top minus height(distance to its box), `height` being the
    // cutter's non-decreasing profile. Each triangle once at most.
    template <class Height, class Triangle>
    void visit(base::Vec2 c, double radius, const Height& height, const double& best, Triangle&& triangle) const;

private:
    static constexpr std::size_t kStride = 14;  // 9 coordinates, top, box (x0 y0 x1 y1)
    int cellX(double x) const { return std::clamp(int(std::floor((x - m_x0) / m_cell)), 0, m_nx - 1); }
    int cellY(double y) const { return std::clamp(int(std::floor((y - m_y0) / m_cell)), 0, m_ny - 1); }
    static double boxDistance(base::Vec2 c, const float* box)
    {
        const double dx = std::max({0.0, box[0] - c.x, c.x - box[2]});
        const double dy = std::max({0.0, box[1] - c.y, c.y - box[3]});
        return std::sqrt(dx * dx + dy * dy);  // not std::hypot: this is the hot loop
    }

    std::vector<float> m_tris;
    double m_x0 = 0, m_y0 = 0, m_cell = 1;
    int m_nx = 1, m_ny = 1;
    std::vector<std::uint32_t> m_start, m_ids;  // cell k lists m_ids[m_start[k] .. m_start[k + 1])
    std::vector<float> m_cellBox;               // per cell: top, x0 y0 x1 y1 of what it lists
};

template <class Height, class Triangle>
void TriangleGrid::visit(base::Vec2 c, double radius, const Height& height, const double& best,
                         Triangle&& triangle) const
{
    const int i0 = cellX(c.x - radius), i1 = cellX(c.x + radius), j0 = cellY(c.y - radius), j1 = cellY(c.y + radius);
    thread_local std::vector<std::pair<double, int>> cells;
    cells.clear();
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const int k = j * m_nx + i;
            if (m_start[k] == m_start[k + 1])
                continue;
            const double d = boxDistance(c, &m_cellBox[5 * k + 1]);
            if (d <= radius)
                cells.emplace_back(m_cellBox[5 * k] - height(d), k);
        }
    // The most promising cell first, alone: it usually sets `best` so high that only a few of the
    // others are left to sort.
    auto visitCell = [&](double bound, int k) {
        const double drop = m_cellBox[5 * k] - bound;  // height() at the cell's box
        const int ci = k % m_nx, cj = k / m_nx;
        for (std::uint32_t n = m_start[k]; n < m_start[k + 1]; ++n) {
            const std::uint32_t id = m_ids[n];
            const float* t = vertices(id);
            if (t[9] - drop <= best)
                break;
            // Visited in the first cell of the query that lists it only.
            if (std::max(cellX(t[10]), i0) != ci || std::max(cellY(t[11]), j0) != cj)
                continue;
            const double d = boxDistance(c, t + 10);
            if (d <= radius && t[9] - height(d) > best)
                triangle(id);
        }
    };
    if (cells.empty())
        return;
    auto first =
        std::max_element(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::iter_swap(first, cells.begin());
    visitCell(cells.front().first, cells.front().second);
    const auto last =
        std::partition(cells.begin() + 1, cells.end(), [&](const auto& cell) { return cell.first > best; });
    std::sort(cells.begin() + 1, last, [](const auto& a, const auto& b) { return a.first > b.first; });
    for (auto it = cells.begin() + 1; it != last && it->first > best; ++it)
        visitCell(it->first, it->second);
}

}  // namespace camwb::ops::surface
