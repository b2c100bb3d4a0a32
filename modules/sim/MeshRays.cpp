#include "sim/MeshRays.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace camwb::sim {

namespace {

struct P2 {
    double u, v;
};

// The edge function of x against the edge p -> q, computed with the endpoints in one canonical
// order so that the two triangles sharing an edge get exactly opposite values (no ray slips
// between them or hits both through rounding).
double edgeFunction(P2 p, P2 q, P2 x)
{
    const bool swapped = q.u < p.u || (q.u == p.u && q.v < p.v);
    if (swapped)
        std::swap(p, q);
    const double w = (q.u - p.u) * (x.v - p.v) - (q.v - p.v) * (x.u - p.u);
    return swapped ? -w : w;
}

// The top-left rule: a ray exactly on an edge belongs to the triangle for which this edge, walked
// counter-clockwise, goes up (or left when horizontal); its neighbour walks it the other way.
bool ownsEdge(P2 p, P2 q) { return q.v > p.v || (q.v == p.v && q.u < p.u); }

}  // namespace

void forEachCrossing(const TriangleMesh& mesh, const RayGrid& grid,
                     const std::function<void(int i, int j, double t, bool entering)>& crossing)
{
    const int a = grid.axis, ua = (a + 1) % 3, va = (a + 2) % 3;
    for (std::size_t tri = 0; tri < mesh.triangleCount(); ++tri) {
        std::array<P2, 3> p;
        std::array<double, 3> t;
        for (int k = 0; k < 3; ++k) {
            const float* v = &mesh.positions[3 * mesh.triangles[3 * tri + k]];
            p[k] = {v[ua], v[va]};
            t[k] = v[a];
        }
        const double area = (p[1].u - p[0].u) * (p[2].v - p[0].v) - (p[1].v - p[0].v) * (p[2].u - p[0].u);
        if (area == 0)  // seen edge-on: the rays run along it
            continue;
        const bool entering = area < 0;  // counter-clockwise from outside: faces +axis when area > 0
        if (area < 0)
            std::swap(p[1], p[2]), std::swap(t[1], t[2]);
        const double umin = std::min({p[0].u, p[1].u, p[2].u}), umax = std::max({p[0].u, p[1].u, p[2].u});
        const double vmin = std::min({p[0].v, p[1].v, p[2].v}), vmax = std::max({p[0].v, p[1].v, p[2].v});
        const int i0 = std::max(0, int(std::ceil((umin - grid.u0) / grid.du - 0.5)));
        const int i1 = std::min(grid.nu - 1, int(std::floor((umax - grid.u0) / grid.du - 0.5)));
        const int j0 = std::max(0, int(std::ceil((vmin - grid.v0) / grid.dv - 0.5)));
        const int j1 = std::min(grid.nv - 1, int(std::floor((vmax - grid.v0) / grid.dv - 0.5)));
        const double absArea = std::abs(area);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const P2 x{grid.uAt(i), grid.vAt(j)};
                double w[3];
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const P2 e0 = p[(k + 1) % 3], e1 = p[(k + 2) % 3];  // the edge opposite vertex k
                    w[k] = edgeFunction(e0, e1, x);
                    inside = w[k] > 0 || (w[k] == 0 && ownsEdge(e0, e1));
                }
                if (inside)
                    crossing(i, j, (w[0] * t[0] + w[1] * t[1] + w[2] * t[2]) / absArea, entering);
            }
    }
}

}  // namespace camwb::sim
