#include "toolpath/KnownPosition.h"

namespace camwb::toolpath {

std::optional<Vec3> endOf(const KnownPosition& from, const Vec3& to, AxisMask axes)
{
    KnownPosition end = from;
    end.moveTo(to, axes);
    return end.point();
}

}  // namespace camwb::toolpath
