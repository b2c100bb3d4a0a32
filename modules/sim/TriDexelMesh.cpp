// The tri-dexel stock's mesh and its comparison with the design (TriDexel.h).
#include "sim/TriDexel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double comp(const Vec3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }

// Calls out(lo, hi) for each stretch where `a` has material and `b` has none.
template <class Out>
void difference(const std::vector<TriDexel::Span>& a, const std::vector<TriDexel::Span>* b, Out out)
{
    for (const TriDexel::Span& s : a) {
        double from = s.lo;
        if (b)
            for (const TriDexel::Span& t : *b) {
                if (t.hi <= from || t.lo >= s.hi)
                    continue;
                if (t.lo > from)
                    out(from, double(t.lo));
                from = std::max<double>(from, t.hi);
            }
        if (from < s.hi)
            out(from, double(s.hi));
    }
}

struct MeshBuilder {
    TriangleMesh mesh;
    // A quad p0..p3, counter-clockwise seen from outside.
    void quad(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3)
    {
        const auto first = std::uint32_t(mesh.vertexCount());
        for (const Vec3& p : {p0, p1, p2, p3})
            mesh.positions.insert(mesh.positions.end(), {float(p.x), float(p.y), float(p.z)});
        mesh.triangles.insert(mesh.triangles.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
};

}  // namespace

TriangleMesh TriDexel::mesh() const
{
    const Grid& g = m_grids[2];
    const RayGrid& rg = g.rays;
    MeshBuilder b;
    for (int j = 0; j < rg.nv; ++j)
        for (int i = 0; i < rg.nu; ++i) {
            const std::vector<Span>& spans = g.spans[g.at(i, j)];
            const double x0 = rg.u0 + i * rg.du, x1 = x0 + rg.du, y0 = rg.v0 + j * rg.dv, y1 = y0 + rg.dv;
            for (const Span& s : spans) {
                b.quad({x0, y0, s.hi}, {x1, y0, s.hi}, {x1, y1, s.hi}, {x0, y1, s.hi});
                b.quad({x0, y0, s.lo}, {x0, y1, s.lo}, {x1, y1, s.lo}, {x1, y0, s.lo});
            }
            // Sides where this column has material and its neighbour (or the outside) has none.
            const std::vector<Span>* east = i + 1 < rg.nu ? &g.spans[g.at(i + 1, j)] : nullptr;
            const std::vector<Span>* west = i > 0 ? &g.spans[g.at(i - 1, j)] : nullptr;
            const std::vector<Span>* north = j + 1 < rg.nv ? &g.spans[g.at(i, j + 1)] : nullptr;
            const std::vector<Span>* south = j > 0 ? &g.spans[g.at(i, j - 1)] : nullptr;
            difference(spans, east, [&](double lo, double hi) {
                b.quad({x1, y0, lo}, {x1, y1, lo}, {x1, y1, hi}, {x1, y0, hi});
            });
            difference(spans, west, [&](double lo, double hi) {
                b.quad({x0, y0, lo}, {x0, y0, hi}, {x0, y1, hi}, {x0, y1, lo});
            });
            difference(spans, north, [&](double lo, double hi) {
                b.quad({x0, y1, lo}, {x0, y1, hi}, {x1, y1, hi}, {x1, y1, lo});
            });
            difference(spans, south, [&](double lo, double hi) {
                b.quad({x0, y0, lo}, {x1, y0, lo}, {x1, y0, hi}, {x0, y0, hi});
            });
        }
    return std::move(b.mesh);
}

double TriDexel::alongRay(int axis, int i, int j, double t) const
{
    const Grid& g = m_grids[axis];
    const std::vector<Span>& design = g.design[g.at(i, j)];
    double best = kInf;
    for (const Span& d : design) {
        if (t >= d.lo && t <= d.hi)
            return -std::min(t - d.lo, d.hi - t);
        best = std::min({best, std::abs(t - d.lo), std::abs(t - d.hi)});
    }
    return best;
}

// The deviation at a surface point: along the nearest ray of each grid, the distance to the
// design's surface; the smallest of the three (a dexel stock knows the model only along its rays).
double TriDexel::vertexDeviation(const Vec3& p) const
{
    double best = kInf;
    for (int a = 0; a < 3; ++a) {
        const auto [i, j] = rayThrough(a, p);
        const double d = alongRay(a, i, j, comp(p, a));
        if (std::abs(d) < std::abs(best))
            best = d;
    }
    return best;
}

std::int64_t TriDexel::lastCutAt(const Vec3& p) const
{
    std::int64_t last = -1;
    for (int a = 0; a < 3; ++a) {
        const auto [i, j] = rayThrough(a, p);
        last = std::max<std::int64_t>(last, m_grids[a].lastCut[m_grids[a].at(i, j)]);
    }
    return last;
}

Deviation TriDexel::compare() const
{
    Deviation out;
    const TriangleMesh m = mesh();
    out.perVertex.assign(m.vertexCount(), 0.f);
    if (!m_hasDesign)
        return out;
    // A face stands up to half a cell from where its rays found the surface, and a ray that
    // grazes the design reads that offset several times over: a point the rays put inside the
    // model is as deep as its exact distance from the model's surface says. That distance is
    // sought within `near` at every face; deeper points (a gross error, e.g. a stock lower than
    // the part) keep the rays' figure for their colour, and only those that could be the deepest
    // are measured fully, deepest first.
    const double nearMm = std::max(1.0, 10 * resolutionMm());
    struct Deep {
        double alongRays;
        Vec3 at, centre;
        std::int64_t move;
    };
    std::vector<Deep> deep;
    // The mesh is quads, four vertices each in order: each is measured once at its middle,
    // which lies on the face's cell boundary.
    for (std::size_t first = 0; first + 3 < m.vertexCount(); first += 4) {
        const Vec3 p = m.vertex(first);
        const Vec3 centre = (m.vertex(first) + m.vertex(first + 1) + m.vertex(first + 2) + m.vertex(first + 3)) * 0.25;
        double dev = vertexDeviation(centre);
        if (!std::isfinite(dev)) {  // no design along any of the three rays: beside the part
            std::fill_n(out.perVertex.begin() + std::ptrdiff_t(first), 4, float(m_box.max.z - m_box.min.z));
            for (std::size_t k = first; k < first + 4; ++k) {
                const Vec3 v = m.vertex(k);
                if (v.z - m_box.min.z > out.maxOutsideMm)
                    out.maxOutsideMm = v.z - m_box.min.z, out.outsideAt = v;
            }
            continue;
        }
        const std::int64_t move = lastCutAt(centre);
        bool confirmed = true;
        if (-dev > m_tolerance) {
            const double within = std::min(-dev, nearMm);
            const double depth = trueDepth(centre, within);
            if (depth >= within && -dev > within) {
                deep.push_back({-dev, p, centre, move});
                confirmed = false;
            } else {
                dev = -depth;
            }
        }
        std::fill_n(out.perVertex.begin() + std::ptrdiff_t(first), 4, float(dev));
        if (dev > out.maxLeftoverMm)
            out.maxLeftoverMm = dev, out.leftoverAt = p, out.leftoverMove = move;
        if (confirmed && -dev > m_tolerance && -dev > out.maxGougeMm)
            out.maxGougeMm = -dev, out.gougeAt = p, out.gougeMove = move;
    }
    std::sort(deep.begin(), deep.end(), [](const Deep& a, const Deep& b) { return a.alongRays > b.alongRays; });
    for (const Deep& d : deep) {
        if (d.alongRays <= out.maxGougeMm)
            break;  // the rays' figure bounds the true depth: none further can be deeper
        const double depth = trueDepth(d.centre, d.alongRays);
        if (depth > out.maxGougeMm)
            out.maxGougeMm = depth, out.gougeAt = d.at, out.gougeMove = d.move;
    }
    return out;
}

}  // namespace camwb::sim
