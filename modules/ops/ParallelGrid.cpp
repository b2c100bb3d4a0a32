#include "ops/ParallelGrid.h"

#include "geom/Region.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kNone = -std::numeric_limits<double>::infinity();
}  // namespace

ParallelGrid::ParallelGrid(const SurfaceInput& input, const ParallelParams& params, double toolRadius) : m_input(input)
{
    const double a = params.angleDeg * kPi / 180;
    m_u = {std::cos(a), std::sin(a)};
    m_v = {-m_u.y, m_u.x};
    const base::Box3& box = input.stock;
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for (double x : {box.min.x, box.max.x})
        for (double y : {box.min.y, box.max.y}) {
            const base::Vec2 p{x, y};
            u0 = std::min(u0, p.dot(m_u)), u1 = std::max(u1, p.dot(m_u));
            v0 = std::min(v0, p.dot(m_v)), v1 = std::max(v1, p.dot(m_v));
        }
    // Lines at both edges and evenly between; samples close enough that a ball's surface between
    // two of them bulges by well under the tolerance (refineCut bisects where it does not).
    m_lines = 1 + std::max(1, int(std::ceil((v1 - v0) / params.stepoverMm - 1e-9)));
    m_dv = (v1 - v0) / (m_lines - 1);
    const double wanted = std::clamp(std::sqrt(2 * toolRadius * params.toleranceMm), 0.005, params.stepoverMm);
    m_samples = 1 + std::max(1, int(std::ceil((u1 - u0) / wanted - 1e-9)));
    m_du = (u1 - u0) / (m_samples - 1);
    m_u0 = u0, m_v0 = v0;
    m_maxSlope =
        params.maxSlopeDeg >= 90 ? std::numeric_limits<double>::infinity() : std::tan(params.maxSlopeDeg * kPi / 180);
}

base::Vec2 ParallelGrid::xy(int line, int sample) const
{
    return m_u * (m_u0 + m_du * sample) + m_v * (m_v0 + m_dv * line);
}

bool ParallelGrid::inside(base::Vec2 p) const
{
    const base::Box3& b = m_input.stock;
    constexpr double e = 1e-9;
    if (p.x < b.min.x - e || p.x > b.max.x + e || p.y < b.min.y - e || p.y > b.max.y + e)
        return false;
    return m_input.boundary.empty() || geom::anyContains(m_input.boundary, p);
}

base::Vec3 ParallelGrid::point(int line, int sample) const
{
    const base::Vec2 p = xy(line, sample);
    return {p.x, p.y, z(line, sample)};
}

bool ParallelGrid::drop(const surface::DropCutter& cutter, const std::function<bool(double)>& step)
{
    m_z.assign(std::size_t(m_lines) * m_samples, kNone);
    m_in.assign(std::size_t(m_lines) * m_samples, 0);
    m_top = kNone;
    constexpr int kBatch = 8;  // lines per batch between progress reports
    for (int first = 0; first < m_lines; first += kBatch) {
        std::vector<base::Vec2> points;
        std::vector<std::size_t> where;
        for (int line = first; line < std::min(m_lines, first + kBatch); ++line)
            for (int m = 0; m < m_samples; ++m)
                if (const base::Vec2 p = xy(line, m); inside(p)) {
                    points.push_back(p);
                    where.push_back(std::size_t(line) * m_samples + m);
                    m_in[where.back()] = 1;
                }
        const std::vector<double> zs = cutter.dropZ(points, kNone);
        for (std::size_t i = 0; i < zs.size(); ++i) {
            m_z[where[i]] = zs[i];
            m_top = std::max(m_top, zs[i]);
        }
        if (!step(double(std::min(m_lines, first + kBatch)) / m_lines))
            return false;
    }
    return true;
}

double ParallelGrid::slope(int line, int sample) const
{
    const double here = z(line, sample);
    auto gentle = [&](double before, double after, double spacing) {
        const double b = (here - before) / spacing, a = (after - here) / spacing;
        const bool hasB = before != kNone, hasA = after != kNone;
        if (hasA && hasB)
            return (a > 0) != (b > 0) ? 0.0 : std::min(std::abs(a), std::abs(b));
        return hasA ? std::abs(a) : hasB ? std::abs(b) : 0.0;
    };
    const double su =
        gentle(sample > 0 ? z(line, sample - 1) : kNone, sample + 1 < m_samples ? z(line, sample + 1) : kNone, m_du);
    const double sv = m_lines > 1 ? gentle(line > 0 ? z(line - 1, sample) : kNone,
                                           line + 1 < m_lines ? z(line + 1, sample) : kNone, m_dv)
                                  : 0.0;
    return std::hypot(su, sv);
}

base::Vec2 ParallelGrid::edge(base::Vec2 in, base::Vec2 out) const
{
    for (int i = 0; i < 40 && (out - in).length() > 1e-6; ++i) {
        const base::Vec2 mid = (in + out) * 0.5;
        (inside(mid) ? in : out) = mid;
    }
    return in;
}

std::vector<ParallelGrid::Run> ParallelGrid::cutRuns(int line) const
{
    std::vector<Run> runs;
    int from = -1;
    for (int m = 0; m <= m_samples; ++m) {
        const bool cuts = m < m_samples && z(line, m) != kNone && slope(line, m) <= m_maxSlope * (1 + 1e-9);
        if (cuts && from < 0)
            from = m;
        if (cuts || from < 0)
            continue;
        Run run{from, m - 1};
        if (from > 0 && outside(line, from - 1))
            run.before = edge(xy(line, from), xy(line, from - 1));
        if (m < m_samples && outside(line, m))
            run.after = edge(xy(line, m - 1), xy(line, m));
        if (run.to > run.from || run.before || run.after)
            runs.push_back(run);
        from = -1;
    }
    return runs;
}

}  // namespace camwb::ops
