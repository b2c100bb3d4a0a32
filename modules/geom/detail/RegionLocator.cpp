#include "geom/detail/RegionLocator.h"

#include <algorithm>
#include <cmath>

namespace camwb::geom::detail {

RegionLocator::RegionLocator(const std::vector<Region>& regions)
{
    for (std::size_t r = 0; r < regions.size(); ++r) {
        auto add = [&](const Profile& loop, bool outer) {
            const int index = static_cast<int>(m_regionOfLoop.size());
            m_regionOfLoop.push_back(static_cast<int>(r));
            m_loopIsOuter.push_back(outer);
            for (const Segment& s : loop.segments)
                m_entries.push_back({&s, boxOf(s), index});
        };
        add(regions[r].outer, true);
        for (const Profile& hole : regions[r].holes)
            add(hole, false);
    }
    m_crossings.assign(m_regionOfLoop.size(), 0);
    m_seen.assign(m_entries.size(), 0);
    if (m_entries.empty())
        return;
    m_minY = m_maxY = m_entries.front().box.minY;
    for (const Entry& e : m_entries) {
        m_minY = std::min(m_minY, e.box.minY);
        m_maxY = std::max(m_maxY, e.box.maxY);
    }
    m_minY -= kOnBoundary;
    m_maxY += kOnBoundary;
    const int binCount = static_cast<int>(std::clamp<std::size_t>(m_entries.size() / 2, 1, 4096));
    m_binHeight = std::max((m_maxY - m_minY) / binCount, 1e-9);
    m_bins.resize(static_cast<std::size_t>(binCount));
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const Box& box = m_entries[i].box;
        for (int b = binOf(box.minY - kOnBoundary); b <= binOf(box.maxY + kOnBoundary); ++b)
            m_bins[static_cast<std::size_t>(b)].push_back(static_cast<int>(i));
    }
}

int RegionLocator::binOf(double y) const
{
    const double bin = std::floor((y - m_minY) / m_binHeight);
    return static_cast<int>(std::clamp(bin, 0.0, static_cast<double>(m_bins.size() - 1)));
}

bool RegionLocator::contains(Vec2 p) const
{
    if (m_entries.empty() || !(p.y >= m_minY && p.y <= m_maxY))
        return false;
    const std::vector<int>& bin = m_bins[static_cast<std::size_t>(binOf(p.y))];
    for (int i : bin)
        if (nearSegment(p, *m_entries[static_cast<std::size_t>(i)].segment))
            return true;
    m_touchedLoops.clear();
    for (int i : bin) {
        const Entry& e = m_entries[static_cast<std::size_t>(i)];
        if (p.y < e.box.minY || p.y > e.box.maxY || p.x > e.box.maxX)
            continue;
        if (const int n = crossingsRight(p, *e.segment)) {
            if (m_crossings[static_cast<std::size_t>(e.loop)] == 0)
                m_touchedLoops.push_back(e.loop);
            m_crossings[static_cast<std::size_t>(e.loop)] += n;
        }
    }
    // Inside a region: odd crossings of its outer loop and even crossings of each of its holes.
    std::vector<int> candidates, excluded;
    for (int loop : m_touchedLoops) {
        const auto l = static_cast<std::size_t>(loop);
        if (m_crossings[l] % 2 == 1)
            (m_loopIsOuter[l] ? candidates : excluded).push_back(m_regionOfLoop[l]);
        m_crossings[l] = 0;
    }
    return std::any_of(candidates.begin(), candidates.end(), [&](int region) {
        return std::find(excluded.begin(), excluded.end(), region) == excluded.end();
    });
}

std::vector<double> RegionLocator::breakpoints(Vec2 a, Vec2 b, bool* touched) const
{
    std::vector<double> ts{0.0, 1.0};
    if (!m_entries.empty()) {
        const Box box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
        if (++m_query == 0) {
            std::fill(m_seen.begin(), m_seen.end(), 0);
            m_query = 1;
        }
        const int last = binOf(box.maxY + kOnBoundary);
        for (int bin = binOf(box.minY - kOnBoundary); bin <= last; ++bin)
            for (int i : m_bins[static_cast<std::size_t>(bin)]) {
                const auto index = static_cast<std::size_t>(i);
                if (m_seen[index] == m_query)
                    continue;
                m_seen[index] = m_query;
                if (m_entries[index].box.overlaps(box, kOnBoundary))
                    appendCrossings(a, b, *m_entries[index].segment, ts);
            }
    }
    if (touched)
        *touched = ts.size() > 2;
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end(), [](double x, double y) { return y - x <= 1e-12; }), ts.end());
    return ts;
}

}  // namespace camwb::geom::detail
