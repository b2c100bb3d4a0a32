#include "nc/detail/CompensationGeometry.h"

#include "base/NumberFormat.h"
#include "geom/CarrierIntersection.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::detail {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Vec2 arcTangentAt(const CompElement& e, Vec2 p)
{
    const Vec2 radial = (p - e.center).normalized();
    return e.clockwise ? radial.rightNormal() : radial.leftNormal();
}

}  // namespace

Vec2 startTangent(const CompElement& e) { return e.arc ? arcTangentAt(e, e.start) : (e.end - e.start).normalized(); }

Vec2 endTangent(const CompElement& e) { return e.arc ? arcTangentAt(e, e.end) : (e.end - e.start).normalized(); }

Vec2 sideNormal(Vec2 tangent, bool left) { return left ? tangent.leftNormal() : tangent.rightNormal(); }

bool toolInsideArc(const CompElement& arc, bool left) { return left != arc.clockwise; }

std::optional<geom::Segment> offsetElement(const CompElement& e, bool left, double radius)
{
    if (!e.arc) {
        const Vec2 n = sideNormal(startTangent(e), left) * radius;
        return geom::Segment::line(e.start + n, e.end + n);
    }
    const double r = distance(e.start, e.center);
    const double offset = toolInsideArc(e, left) ? r - radius : r + radius;
    if (!(offset > 1e-9) || r <= 0)
        return std::nullopt;
    const double k = offset / r;
    return geom::Segment::arc(e.center + (e.start - e.center) * k, e.center + (e.end - e.center) * k, e.center,
                              !e.clockwise);
}

CornerKind classifyCorner(const CompElement& before, const CompElement& after, bool left, double tangentTolerance,
                          bool reversalOutsideArcIsInside, double* turnOut)
{
    const Vec2 a = endTangent(before), b = startTangent(after);
    const double turn = std::atan2(a.cross(b), a.dot(b));
    if (turnOut)
        *turnOut = turn;
    if (std::abs(turn) <= tangentTolerance)
        return CornerKind::Tangent;
    // A reversal (turn of pi) goes around the vertex on the outside, whichever way it turns.
    if (std::abs(turn) >= std::numbers::pi - tangentTolerance) {
        const CompElement* arc = after.arc ? &after : before.arc ? &before : nullptr;
        if (reversalOutsideArcIsInside && arc && !toolInsideArc(*arc, left))
            return CornerKind::Inside;
        return CornerKind::Outside;
    }
    const bool towardsTool = left ? turn > 0 : turn < 0;
    return towardsTool ? CornerKind::Inside : CornerKind::Outside;
}

std::optional<Vec2> cornerPoint(const CompElement& before, const CompElement& after, bool left, double radius,
                                bool inside)
{
    const auto a = offsetElement(before, left, radius);
    const auto b = offsetElement(after, left, radius);
    if (!a || !b)
        return std::nullopt;
    // Of two crossings (a circle), the one on the right side of the vertex: at a right-angled
    // corner this guess is the crossing itself; at a reversal it still tells back from ahead.
    const Vec2 tBefore = endTangent(before), tAfter = startTangent(after);
    const Vec2 along = inside ? tAfter - tBefore : tBefore - tAfter;
    const Vec2 near = before.end + (sideNormal(tBefore, left) + sideNormal(tAfter, left) + along) * (radius / 2);
    return geom::intersectCarriers(*a, *b, near);
}

double arcTravel(Vec2 center, Vec2 from, Vec2 to, bool clockwise)
{
    const Vec2 a = from - center, b = to - center;
    double angle = std::atan2(a.cross(b), a.dot(b));
    if (clockwise)
        angle = -angle;
    if (angle < 0)
        angle += kTwoPi;
    return angle;
}

bool keepsDirection(const CompElement& offset, const CompElement& programmed, Vec2 newEnd)
{
    // A line trimmed to nothing still goes nowhere backwards (LinuxCNC accepts it too).
    if (!offset.arc)
        return (newEnd - offset.start).dot(programmed.end - programmed.start) >= -1e-12;
    if (offset.fullCircle())
        return true;
    const double sweep = arcTravel(offset.center, offset.start, offset.end, offset.clockwise);
    const double travel = arcTravel(offset.center, offset.start, newEnd, offset.clockwise);
    return travel <= sweep + 1e-9 || travel >= 2 * std::numbers::pi - 1e-12;
}

std::string formatPoint(Vec2 p)
{
    const base::NumberFormat f{3, false};
    return "(" + f.format(p.x) + ", " + f.format(p.y) + ")";
}

}  // namespace camwb::nc::detail
