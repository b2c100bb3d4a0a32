// distanceToPath (MeasuredTrace.h): the nearest programmed move to each sample, found through a
// uniform grid of the moves' boxes so that a long trace against a long program costs about one
// cell's moves per sample, not every move.
#include "sim/MeasuredTrace.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace camwb::sim {

namespace {

struct Segment {
    Vec3 a, b;
};

double pointSegment(const Vec3& p, const Segment& s)
{
    const Vec3 d = s.b - s.a;
    const double len2 = d.dot(d);
    const double u = len2 > 0 ? std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return base::distance(p, s.a + d * u);
}

class SegmentGrid {
public:
    explicit SegmentGrid(std::vector<Segment> segments) : m_segments(std::move(segments))
    {
        Vec3 lo = m_segments[0].a, hi = lo;
        for (const Segment& s : m_segments)
            for (const Vec3& v : {s.a, s.b}) {
                lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
                hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
            }
        m_origin = lo;
        const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-3});
        // About as many cells along the largest side as the cube root of the moves, times two.
        const double perSide = std::clamp(2 * std::cbrt(double(m_segments.size())), 1.0, 256.0);
        m_cell = extent / perSide;
        const Vec3 span = hi - lo;
        m_size = {int(span.x / m_cell) + 1, int(span.y / m_cell) + 1, int(span.z / m_cell) + 1};
        for (std::uint32_t i = 0; i < m_segments.size(); ++i) {
            const Segment& s = m_segments[i];
            const auto a = cellOf(s.a), b = cellOf(s.b);
            for (int x = std::min(a[0], b[0]); x <= std::max(a[0], b[0]); ++x)
                for (int y = std::min(a[1], b[1]); y <= std::max(a[1], b[1]); ++y)
                    for (int z = std::min(a[2], b[2]); z <= std::max(a[2], b[2]); ++z)
                        m_cells[key(x, y, z)].push_back(i);
        }
    }

    double nearest(const Vec3& p) const
    {
        const auto c = cellOf(p);
        double best = std::numeric_limits<double>::infinity();
        const int maxRing = std::max({m_size[0], m_size[1], m_size[2]}) + 1;
        for (int r = 0; r <= maxRing; ++r) {
            for (int x = c[0] - r; x <= c[0] + r; ++x)
                for (int y = c[1] - r; y <= c[1] + r; ++y)
                    for (int z = c[2] - r; z <= c[2] + r; ++z) {
                        if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r)
                            continue;  // inner rings were searched already
                        const auto it = m_cells.find(key(x, y, z));
                        if (it != m_cells.end())
                            for (std::uint32_t i : it->second)
                                best = std::min(best, pointSegment(p, m_segments[i]));
                    }
            // Every cell of the next ring lies at least r cells from p (also where p lies outside
            // the grid and its cell was clamped: it is then only farther from them).
            if (best <= r * m_cell)
                break;
        }
        return best;
    }

private:
    std::array<int, 3> cellOf(const Vec3& p) const
    {
        const double v[3] = {p.x - m_origin.x, p.y - m_origin.y, p.z - m_origin.z};
        std::array<int, 3> c{};
        for (int k = 0; k < 3; ++k)
            c[k] = std::clamp(int(std::floor(v[k] / m_cell)), 0, m_size[k] - 1);
        return c;
    }
    static std::int64_t key(int x, int y, int z)
    {
        return (std::int64_t(x) << 42) ^ (std::int64_t(y) << 21) ^ std::int64_t(z);
    }

    std::vector<Segment> m_segments;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> m_cells;
    Vec3 m_origin;
    double m_cell = 1;
    std::array<int, 3> m_size{1, 1, 1};
};

}  // namespace

std::vector<double> distanceToPath(const Trace& trace, const MoveList& program)
{
    std::vector<Segment> segments;
    for (const Move& m : program.moves)
        if (m.moves() && m.positionKnown)
            segments.push_back({m.from, m.to});
    std::vector<double> distances(trace.size(), std::numeric_limits<double>::infinity());
    if (segments.empty())
        return distances;
    const SegmentGrid grid(std::move(segments));
    for (std::size_t k = 0; k < trace.size(); ++k)
        distances[k] = grid.nearest(trace[k].tip);
    return distances;
}

}  // namespace camwb::sim
