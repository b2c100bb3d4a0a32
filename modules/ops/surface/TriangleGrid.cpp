#include "ops/surface/TriangleGrid.h"

#include <limits>
#include <numeric>

namespace camwb::ops::surface {

TriangleGrid::TriangleGrid(const sim::TriangleMesh& mesh, double radius)
{
    const std::size_t n = mesh.triangleCount();
    m_tris.resize(n * kStride);
    float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    for (std::size_t t = 0; t < n; ++t) {
        float* out = &m_tris[t * kStride];
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a)
                out[3 * v + a] = mesh.positions[3 * mesh.triangles[3 * t + v] + a];
        out[9] = std::max({out[2], out[5], out[8]});
        out[10] = std::min({out[0], out[3], out[6]}), out[11] = std::min({out[1], out[4], out[7]});
        out[12] = std::max({out[0], out[3], out[6]}), out[13] = std::max({out[1], out[4], out[7]});
        x0 = std::min(x0, out[10]), y0 = std::min(y0, out[11]), x1 = std::max(x1, out[12]), y1 = std::max(y1, out[13]);
    }
    if (n == 0) {
        m_start.assign(2, 0);
        m_cellBox.assign(5, 0);
        return;
    }
    // About a dozen triangles a cell, and no cell wider than half the tool (so that the cells'
    // bounds prune), within a few million cells.
    const double w = std::max(1e-6, double(x1) - x0), h = std::max(1e-6, double(y1) - y0);
    m_cell = std::min(std::sqrt(w * h * 12 / double(n)), std::max(radius / 2, 1e-3));
    m_cell = std::max(m_cell, std::sqrt(w * h / 4e6));
    m_x0 = x0, m_y0 = y0;
    m_nx = std::max(1, int(std::ceil(w / m_cell))), m_ny = std::max(1, int(std::ceil(h / m_cell)));
    const std::size_t cells = std::size_t(m_nx) * m_ny;

    // Counting sort into the cells, then each cell's list by falling top.
    m_start.assign(cells + 1, 0);
    auto forCells = [&](std::size_t t, auto&& f) {
        const float* b = &m_tris[t * kStride + 10];
        for (int j = cellY(b[1]); j <= cellY(b[3]); ++j)
            for (int i = cellX(b[0]); i <= cellX(b[2]); ++i)
                f(std::size_t(j) * m_nx + i);
    };
    for (std::size_t t = 0; t < n; ++t)
        forCells(t, [&](std::size_t k) { ++m_start[k + 1]; });
    std::partial_sum(m_start.begin(), m_start.end(), m_start.begin());
    m_ids.resize(m_start.back());
    std::vector<std::uint32_t> fill(m_start.begin(), m_start.end() - 1);
    for (std::size_t t = 0; t < n; ++t)
        forCells(t, [&](std::size_t k) { m_ids[fill[k]++] = std::uint32_t(t); });
    m_cellBox.assign(cells * 5, 0);
    for (std::size_t k = 0; k < cells; ++k) {
        auto first = m_ids.begin() + m_start[k], last = m_ids.begin() + m_start[k + 1];
        std::sort(first, last, [&](std::uint32_t a, std::uint32_t b) { return vertices(a)[9] > vertices(b)[9]; });
        float* box = &m_cellBox[5 * k];
        box[0] = -std::numeric_limits<float>::infinity();
        box[1] = box[2] = std::numeric_limits<float>::max(), box[3] = box[4] = -std::numeric_limits<float>::max();
        for (auto it = first; it != last; ++it) {
            const float* t = vertices(*it);
            box[0] = std::max(box[0], t[9]);
            box[1] = std::min(box[1], t[10]), box[2] = std::min(box[2], t[11]);
            box[3] = std::max(box[3], t[12]), box[4] = std::max(box[4], t[13]);
        }
    }
}

}  // namespace camwb::ops::surface
