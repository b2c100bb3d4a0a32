// Marching squares over the drop heights: each cell with touching and clear corners gives one or
// two pieces, from the crossing where its boundary (walked counter-clockwise) leaves the touching
// side to the one where it enters it again, so that the material is on the left. A saddle (two
// touching corners facing each other) is told by a drop at the cell's centre. The grid is ringed
// by clear nodes, so every loop closes; the crossing each piece ends on is where the next starts.
#include "ops/surface/DropContours.h"

#include "ops/surface/AllCores.h"
#include "ops/surface/DropCutter.h"
#include "sim/ToolShape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

namespace camwb::ops::surface {

using base::Vec2;

double DropContours::step(const toolpath::Tool& tool, double stockMm, double toleranceMm)
{
    const sim::ToolShape shape(tool);
    double curvature = 0;
    if (shape.flatBottomed())
        curvature = shape.radiusMm();
    else if (shape.coneSlope() == 0)
        curvature = shape.cornerRadiusMm();
    if (!(curvature > 0))
        return 0;
    return std::sqrt(2 * (curvature + stockMm) * toleranceMm);
}

DropContours::DropContours(const DropCutter& cutter, Vec2 lo, Vec2 hi, double step, double ignoreMm, double toleranceMm,
                           const Progress& progress, double from, double to) :
    m_cutter(cutter),
    m_step(step),
    m_ignore(ignoreMm),
    m_tol(toleranceMm),
    m_lo(lo),
    m_hi(hi)
{
    m_x0 = lo.x - 2 * step;
    m_y0 = lo.y - 2 * step;
    m_nx = int(std::ceil((hi.x - lo.x) / step)) + 5;
    m_ny = int(std::ceil((hi.y - lo.y) / step)) + 5;
    m_z.resize(std::size_t(m_nx) * std::size_t(m_ny));
    m_complete = forEachOnAllCores(
        std::size_t(m_ny),
        [&](std::size_t j) {
            for (int i = 0; i < m_nx; ++i)
                m_z[j * std::size_t(m_nx) + std::size_t(i)] = m_cutter.dropZ(node(i, int(j)));
        },
        progress, from, to);
}

double DropContours::value(int i, int j) const
{
    if (i < 0 || j < 0 || i >= m_nx || j >= m_ny)
        return -std::numeric_limits<double>::infinity();
    return m_z[std::size_t(j) * std::size_t(m_nx) + std::size_t(i)];
}

bool DropContours::nearArea(Vec2 p) const
{
    return p.x > m_lo.x - m_step && p.x < m_hi.x + m_step && p.y > m_lo.y - m_step && p.y < m_hi.y + m_step;
}

bool DropContours::touches(Vec2 xy, double z) const { return m_cutter.dropZ(xy) > z + m_ignore; }

// The point between `touching` and `clear` where the tool starts to touch, to a tenth of the
// tolerance, on the clear side: regula falsi (the Illinois variant), halving where it stalls.
Vec2 DropContours::crossing(Vec2 touching, Vec2 clear, double level) const
{
    const double length = (clear - touching).length();
    const double cap = 4 * length + 1;  // no model under a point: -infinity, kept finite here
    const auto f = [&](double t) {
        const double z = m_cutter.dropZ(touching + (clear - touching) * t) - level;
        return std::clamp(z, -cap, cap);
    };
    double a = 0, b = 1, fa = f(0), fb = f(1);
    int side = 0;
    double width = 1;
    bool halve = false;
    for (int i = 0; i < 60 && (b - a) * length > m_tol / 10; ++i) {
        double t = halve || !(fa > fb) ? (a + b) / 2 : a + (b - a) * fa / (fa - fb);
        t = std::clamp(t, a + (b - a) * 1e-3, b - (b - a) * 1e-3);
        const double ft = f(t);
        if (ft > 0) {
            a = t, fa = ft;
            if (side == 1)
                fb /= 2;
            side = 1;
        } else {
            b = t, fb = ft;
            if (side == -1)
                fa /= 2;
            side = -1;
        }
        halve = b - a > width / 2;  // less than halved: the next step halves
        width = b - a;
    }
    return touching + (clear - touching) * b;
}

std::vector<std::vector<Vec2>> DropContours::loopsAt(double z) const
{
    const double level = z + m_ignore;
    // Padded indices: node (I, J) is grid node (I - 1, J - 1); the ring round the grid is clear.
    const int W = m_nx + 2, H = m_ny + 2;
    std::vector<char> in(std::size_t(W) * std::size_t(H));
    for (int J = 0; J < H; ++J)
        for (int I = 0; I < W; ++I)
            in[std::size_t(J) * W + I] = value(I - 1, J - 1) > level;
    const auto at = [&](int I, int J) { return in[std::size_t(J) * W + I] != 0; };
    // Edge ids: 2 (J W + I) from node (I, J) to (I + 1, J), that + 1 from (I, J) to (I, J + 1).
    const auto horizontal = [&](int I, int J) { return 2 * (std::uint64_t(J) * W + std::uint64_t(I)); };
    const auto vertical = [&](int I, int J) { return horizontal(I, J) + 1; };

    // The pieces (the crossing each starts on, the one it ends on), sorted by the first so that a
    // loop's next piece is found by bisection and the loops come in the same order on every run.
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pieces;
    for (int J = 0; J + 1 < H; ++J)
        for (int I = 0; I + 1 < W; ++I) {
            const bool b[4] = {at(I, J), at(I + 1, J), at(I + 1, J + 1), at(I, J + 1)};
            if (b[0] == b[1] && b[1] == b[2] && b[2] == b[3])
                continue;
            const std::uint64_t edges[4] = {horizontal(I, J), vertical(I + 1, J), horizontal(I, J + 1), vertical(I, J)};
            std::uint64_t id[4];
            bool exits[4];
            int n = 0;
            for (int k = 0; k < 4; ++k)
                if (b[k] != b[(k + 1) % 4])
                    id[n] = edges[k], exits[n] = b[k], ++n;
            // Round a touching centre the clear corners are cut off (each exit to the entry after
            // it); round a clear one the touching corners (each exit to the entry before it).
            const bool centre = n == 4 && touches(node(I - 1, J - 1) + Vec2{m_step / 2, m_step / 2}, z);
            for (int k = 0; k < n; ++k)
                if (exits[k])
                    pieces.emplace_back(id[k], id[(k + (centre ? 1 : n - 1)) % n]);
        }
    std::sort(pieces.begin(), pieces.end());

    // A crossing's point: found by drops near [lo, hi]; farther out (where the loops close along
    // the grid's ring, or pass outside the area) the edge's middle serves.
    const auto point = [&](std::uint64_t edge) {
        const std::uint64_t k = edge / 2;
        const int I = int(k % std::uint64_t(W)), J = int(k / std::uint64_t(W));
        const int I1 = edge % 2 ? I : I + 1, J1 = edge % 2 ? J + 1 : J;
        Vec2 p = node(I - 1, J - 1), q = node(I1 - 1, J1 - 1);
        if (!at(I, J))
            std::swap(p, q);
        const Vec2 mid = (p + q) * 0.5;
        return nearArea(mid) ? crossing(p, q, level) : mid;
    };
    const auto pieceFrom = [&](std::uint64_t edge) {
        const auto it = std::lower_bound(pieces.begin(), pieces.end(), std::make_pair(edge, std::uint64_t(0)));
        return it != pieces.end() && it->first == edge ? std::size_t(it - pieces.begin()) : pieces.size();
    };
    std::vector<std::vector<Vec2>> loops;
    std::vector<char> used(pieces.size());
    for (std::size_t first = 0; first < pieces.size(); ++first) {
        std::vector<Vec2> loop;
        // Every crossing is left by one piece and entered by one, so the walk comes back to `first`.
        for (std::size_t i = first; i < pieces.size() && !used[i]; i = pieceFrom(pieces[i].second)) {
            used[i] = 1;
            loop.push_back(point(pieces[i].first));
        }
        if (loop.size() >= 3)
            loops.push_back(refined(loop, level));
    }
    return loops;
}

// Where a loop turns sharply, a chord may cut a corner of the contour (two walls met in a cell):
// the contour's point on the chord's normal through its middle is put in where it stands more
// than half the tolerance off it, and the two halves are looked at again, down to a sixteenth of
// the chord. Only near [lo, hi]: outside, the loops close along the grid's ring.
std::vector<Vec2> DropContours::refined(const std::vector<Vec2>& loop, double level) const
{
    constexpr double kSharpCos = 0.94;  // turning by more than 20 degrees
    const auto sharp = [](Vec2 a, Vec2 b, Vec2 c) {
        return (b - a).normalized().dot((c - b).normalized()) < kSharpCos;
    };
    std::vector<Vec2> out;
    const std::function<void(Vec2, Vec2, int)> split = [&](Vec2 a, Vec2 b, int depth) {
        const double length = (b - a).length();
        const Vec2 m = (a + b) * 0.5;
        if (depth == 0 || !(length > 0) || !nearArea(m))
            return;
        const Vec2 inward = (b - a).leftNormal() * (1 / length);  // towards the material
        const bool touching = m_cutter.dropZ(m) > level;
        const Vec2 far = touching ? m - inward * length : m + inward * length;
        if ((m_cutter.dropZ(far) > level) == touching)
            return;  // no contour within a chord's length: leave the chord
        const Vec2 p = touching ? crossing(m, far, level) : crossing(far, m, level);
        if ((p - m).length() <= m_tol / 2)
            return;
        split(a, p, depth - 1);
        out.push_back(p);
        split(p, b, depth - 1);
    };
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 prev = loop[(i + n - 1) % n], a = loop[i], b = loop[(i + 1) % n], next = loop[(i + 2) % n];
        out.push_back(a);
        if (sharp(prev, a, b) || sharp(a, b, next))
            split(a, b, 4);
    }
    return out;
}

}  // namespace camwb::ops::surface
