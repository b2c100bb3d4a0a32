#include "geom/detail/RegionLocator.h"

#include <algorithm>
#include <cmath>

namespace camwb::geom::detail {

namespace {

// The loops a ray from the query point crossed an odd number of times. A band holds few loops,
// so the list stays on the stack (a vector only past kInline loops) and is searched in place.
class OddLoops {
public:
    void toggle(int loop)
    {
        int* items = data();
        for (int k = 0; k < m_size; ++k)
            if (items[k] == loop) {
                items[k] = items[--m_size];
                if (!m_heap.empty())
                    m_heap.pop_back();
                return;
            }
        if (!m_heap.empty()) {
            m_heap.push_back(loop);
        } else if (m_size < kInline) {
            m_inline[m_size] = loop;
        } else {
            m_heap.assign(m_inline, m_inline + kInline);
            m_heap.push_back(loop);
        }
        ++m_size;
    }
    const int* begin() const { return m_heap.empty() ? m_inline : m_heap.data(); }
    const int* end() const { return begin() + m_size; }

private:
    static constexpr int kInline = 32;
    int* data() { return m_heap.empty() ? m_inline : m_heap.data(); }
    int m_inline[kInline];
    std::vector<int> m_heap;
    int m_size = 0;
};

}  // namespace

RegionLocator::RegionLocator(const std::vector<Region>& regions)
{
    for (std::size_t r = 0; r < regions.size(); ++r) {
        auto add = [&](const Profile& loop, bool outer) {
            const int index = static_cast<int>(m_regionOfLoop.size());
            m_regionOfLoop.push_back(static_cast<int>(r));
            m_loopIsOuter.push_back(outer);
            for (const Segment& s : loop.segments)
                m_entries.push_back({&s, boxOf(s), index, 0});
        };
        add(regions[r].outer, true);
        for (const Profile& hole : regions[r].holes)
            add(hole, false);
    }
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
        m_entries[i].firstBin = binOf(box.minY - kOnBoundary);
        for (int b = m_entries[i].firstBin; b <= binOf(box.maxY + kOnBoundary); ++b)
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
    OddLoops odd;
    for (int i : bin) {
        const Entry& e = m_entries[static_cast<std::size_t>(i)];
        if (p.y < e.box.minY || p.y > e.box.maxY || p.x > e.box.maxX)
            continue;
        if (crossingsRight(p, *e.segment) % 2 == 1)
            odd.toggle(e.loop);
    }
    // Inside a region: odd crossings of its outer loop and even crossings of each of its holes.
    return std::any_of(odd.begin(), odd.end(), [&](int outer) {
        const int region = m_regionOfLoop[static_cast<std::size_t>(outer)];
        return m_loopIsOuter[static_cast<std::size_t>(outer)] && std::none_of(odd.begin(), odd.end(), [&](int hole) {
                   return !m_loopIsOuter[static_cast<std::size_t>(hole)] &&
                          m_regionOfLoop[static_cast<std::size_t>(hole)] == region;
               });
    });
}

std::vector<double> RegionLocator::breakpoints(Vec2 a, Vec2 b, bool* touched) const
{
    std::vector<double> ts{0.0, 1.0};
    if (!m_entries.empty()) {
        const Box box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
        const int first = binOf(box.minY - kOnBoundary), last = binOf(box.maxY + kOnBoundary);
        for (int bin = first; bin <= last; ++bin)
            for (int i : m_bins[static_cast<std::size_t>(bin)]) {
                const Entry& e = m_entries[static_cast<std::size_t>(i)];
                // An entry listed in several of these bands is taken in the first of them.
                if (bin == std::max(first, e.firstBin) && e.box.overlaps(box, kOnBoundary))
                    appendCrossings(a, b, *e.segment, ts);
            }
    }
    if (touched)
        *touched = ts.size() > 2;
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end(), [](double x, double y) { return y - x <= 1e-12; }), ts.end());
    return ts;
}

}  // namespace camwb::geom::detail
