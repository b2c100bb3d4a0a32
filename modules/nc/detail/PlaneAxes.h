// The three main planes of circular motion as their in-plane axes u, v and normal w (0 X, 1 Y,
// 2 Z) with u x v = w, so a turn from u towards v is counter-clockwise seen from +w (G3, DR+) and
// u is the 0-degree axis of polar angles: XY (G17) X, Y about Z; ZX (G18) Z, X about Y; YZ (G19)
// Y, Z about X. Shared by the interpreters that trace arcs in all three planes.
#pragma once

#include "base/Vec.h"

namespace camwb::nc::detail {

struct PlaneAxes {
    int u = 0, v = 1, w = 2;
    base::Vec3 normal{0, 0, 1};
};

// The plane of G17, G18 or G19 (17, 18, 19; anything else is XY).
constexpr PlaneAxes planeAxes(int plane)
{
    if (plane == 18)
        return {2, 0, 1, {0, 1, 0}};
    if (plane == 19)
        return {1, 2, 0, {1, 0, 0}};
    return {0, 1, 2, {0, 0, 1}};
}

inline double component(const base::Vec3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
inline void setComponent(base::Vec3& p, int axis, double value) { (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value; }

// `p` in the plane's coordinates (u, v), and `p` with its u and v replaced by `q`.
inline base::Vec2 inPlane(const base::Vec3& p, const PlaneAxes& a) { return {component(p, a.u), component(p, a.v)}; }
inline base::Vec3 withInPlane(base::Vec3 p, const PlaneAxes& a, base::Vec2 q)
{
    setComponent(p, a.u, q.x);
    setComponent(p, a.v, q.y);
    return p;
}

}  // namespace camwb::nc::detail
