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
    bool row(double y, double& xlo, double& xhi) const
    {
        return rowFromChords(y, halfChord(m_a, m_r, y), halfChord(m_b, m_r, y), xlo, xhi);
    }
    // The half chord of the disc of radius r round `c` on row y; -1 where the row misses it. For
    // the end discs this is the root row() takes: a caller that keeps an end's chords (the next
    // move starts there) hands them to rowFromChords().
    static double halfChord(base::Vec2 c, double r, double y)
    {
        const double dy = y - c.y;
        return std::abs(dy) <= r ? std::sqrt(r * r - dy * dy) : -1;
    }
    bool rowFromChords(double y, double aHalf, double bHalf, double& xlo, double& xhi) const
    {
        xlo = 1e300, xhi = -1e300;
        if (aHalf >= 0)
            xlo = std::min(xlo, m_a.x - aHalf), xhi = std::max(xhi, m_a.x + aHalf);
        if (bHalf >= 0)
            xlo = std::min(xlo, m_b.x - bHalf), xhi = std::max(xhi, m_b.x + bHalf);
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
