#include "toolpath/KnownPosition.h"

namespace camwb::toolpath {

double axisValue(const Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

void setAxisValue(Vec3& p, int axis, double value) { (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value; }

const char* axisName(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

void KnownPosition::moveTo(const Vec3& to, AxisMask axes)
{
    for (int axis = 0; axis < 3; ++axis) {
        if (axes.has(axis))
            setAxisValue(m_value, axis, axisValue(to, axis));
    }
    m_known.bits |= axes.bits;
}

std::optional<Vec3> KnownPosition::point() const
{
    if (!complete())
        return std::nullopt;
    return m_value;
}

std::optional<Vec3> endOf(const KnownPosition& from, const Vec3& to, AxisMask axes)
{
    KnownPosition end = from;
    end.moveTo(to, axes);
    return end.point();
}

}  // namespace camwb::toolpath
