// The capsule of radius r around a segment a-b in a plane, read row by row: the x range over which
// a row y meets it, the hull of the two end discs and the band between them (the capsule is
// convex). The band's four edges are set up once; a row then costs a few multiplications. The
// height field sweeps a tool's disc along a move with it, the tri-dexels find the rays that can
// meet a cutter's axis segment.
#pragma once

#include "base/Vec.h"

#include <algorithm>
#include <cmath>

namespace camwb::sim {

class Capsule {
public:
    Capsule(base::Vec2 a, base::Vec2 b, double r) : m_a(a), m_b(b), m_r(r)
    {
        const base::Vec2 n = (b - a).normalized().leftNormal() * r;
        const base::Vec2 quad[4] = {a + n, b + n, b - n, a - n};
        for (int k = 0; k < 4; ++k) {
            const base::Vec2 p = quad[k], q = quad[(k + 1) % 4];
            m_edges[k] = {std::min(p.y, q.y), std::max(p.y, q.y), p.x, p.y, p.y == q.y ? 0 : (q.x - p.x) / (q.y - p.y)};
        }
    }
    // `aHalf`, when given, gets the half chord of a's disc on the row (-1 where the row misses
    // it): the height field sweeps what lies beyond that disc and need not take its root again.
    bool row(double y, double& xlo, double& xhi, double* aHalf = nullptr) const
    {
        xlo = 1e300, xhi = -1e300;
        if (aHalf)
            *aHalf = -1;
        for (const base::Vec2 c : {m_a, m_b}) {
            const double dy = y - c.y;
            if (std::abs(dy) <= m_r) {
                const double half = std::sqrt(m_r * m_r - dy * dy);
                xlo = std::min(xlo, c.x - half), xhi = std::max(xhi, c.x + half);
                if (aHalf && c == m_a)
                    *aHalf = half;
            }
        }
        for (const Edge& e : m_edges) {
            if (y < e.ylo || y > e.yhi || e.ylo == e.yhi)
                continue;
            const double x = e.x0 + (y - e.y0) * e.slope;
            xlo = std::min(xlo, x), xhi = std::max(xhi, x);
        }
        return xlo <= xhi;
    }

private:
    struct Edge {
        double ylo, yhi, x0, y0, slope;
    };
    base::Vec2 m_a, m_b;
    double m_r;
    Edge m_edges[4];
};

}  // namespace camwb::sim
