// Private accelerator for many point and segment queries against one set of regions (clipping
// zig-zag lines, link checks): loop segments bucketed by y, so a containment test or a crossing
// search looks at the few segments in the query's horizontal band instead of all of them. The
// queries keep no scratch in the locator, so any number of threads may ask one locator at once.
#pragma once

#include "geom/Region.h"
#include "geom/detail/LoopQueries.h"

#include <vector>

namespace camwb::geom::detail {

class RegionLocator {
public:
    // The regions must outlive the locator (it keeps pointers to their segments).
    explicit RegionLocator(const std::vector<Region>& regions);

    // Same answer as anyContains(regions, p) (points on a loop count as inside).
    bool contains(Vec2 p) const;
    // Sorted parameters in [0, 1], 0 and 1 included, where the segment a-b meets a loop (and so
    // may change side). `touched`: it meets some loop, at an end too.
    std::vector<double> breakpoints(Vec2 a, Vec2 b, bool* touched = nullptr) const;

private:
    struct Entry {
        const Segment* segment;
        Box box;
        int loop;
        int firstBin;  // the lowest band it is listed in: a query over several bands takes it there
    };
    int binOf(double y) const;

    std::vector<Entry> m_entries;
    std::vector<int> m_regionOfLoop;
    std::vector<bool> m_loopIsOuter;
    std::vector<std::vector<int>> m_bins;  // entry indices per horizontal band
    double m_minY = 0, m_maxY = 0, m_binHeight = 1;
};

// Whether the segment a-b lies within the regions, given the sorted parameters `ts` (0 and 1
// included) where it meets their loops: the middle of every piece between them and both ends
// inside (touching a loop counts as inside).
template <class Contains> bool segmentWithin(Vec2 a, Vec2 b, const std::vector<double>& ts, Contains contains)
{
    for (std::size_t i = 0; i + 1 < ts.size(); ++i)
        if (ts[i + 1] - ts[i] > 1e-12 && !contains(a + (b - a) * (0.5 * (ts[i] + ts[i + 1]))))
            return false;
    return contains(a) && contains(b);
}

}  // namespace camwb::geom::detail
