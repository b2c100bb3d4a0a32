#include "geom/RegionIndex.h"

#include "geom/detail/RegionLocator.h"

namespace camwb::geom {

RegionIndex::RegionIndex(const std::vector<Region>& regions) :
    m_regions(&regions),
    m_locator(std::make_unique<detail::RegionLocator>(regions))
{
}

RegionIndex::~RegionIndex() = default;
RegionIndex::RegionIndex(RegionIndex&&) noexcept = default;
RegionIndex& RegionIndex::operator=(RegionIndex&&) noexcept = default;

bool RegionIndex::contains(Vec2 p) const { return m_locator->contains(p); }

bool RegionIndex::segmentInside(Vec2 a, Vec2 b) const
{
    return detail::segmentWithin(a, b, m_locator->breakpoints(a, b), [this](Vec2 p) { return contains(p); });
}

}  // namespace camwb::geom
