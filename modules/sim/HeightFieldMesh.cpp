// The height field's design comparison and its mesh (HeightField.h).
#include "sim/HeightField.h"

#include "sim/MeshRays.h"

#include <algorithm>
#include <cmath>

namespace camwb::sim {

namespace {

// How far from a column the nearest-boundary searches look: deviations within this are measured
// to the nearest column (to half a cell); beyond it a value is the vertical one, which is never
// smaller than the true distance. The cap keeps compare() linear in the number of columns.
double searchCap(double cell) { return std::max(1.0, 8 * cell); }

// The running maximum over a window of `radius` either side along one line (a deque of the
// candidates, each pushed and popped once: linear in the line's length).
void windowMax(const float* in, float* out, int n, int stride, int radius)
{
    std::vector<int> q;
    std::size_t head = 0;
    for (int k = 0, produced = 0; produced < n; ++k) {
        if (k < n) {
            while (q.size() > head && in[std::size_t(q.back()) * stride] <= in[std::size_t(k) * stride])
                q.pop_back();
            q.push_back(k);
        }
        const int centre = k - radius;
        if (centre < 0)
            continue;
        while (q[head] < centre - radius)
            ++head;
        out[std::size_t(centre) * stride] = in[std::size_t(q[head]) * stride];
        ++produced;
    }
}

}  // namespace

void HeightField::setDesign(const TriangleMesh& model, double toleranceMm)
{
    m_tolerance = toleranceMm;
    m_design.clear();
    if (model.empty())
        return;
    m_design.assign(m_top.size(), kNone);
    const RayGrid grid{2, m_box.min.x, m_box.min.y, m_dx, m_dy, m_nx, m_ny};
    forEachCrossing(model, grid, [&](int i, int j, double z, bool) {
        float& d = m_design[index(i, j)];
        d = std::max(d, float(z));
    });
    // The highest design top near each column bounds every sideways distance from below, so a
    // column over a level stretch of the model skips the search (compare() stays linear).
    const int radius = int(std::ceil(searchCap(std::min(m_dx, m_dy)) / std::min(m_dx, m_dy))) + 1;
    std::vector<float> rows(m_design.size());
    m_designNear.resize(m_design.size());
    for (int j = 0; j < m_ny; ++j)
        windowMax(&m_design[index(0, j)], &rows[index(0, j)], m_nx, 1, radius);
    for (int i = 0; i < m_nx; ++i)
        windowMax(&rows[index(i, 0)], &m_designNear[index(i, 0)], m_ny, m_nx, radius);
}

// The distance from (q, z), inside the design, to its outside {z' > designTop(q')}: straight up,
// or sideways to a column whose design top is lower (then up over it), within the search cap.
double HeightField::depthInDesign(int i, int j, double z) const
{
    const double cell = std::min(m_dx, m_dy), cap = searchCap(cell);
    double best = m_design[index(i, j)] - z;
    for (int r = 1; (r - 0.5) * cell < best && (r - 1) * cell <= cap; ++r)
        for (int dj = -r; dj <= r; ++dj)
            for (int di = -r; di <= r; di += (std::abs(dj) == r ? 1 : 2 * r)) {
                const int ii = i + di, jj = j + dj;
                const double side = std::hypot(di * m_dx, dj * m_dy) - 0.5 * cell;
                if (side >= best)
                    continue;
                const bool outsideGrid = ii < 0 || jj < 0 || ii >= m_nx || jj >= m_ny;
                const double up = outsideGrid ? 0 : std::max(0.0, double(m_design[index(ii, jj)]) - z);
                best = std::min(best, std::hypot(side, up));
            }
    return best;
}

// The distance from (q, z), above the design, down or sideways to the design's material
// {z' <= designTop(q')}; where none lies within the cap, the column's own height over the
// design (or over its bottom where the design is absent).
double HeightField::distanceToDesign(int i, int j, double z) const
{
    const double cell = std::min(m_dx, m_dy), cap = searchCap(cell);
    const double own = m_design[index(i, j)];
    double best = own > kNone ? z - own : 1e300;
    if (z - m_designNear[index(i, j)] >= best)  // nothing near is higher than the column's own
        return best < 1e300 ? best : z - m_bottom[index(i, j)];
    for (int r = 1; (r - 0.5) * cell < best && (r - 1) * cell <= cap; ++r)
        for (int dj = -r; dj <= r; ++dj)
            for (int di = -r; di <= r; di += (std::abs(dj) == r ? 1 : 2 * r)) {
                const int ii = i + di, jj = j + dj;
                if (ii < 0 || jj < 0 || ii >= m_nx || jj >= m_ny || m_design[index(ii, jj)] == kNone)
                    continue;
                const double side = std::hypot(di * m_dx, dj * m_dy) - 0.5 * cell;
                best = std::min(best, std::hypot(side, std::max(0.0, z - m_design[index(ii, jj)])));
            }
    return best < 1e300 ? best : z - m_bottom[index(i, j)];
}

double HeightField::deviation(int i, int j) const
{
    const std::size_t k = index(i, j);
    if (m_design.empty())
        return 0;
    const double z = m_top[k], d = m_design[k];
    if (d == kNone && z <= m_bottom[k] + 1e-6)
        return 0;  // nothing left and nothing wanted
    if (d > kNone && z < d)
        return -depthInDesign(i, j, z);
    return distanceToDesign(i, j, z);
}

Deviation HeightField::compare() const
{
    Deviation out;
    out.perVertex.assign(m_top.size() + (sameBottom() ? 2 * (m_nx + m_ny) - 3 : m_top.size()), 0.f);
    if (m_design.empty())
        return out;
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i) {
            const double dev = deviation(i, j);
            const std::size_t k = index(i, j);
            out.perVertex[k] = float(dev);
            const Vec3 at{columnX(i), columnY(j), m_top[k]};
            if (m_design[k] == kNone) {
                if (m_top[k] - m_bottom[k] > out.maxOutsideMm)
                    out.maxOutsideMm = m_top[k] - m_bottom[k], out.outsideAt = at;
                continue;
            }
            if (dev > out.maxLeftoverMm)
                out.maxLeftoverMm = dev, out.leftoverAt = at, out.leftoverMove = m_lastCut[k];
            if (-dev > m_tolerance && -dev > out.maxGougeMm)
                out.maxGougeMm = -dev, out.gougeAt = at, out.gougeMove = m_lastCut[k];
        }
    return out;
}

bool HeightField::sameBottom() const
{
    return std::all_of(m_bottom.begin(), m_bottom.end(), [&](float b) { return b == m_bottom.front(); });
}

// One top vertex per column (the grid's outer vertices pushed out to the box's sides, so the mesh
// covers the stock), triangles that never change while cutting, side walls down to the bottom,
// and the bottom as a fan (a flat bottom) or a second grid (a blank's).
TriangleMesh HeightField::mesh() const { return buildMesh(false); }
TriangleMesh HeightField::fileMesh() const { return buildMesh(true); }

namespace {

constexpr int kMinMergedLevel = 2;  // blocks of 4 x 4 cells: a fan of 16 triangles against 32

int blocks(int cells, int level) { return (cells + (1 << level) - 1) >> level; }  // aligned blocks of 2^level cells

// The triangles of a grid surface over nx x ny vertices (vertex (i, j) at base + j * nx + i, its
// height heights[j * nx + i]), facing up or down; `merge`: each flat aligned block of 4 x 4 cells
// or more (a quadtree's) as a fan around a new centre vertex through every vertex of its edges,
// so that neighbours meet vertex to vertex.
class GridSurface {
public:
    GridSurface(TriangleMesh& m, const std::vector<float>& heights, std::uint32_t base, int nx, int ny, bool up) :
        m(m),
        heights(heights),
        base(base),
        nx(nx),
        ny(ny),
        cx(nx - 1),
        cy(ny - 1),
        up(up)
    {
    }

    void plain()
    {
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i)
                cell(i, j);
    }

    void merged()
    {
        // Per level, each aligned block's height where it is flat (NaN where not, or where the
        // block reaches past the grid's cells); level 0 is a cell with its four vertices.
        const float none = std::numeric_limits<float>::quiet_NaN();
        flat.assign(1, std::vector<float>(std::size_t(cx) * cy, none));
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i) {
                const float h = height(i, j);
                if (height(i + 1, j) == h && height(i, j + 1) == h && height(i + 1, j + 1) == h)
                    flat[0][std::size_t(j) * cx + i] = h;
            }
        for (int level = 1; (1 << (level - 1)) < std::max(cx, cy); ++level) {
            const int size = 1 << level, bx = blocks(cx, level), by = blocks(cy, level), below = blocks(cx, level - 1);
            std::vector<float> next(std::size_t(bx) * by, none);
            const std::vector<float>& f = flat.back();
            for (int j = 0; j < by; ++j)
                for (int i = 0; i < bx; ++i) {
                    if ((i + 1) * size > cx || (j + 1) * size > cy)
                        continue;  // a block cut off by the grid's edge: its cells go on their own
                    const float h = f[std::size_t(2 * j) * below + 2 * i];
                    // NaN equals nothing: a block with one rough child is not flat.
                    if (h == f[std::size_t(2 * j) * below + 2 * i + 1] &&
                        h == f[std::size_t(2 * j + 1) * below + 2 * i] &&
                        h == f[std::size_t(2 * j + 1) * below + 2 * i + 1])
                        next[std::size_t(j) * bx + i] = h;
                }
            flat.push_back(std::move(next));
        }
        block(int(flat.size()) - 1, 0, 0);
    }

private:
    float height(int i, int j) const { return heights[std::size_t(j) * nx + i]; }
    std::uint32_t vertex(int i, int j) const { return base + std::uint32_t(std::size_t(j) * nx + i); }
    void tri(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        if (up)
            m.triangles.insert(m.triangles.end(), {a, b, c});
        else
            m.triangles.insert(m.triangles.end(), {a, c, b});
    }
    void cell(int i, int j)
    {
        const std::uint32_t a = vertex(i, j), b = a + 1, d = vertex(i, j + 1), c = d + 1;
        tri(a, b, c), tri(a, c, d);
    }
    void block(int level, int bi, int bj)
    {
        if (bi >= cx || bj >= cy)
            return;  // wholly past the grid's cells
        const int size = 1 << level;
        const float h = flat[std::size_t(level)][std::size_t(bj >> level) * blocks(cx, level) + (bi >> level)];
        if (level >= kMinMergedLevel && !std::isnan(h)) {
            // The rim counter-clockwise seen from above, through every vertex of its edges.
            std::vector<std::uint32_t> rim;
            for (int i = bi; i < bi + size; ++i)
                rim.push_back(vertex(i, bj));
            for (int j = bj; j < bj + size; ++j)
                rim.push_back(vertex(bi + size, j));
            for (int i = bi + size; i > bi; --i)
                rim.push_back(vertex(i, bj + size));
            for (int j = bj + size; j > bj; --j)
                rim.push_back(vertex(bi, j));
            const base::Vec3 lo = m.vertex(vertex(bi, bj)), hi = m.vertex(vertex(bi + size, bj + size));
            m.positions.insert(m.positions.end(), {float((lo.x + hi.x) / 2), float((lo.y + hi.y) / 2), h});
            const auto centre = std::uint32_t(m.vertexCount() - 1);
            for (std::size_t k = 0; k < rim.size(); ++k)
                tri(centre, rim[k], rim[(k + 1) % rim.size()]);
        } else if (level == 0) {
            cell(bi, bj);
        } else {
            const int half = size / 2;
            for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di)
                    block(level - 1, bi + di * half, bj + dj * half);
        }
    }

    TriangleMesh& m;
    const std::vector<float>& heights;
    std::uint32_t base;
    int nx, ny, cx, cy;
    bool up;
    std::vector<std::vector<float>> flat;
};

void gridSurface(TriangleMesh& m, const std::vector<float>& heights, std::uint32_t base, int nx, int ny, bool up,
                 bool merge)
{
    GridSurface grid(m, heights, base, nx, ny, up);
    if (merge)
        grid.merged();
    else
        grid.plain();
}

}  // namespace

TriangleMesh HeightField::buildMesh(bool mergeFlats) const
{
    TriangleMesh m;
    const bool flatBottom = sameBottom();
    const std::size_t n = m_top.size();
    m.positions.reserve(3 * (flatBottom ? n + 2 * (m_nx + m_ny) : 2 * n));
    auto vx = [&](int i) { return i == 0 ? m_box.min.x : i == m_nx - 1 ? m_box.max.x : columnX(i); };
    auto vy = [&](int j) { return j == 0 ? m_box.min.y : j == m_ny - 1 ? m_box.max.y : columnY(j); };
    auto put = [&](double x, double y, double z) {
        m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
        return std::uint32_t(m.positions.size() / 3 - 1);
    };
    auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.triangles.insert(m.triangles.end(), {a, b, c});
    };
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i)
            put(vx(i), vy(j), m_top[index(i, j)]);
    // The perimeter counter-clockwise seen from above.
    std::vector<std::pair<int, int>> ring;
    for (int i = 0; i < m_nx - 1; ++i)
        ring.push_back({i, 0});
    for (int j = 0; j < m_ny - 1; ++j)
        ring.push_back({m_nx - 1, j});
    for (int i = m_nx - 1; i > 0; --i)
        ring.push_back({i, m_ny - 1});
    for (int j = m_ny - 1; j > 0; --j)
        ring.push_back({0, j});
    std::vector<std::uint32_t> below(ring.size());
    if (flatBottom) {
        for (std::size_t k = 0; k < ring.size(); ++k)
            below[k] = put(vx(ring[k].first), vy(ring[k].second), m_bottom.front());
        const std::uint32_t centre =
            put((m_box.min.x + m_box.max.x) / 2, (m_box.min.y + m_box.max.y) / 2, m_bottom.front());
        for (std::size_t k = 0; k < ring.size(); ++k)
            tri(centre, below[(k + 1) % ring.size()], below[k]);
    } else {
        for (int j = 0; j < m_ny; ++j)
            for (int i = 0; i < m_nx; ++i)
                put(vx(i), vy(j), m_bottom[index(i, j)]);
        for (std::size_t k = 0; k < ring.size(); ++k)
            below[k] = std::uint32_t(n + index(ring[k].first, ring[k].second));
    }
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::size_t next = (k + 1) % ring.size();
        const auto p = std::uint32_t(index(ring[k].first, ring[k].second));
        const auto q = std::uint32_t(index(ring[next].first, ring[next].second));
        tri(below[k], below[next], q), tri(below[k], q, p);
    }
    // The grids last: a merged block's centre comes after the vertices the walls index.
    gridSurface(m, m_top, 0, m_nx, m_ny, true, mergeFlats);
    if (!flatBottom)
        gridSurface(m, m_bottom, std::uint32_t(n), m_nx, m_ny, false, mergeFlats);
    return m;
}

void HeightField::updateMesh(TriangleMesh& mesh, const ColumnRect& changed) const
{
    if (changed.empty())
        return;
    for (int j = std::max(0, changed.j0); j <= std::min(m_ny - 1, changed.j1); ++j)
        for (int i = std::max(0, changed.i0); i <= std::min(m_nx - 1, changed.i1); ++i)
            mesh.positions[3 * index(i, j) + 2] = m_top[index(i, j)];
}

}  // namespace camwb::sim
