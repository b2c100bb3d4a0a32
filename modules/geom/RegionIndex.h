// Many containment and straight-link queries against one set of regions (a pattern's links, its
// entries, zig-zag chaining): the loops are indexed once, so that each query looks at the few
// segments near it instead of at every segment of every loop.
#pragma once

#include "geom/Region.h"

#include <memory>
#include <vector>

namespace camwb::geom {

namespace detail {
class RegionLocator;
}

class RegionIndex {
public:
    // The regions must outlive the index. The queries change nothing: threads may share an index.
    explicit RegionIndex(const std::vector<Region>& regions);
    ~RegionIndex();
    RegionIndex(RegionIndex&&) noexcept;
    RegionIndex& operator=(RegionIndex&&) noexcept;

    const std::vector<Region>& regions() const { return *m_regions; }
    // The answers of anyContains (Region.h) and segmentInside (RegionOps.h), faster.
    bool contains(Vec2 p) const;
    bool segmentInside(Vec2 a, Vec2 b) const;

private:
    const std::vector<Region>* m_regions;
    std::unique_ptr<detail::RegionLocator> m_locator;
};

}  // namespace camwb::geom
