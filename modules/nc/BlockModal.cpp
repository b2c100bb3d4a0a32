#include "nc/BlockModal.h"

#include <cstring>

namespace camwb::nc {

bool BlockModal::sameState(const BlockModal& o) const
{
    auto same = [](const char* a, const char* b) { return a == b || std::strcmp(a, b) == 0; };
    return distance == o.distance && same(distanceWord, o.distanceWord) && inch == o.inch &&
           same(unitsWord, o.unitsWord) && plane == o.plane && same(planeWord, o.planeWord) &&
           compensation == o.compensation && same(compensationWord, o.compensationWord) && feedMode == o.feedMode &&
           same(feedModeWord, o.feedModeWord) && workOffset == o.workOffset;
}

}  // namespace camwb::nc
