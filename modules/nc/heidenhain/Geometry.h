// Plane geometry of Klartext contour elements: the planned element (a line, or an arc in one of
// the main planes XY, ZX, YZ), its tangents in any of them, and the rounding (RND) of the corner
// between two elements in the XY working plane, each a line or an arc, as the control makes it: an
// arc tangent to both, cutting the corner off.
#pragma once

#include "base/Vec.h"

#include <optional>
#include <string>

namespace camwb::nc::heidenhain {

using base::Vec2;
using base::Vec3;

// A contour element as planned from a block, before it is sent.
struct Element {
    enum class Type { None, Line, Arc } type = Type::None;
    Vec3 start;
    Vec3 end;
    Vec2 center;             // of an arc, in its plane's coordinates (u, v) (nc/detail/PlaneAxes.h)
    int plane = 17;          // of an arc: 17 XY, 18 ZX, 19 YZ
    bool clockwise = false;  // DR-: clockwise seen from the plane's +normal
    int turns = 0;
};

// Unit tangents in the direction of travel at the element's start and end in the coordinates
// (u, v) of `plane` (an arc's helical rise left out); nullopt when the element does not move in it.
std::optional<Vec2> startTangent(const Element& e, int plane = 17);
std::optional<Vec2> endTangent(const Element& e, int plane = 17);

struct Rounding {
    Vec2 from;  // on the first element
    Vec2 to;    // on the second element
    Vec2 center;
    bool clockwise = false;
};

// The arc of `radius` tangent to `a` and `b` (a ends where b starts; arcs in the XY plane only:
// the caller checks), or a reason why there is none (collinear joint, radius too large).
std::optional<Rounding> roundCorner(const Element& a, const Element& b, double radius, std::string& problem);

// Angle in (0, 360] degrees travelled from `from` to `to` about the element's centre in its
// direction (360 when they coincide).
double travelledDegrees(const Element& arc, const Vec2& from, const Vec2& to);

}  // namespace camwb::nc::heidenhain
