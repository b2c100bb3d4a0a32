// Where the tool is, axis by axis, as far as the CL (or NC) has said. Unknown at the start of a
// program and, for a post, after a tool change; a straight move sets only the axes it gives
// (AxisMask), so the others keep their value, known or not. Every consumer of Rapid/Linear
// follows the moves through this one type instead of inventing the axes a move leaves out.
#pragma once

#include "toolpath/ClRecords.h"

#include <optional>

namespace camwb::toolpath {

// Inline: every move of a million-move program goes through these.
inline double axisValue(const Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }  // 0 X, 1 Y, 2 Z
inline void setAxisValue(Vec3& p, int axis, double value) { (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value; }

class KnownPosition {
public:
    KnownPosition() = default;
    explicit KnownPosition(const Vec3& point) : m_value(point), m_known{AxisMask::kAll} {}

    // The axes in `axes` take their values from `to`; the others stay as they are.
    void moveTo(const Vec3& to, AxisMask axes)
    {
        if (axes.all()) {
            m_value = to;
        } else {
            for (int axis = 0; axis < 3; ++axis) {
                if (axes.has(axis))
                    setAxisValue(m_value, axis, axisValue(to, axis));
            }
        }
        m_known.bits |= axes.bits;
    }
    void moveTo(const Rapid& r) { moveTo(r.to, r.axes); }
    void moveTo(const Linear& l) { moveTo(l.to, l.axes); }
    void set(const Vec3& point) { *this = KnownPosition(point); }
    void forget() { *this = KnownPosition(); }
    void forget(AxisMask axes) { m_known.bits &= static_cast<unsigned char>(~axes.bits); }

    AxisMask known() const { return m_known; }
    bool known(int axis) const { return m_known.has(axis); }
    bool complete() const { return m_known.all(); }
    bool any() const { return !m_known.none(); }
    // The point, when every axis is known.
    std::optional<Vec3> point() const { return complete() ? std::optional<Vec3>(m_value) : std::nullopt; }
    // The values; those of unknown axes mean nothing (0).
    const Vec3& value() const { return m_value; }
    double value(int axis) const { return axisValue(m_value, axis); }

private:
    Vec3 m_value;
    AxisMask m_known{0};
};

// The end of a straight move from `from`: the given axes from the move, the others from `from`;
// nullopt when an axis the move leaves out is unknown there.
std::optional<Vec3> endOf(const KnownPosition& from, const Vec3& to, AxisMask axes);

}  // namespace camwb::toolpath
