// The height field's design comparison and its mesh (HeightField.h).
#include "sim/HeightField.h"

#include "sim/MeshRays.h"

#include <algorithm>
#include <cmath>
#include <optional>

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
    m_lastCut.clear();
    if (model.empty())
        return;
    m_design.assign(m_top.size(), kNone);
    m_lastCut.assign(m_top.size(), -1);
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
        return best < 1e300 ? best : z - bottom(i, j);
    for (int r = 1; (r - 0.5) * cell < best && (r - 1) * cell <= cap; ++r)
        for (int dj = -r; dj <= r; ++dj)
            for (int di = -r; di <= r; di += (std::abs(dj) == r ? 1 : 2 * r)) {
                const int ii = i + di, jj = j + dj;
                if (ii < 0 || jj < 0 || ii >= m_nx || jj >= m_ny || m_design[index(ii, jj)] == kNone)
                    continue;
                const double side = std::hypot(di * m_dx, dj * m_dy) - 0.5 * cell;
                best = std::min(best, std::hypot(side, std::max(0.0, z - m_design[index(ii, jj)])));
            }
    return best < 1e300 ? best : z - bottom(i, j);
}

double HeightField::deviation(int i, int j) const
{
    const std::size_t k = index(i, j);
    if (m_design.empty())
        return 0;
    const double z = m_top[k], d = m_design[k];
    if (d == kNone && z <= bottom(i, j) + 1e-6)
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
                if (m_top[k] - bottom(i, j) > out.maxOutsideMm)
                    out.maxOutsideMm = m_top[k] - bottom(i, j), out.outsideAt = at;
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
// and the bottom as a fan (a flat bottom) or a second grid (a blank's). The file's mesh gathers
// the flat cells into fans and holds only the vertices its triangles use.
TriangleMesh HeightField::mesh() const { return buildMesh(false); }
TriangleMesh HeightField::fileMesh() const { return buildMesh(true); }

namespace {

// Grid points numbered in grid order: a bit per point and, per word of bits, how many points the
// words before it hold. The file's mesh uses a few percent of the grid's points; a vertex id per
// grid point was megabytes at 0.1 mm, and faulting them in a good part of the command's time.
class GridPointSet {
public:
    explicit GridPointSet(std::size_t points) : bits((points + 63) / 64, 0) {}
    void add(std::size_t k) { bits[k / 64] |= std::uint64_t(1) << (k % 64); }
    bool has(std::size_t k) const { return (bits[k / 64] >> (k % 64)) & 1; }
    // Numbers the points; rank() is valid from here on.
    void seal()
    {
        before.resize(bits.size());
        std::uint32_t count = 0;
        for (std::size_t w = 0; w < bits.size(); ++w)
            before[w] = count, count += std::uint32_t(__builtin_popcountll(bits[w]));
    }
    // The number of points before point k (k in the set: its place among them).
    std::uint32_t rank(std::size_t k) const
    {
        const std::uint64_t lower = (std::uint64_t(1) << (k % 64)) - 1;
        return before[k / 64] + std::uint32_t(__builtin_popcountll(bits[k / 64] & lower));
    }
    template <class F> void forEach(F f) const
    {
        for (std::size_t w = 0; w < bits.size(); ++w)
            for (std::uint64_t word = bits[w]; word; word &= word - 1)
                f(w * 64 + std::size_t(__builtin_ctzll(word)));
    }

private:
    std::vector<std::uint64_t> bits;
    std::vector<std::uint32_t> before;
};

// A grid surface's heights: nx x ny points, heights[j * nx + i].
struct GridHeights {
    const std::vector<float>& heights;
    int nx, ny;
    float at(int i, int j) const { return heights[std::size_t(j) * nx + i]; }
};

// The file's surface: its flat cells (four corners at one height) gathered into rectangles,
// greedily row by row, each of four cells or more a fan around a new centre vertex through the
// vertices of its edges that anything else uses, so that neighbours meet vertex to vertex; the
// other cells on their own. A vertex that is no rectangle's corner and no lone cell's lies inside
// the edge two fans share (or inside one fan): both pass it by along the same edge.
struct FlatPlan {
    struct Rect {
        int i, j, w, h;
    };
    std::vector<Rect> fans;
    std::vector<char> inFan;  // per cell
    // The vertices the surface passes through: the grid's outer ring (the side walls use every
    // one), the corners of every fan and every vertex of a cell on its own. No other is used.
    GridPointSet used;

    explicit FlatPlan(const GridHeights& g) : used(std::size_t(g.nx) * g.ny)
    {
        const int cx = g.nx - 1, cy = g.ny - 1;
        // Per cell, 1 while it is not free: not flat, or in a rectangle already. Flat cells that
        // share an edge share two corners and so lie at one height: a rectangle grows over free
        // cells alone, and a pass that compares four corners per cell is made once, up front.
        std::vector<char>& taken = inFan;
        taken.resize(std::size_t(cx) * cy);
        for (int j = 0; j < cy; ++j) {
            const float* below = &g.heights[std::size_t(j) * g.nx];
            const float* above = below + g.nx;
            char* row = &taken[std::size_t(j) * cx];
            for (int i = 0; i < cx; ++i)
                row[i] = char(!((below[i] == below[i + 1]) & (below[i] == above[i]) & (below[i] == above[i + 1])));
        }
        auto free = [&](int i, int j) { return !taken[std::size_t(j) * cx + i]; };
        auto mark = [&](const Rect& r) {
            for (int dj = 0; dj < r.h; ++dj)
                std::fill_n(taken.begin() + std::ptrdiff_t(std::size_t(r.j + dj) * cx + r.i), r.w, char(1));
        };
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i) {
                if (!free(i, j))
                    continue;
                int w = 1, rows = 1;
                while (i + w < cx && free(i + w, j))
                    ++w;
                for (; j + rows < cy; ++rows) {
                    int k = 0;
                    while (k < w && free(i + k, j + rows))
                        ++k;
                    if (k < w)
                        break;
                }
                if (w * rows < 4)
                    w = 1, rows = 1;  // its cells on their own: fewer triangles than a fan may take
                mark({i, j, w, rows});
                if (w * rows > 1)
                    fans.push_back({i, j, w, rows});
            }
        auto use = [&](int i, int j) { used.add(std::size_t(j) * g.nx + i); };
        for (int i = 0; i < g.nx; ++i)
            use(i, 0), use(i, cy);
        for (int j = 0; j < g.ny; ++j)
            use(0, j), use(cx, j);
        std::fill(taken.begin(), taken.end(), char(0));
        for (const Rect& r : fans) {
            use(r.i, r.j), use(r.i + r.w, r.j), use(r.i, r.j + r.h), use(r.i + r.w, r.j + r.h);
            mark(r);
        }
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i)
                if (!taken[std::size_t(j) * cx + i])
                    use(i, j), use(i + 1, j), use(i, j + 1), use(i + 1, j + 1);
        used.seal();
    }
};

// The mesh's vertices at the grid points of one surface (x and y per grid line). Made in grid
// order from `base` on: all of them (the display mesh: its heights are rewritten in place while
// cutting) or those a plan uses (the file's).
class GridVertices {
public:
    GridVertices(TriangleMesh& m, const std::vector<double>& xs, const std::vector<double>& ys, const GridHeights& g,
                 const FlatPlan* plan) :
        xs(xs),
        ys(ys),
        g(g),
        plan(plan),
        base(std::uint32_t(m.vertexCount()))
    {
        auto add = [&](int i, int j) { m.positions.insert(m.positions.end(), {float(x(i)), float(y(j)), g.at(i, j)}); };
        if (plan) {
            plan->used.forEach([&](std::size_t k) { add(int(k % std::size_t(g.nx)), int(k / std::size_t(g.nx))); });
            return;
        }
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                add(i, j);
    }

    std::uint32_t at(int i, int j) const
    {
        const std::size_t k = std::size_t(j) * g.nx + i;
        return base + (plan ? plan->used.rank(k) : std::uint32_t(k));
    }
    double x(int i) const { return xs[std::size_t(i)]; }
    double y(int j) const { return ys[std::size_t(j)]; }
    const GridHeights& heights() const { return g; }
    const FlatPlan* flatPlan() const { return plan; }

private:
    const std::vector<double>& xs;
    const std::vector<double>& ys;
    const GridHeights& g;
    const FlatPlan* plan;
    std::uint32_t base;
};

// The triangles of a grid surface, facing up or down: a pair per cell, or as its vertices' plan
// gathers them.
class GridSurface {
public:
    GridSurface(TriangleMesh& m, const GridVertices& v, bool up) : m(m), v(v), g(v.heights()), up(up) {}

    void write()
    {
        const FlatPlan* plan = v.flatPlan();
        const int cx = g.nx - 1, cy = g.ny - 1;
        if (plan)
            for (const FlatPlan::Rect& r : plan->fans)
                fan(r.i, r.j, r.w, r.h);
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i)
                if (!plan || !plan->inFan[std::size_t(j) * cx + i])
                    cell(i, j);
    }

private:
    void tri(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        if (up)
            m.triangles.insert(m.triangles.end(), {a, b, c});
        else
            m.triangles.insert(m.triangles.end(), {a, c, b});
    }
    void cell(int i, int j)
    {
        const std::uint32_t a = v.at(i, j), b = v.at(i + 1, j), c = v.at(i + 1, j + 1), d = v.at(i, j + 1);
        tri(a, b, c), tri(a, c, d);
    }
    // The rectangle of w x h cells from (bi, bj) as a fan: its rim counter-clockwise seen from
    // above, through the vertices of its edges that are used.
    void fan(int bi, int bj, int w, int h)
    {
        std::vector<std::uint32_t>& rim = rimScratch;
        rim.clear();
        auto on = [&](int i, int j) {
            if (v.flatPlan()->used.has(std::size_t(j) * g.nx + i))
                rim.push_back(v.at(i, j));
        };
        for (int i = bi; i < bi + w; ++i)
            on(i, bj);
        for (int j = bj; j < bj + h; ++j)
            on(bi + w, j);
        for (int i = bi + w; i > bi; --i)
            on(i, bj + h);
        for (int j = bj + h; j > bj; --j)
            on(bi, j);
        m.positions.insert(m.positions.end(),
                           {float((v.x(bi) + v.x(bi + w)) / 2), float((v.y(bj) + v.y(bj + h)) / 2), g.at(bi, bj)});
        const auto centre = std::uint32_t(m.vertexCount() - 1);
        for (std::size_t k = 0; k < rim.size(); ++k)
            tri(centre, rim[k], rim[(k + 1) % rim.size()]);
    }

    TriangleMesh& m;
    const GridVertices& v;
    const GridHeights& g;
    bool up;
    std::vector<std::uint32_t> rimScratch;
};

}  // namespace

TriangleMesh HeightField::buildMesh(bool mergeFlats) const
{
    TriangleMesh m;
    const bool flatBottom = sameBottom();
    if (!mergeFlats)
        m.positions.reserve(3 * (flatBottom ? m_top.size() + 2 * (m_nx + m_ny) : 2 * m_top.size()));
    std::vector<double> xs(static_cast<std::size_t>(m_nx)), ys(static_cast<std::size_t>(m_ny));
    for (int i = 0; i < m_nx; ++i)
        xs[std::size_t(i)] = i == 0 ? m_box.min.x : i == m_nx - 1 ? m_box.max.x : columnX(i);
    for (int j = 0; j < m_ny; ++j)
        ys[std::size_t(j)] = j == 0 ? m_box.min.y : j == m_ny - 1 ? m_box.max.y : columnY(j);
    // The display mesh's top vertices first, in grid order: updateMesh finds them by column.
    const GridHeights topHeights{m_top, m_nx, m_ny}, bottomHeights{m_bottom, m_nx, m_ny};
    std::optional<FlatPlan> topPlan, bottomPlan;
    if (mergeFlats)
        topPlan.emplace(topHeights);
    const GridVertices top(m, xs, ys, topHeights, topPlan ? &*topPlan : nullptr);
    std::optional<GridVertices> bottom;
    if (!flatBottom) {
        if (mergeFlats)
            bottomPlan.emplace(bottomHeights);
        bottom.emplace(m, xs, ys, bottomHeights, bottomPlan ? &*bottomPlan : nullptr);
    }
    auto put = [&](double x, double y, double z) {
        m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
        return std::uint32_t(m.positions.size() / 3 - 1);
    };
    auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.triangles.insert(m.triangles.end(), {a, b, c});
    };
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
            below[k] = put(xs[std::size_t(ring[k].first)], ys[std::size_t(ring[k].second)], floorHeight());
        const std::uint32_t centre =
            put((m_box.min.x + m_box.max.x) / 2, (m_box.min.y + m_box.max.y) / 2, floorHeight());
        for (std::size_t k = 0; k < ring.size(); ++k)
            tri(centre, below[(k + 1) % ring.size()], below[k]);
    } else {
        for (std::size_t k = 0; k < ring.size(); ++k)
            below[k] = bottom->at(ring[k].first, ring[k].second);
    }
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::size_t next = (k + 1) % ring.size();
        const std::uint32_t p = top.at(ring[k].first, ring[k].second);
        const std::uint32_t q = top.at(ring[next].first, ring[next].second);
        tri(below[k], below[next], q), tri(below[k], q, p);
    }
    GridSurface(m, top, true).write();
    if (bottom)
        GridSurface(m, *bottom, false).write();
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
