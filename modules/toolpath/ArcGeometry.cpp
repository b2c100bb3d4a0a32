#include "toolpath/ArcGeometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace camwb::toolpath {

namespace {

constexpr double kAxisTolerance = 1e-9;   // |normal . axis| within this of 1 counts as principal
constexpr double kPointTolerance = 1e-7;  // mm: start and end this close make a full circle
constexpr double kSweepTolerance = 1e-6;  // radians of slack before a piece counts as too long
constexpr double kTwoPi = 2 * std::numbers::pi;

// A unit vector; a zero one (an arc without a normal) is +Z.
Vec3 unit(const Vec3& v) { return v.length() > 0 ? v.normalized() : Vec3{0, 0, 1}; }

enum class Plane { XY, ZX, YZ, Other };

// Which principal plane a unit normal is the axis of (either sign).
Plane planeOf(const Vec3& n)
{
    if (std::abs(std::abs(n.z) - 1) < kAxisTolerance)
        return Plane::XY;
    if (std::abs(std::abs(n.y) - 1) < kAxisTolerance)
        return Plane::ZX;
    if (std::abs(std::abs(n.x) - 1) < kAxisTolerance)
        return Plane::YZ;
    return Plane::Other;
}

// Angle in (0, 2*pi] from the in-plane radius vector `from` to `to` about the unit normal `n`, in
// the direction of travel; vectors within kPointTolerance of each other are a full turn.
double sweepBetween(const Vec3& from, const Vec3& to, const Vec3& n, bool clockwise)
{
    if ((from - to).length() < kPointTolerance)
        return kTwoPi;
    const double ccw = std::atan2(n.dot(from.cross(to)), from.dot(to));  // (-pi, pi]
    const double sweep = clockwise ? -ccw : ccw;
    return sweep <= 0 ? sweep + kTwoPi : sweep;
}

// An arc as a function of t in [0, 1]: the angle grows linearly in the direction of travel, and
// so do the radius and the height along the normal (a helix, or a spiral when the radii differ).
struct ArcFrame {
    Vec3 center, normal, u, v;  // u: unit radius vector at the start, v = normal x u
    double radiusStart = 0, radiusEnd = 0;
    double axialStart = 0, axialEnd = 0;
    double sweep = 0;        // radians, > 0
    bool wholeTurn = false;  // the sweep is 2 pi or more
    bool clockwise = false;

    Vec3 at(double t) const
    {
        const double angle = (clockwise ? -sweep : sweep) * t;
        const double radius = radiusStart + (radiusEnd - radiusStart) * t;
        const double axial = axialStart + (axialEnd - axialStart) * t;
        return center + (u * std::cos(angle) + v * std::sin(angle)) * radius + normal * axial;
    }
    bool helical() const { return std::abs(axialEnd - axialStart) > kAxisTolerance; }
};

// `withSweep` false leaves sweep 0 (the one trigonometric call), for callers that need only the
// frame and whether the arc is a whole turn.
std::optional<ArcFrame> frameOf(const Vec3& start, const Arc& arc, bool withSweep = true)
{
    ArcFrame f;
    f.center = arc.center;
    f.clockwise = arc.clockwise;
    Vec3 n = unit(arc.normal);
    // Seen against -Z, clockwise is counter-clockwise seen against +Z: flip both to the positive axis.
    const Plane plane = planeOf(n);
    if ((plane == Plane::XY && n.z < 0) || (plane == Plane::ZX && n.y < 0) || (plane == Plane::YZ && n.x < 0)) {
        n = n * -1.0;
        f.clockwise = !f.clockwise;
    }
    if (plane == Plane::XY)
        n = {0, 0, 1};
    else if (plane == Plane::ZX)
        n = {0, 1, 0};
    else if (plane == Plane::YZ)
        n = {1, 0, 0};
    f.normal = n;

    const Vec3 s = start - arc.center;
    const Vec3 e = arc.to - arc.center;
    f.axialStart = s.dot(n);
    f.axialEnd = e.dot(n);
    const Vec3 radialStart = s - n * f.axialStart;  // in-plane radius vectors
    const Vec3 radialEnd = e - n * f.axialEnd;
    f.radiusStart = radialStart.length();
    f.radiusEnd = radialEnd.length();
    if (f.radiusStart < kPointTolerance || f.radiusEnd < kPointTolerance)
        return std::nullopt;

    f.sweep = withSweep ? sweepBetween(radialStart, radialEnd, n, f.clockwise) + kTwoPi * std::max(0, arc.turns) : 0;
    f.wholeTurn = arc.turns > 0 || (radialStart - radialEnd).length() < kPointTolerance;
    f.u = radialStart * (1.0 / f.radiusStart);
    f.v = n.cross(f.u);
    return f;
}

}  // namespace

std::string arcPlane(const Vec3& normal)
{
    switch (planeOf(unit(normal))) {
    case Plane::XY:
        return "XY";
    case Plane::ZX:
        return "ZX";
    case Plane::YZ:
        return "YZ";
    case Plane::Other:
        break;
    }
    return {};
}

double arcSweepDeg(const Vec3& start, const Arc& arc)
{
    const std::optional<ArcFrame> frame = frameOf(start, arc);
    return frame ? frame->sweep * 180 / std::numbers::pi : 0;
}

double arcLength(const Vec3& start, const Arc& arc)
{
    const std::optional<ArcFrame> frame = frameOf(start, arc);
    if (!frame)
        return (arc.to - start).length();
    const double meanRadius = (frame->radiusStart + frame->radiusEnd) / 2;
    return std::hypot(meanRadius * frame->sweep, frame->axialEnd - frame->axialStart);
}

double forwardAngle(const Arc& arc, const Vec3& from, const Vec3& to)
{
    const Vec3 n = unit(arc.normal);
    const Vec3 u = (from - arc.center) - n * (from - arc.center).dot(n);
    const Vec3 w = (to - arc.center) - n * (to - arc.center).dot(n);
    const double sweep = sweepBetween(u, w, n, arc.clockwise);
    return sweep >= kTwoPi ? 0.0 : sweep;
}

Vec3 arcEndTangent(const Arc& arc)
{
    const Vec3 radius = arc.to - arc.center;
    const Vec3 inPlane = radius - arc.normal * radius.dot(arc.normal);
    const Vec3 ccw = arc.normal.cross(inPlane);
    return arc.clockwise ? ccw * -1.0 : ccw;
}

std::vector<ArcPiece> splitArc(const Vec3& start, const Arc& arc, double maxSweepDeg)
{
    const std::optional<ArcFrame> frame = frameOf(start, arc);
    if (!frame)
        return {};
    const double maxSweep = std::clamp(maxSweepDeg, 1.0, 36000.0) * std::numbers::pi / 180;  // helices: many turns
    const int count = std::max(1, static_cast<int>(std::ceil((frame->sweep - kSweepTolerance) / maxSweep)));
    const bool helical = frame->helical();

    std::vector<ArcPiece> pieces;
    pieces.reserve(count);
    Vec3 pieceStart = start;
    for (int i = 1; i <= count; ++i) {
        const double t = static_cast<double>(i) / count;
        const Vec3 pieceEnd = i < count ? frame->at(t) : arc.to;
        const double radius = frame->radiusStart + (frame->radiusEnd - frame->radiusStart) * (i - 1) / count;
        pieces.push_back({pieceStart, pieceEnd, arc.center, frame->normal, frame->clockwise,
                          frame->sweep / count * 180 / std::numbers::pi, radius, helical});
        pieceStart = pieceEnd;
    }
    return pieces;
}

namespace {

// How many chords of `sweep` (radians) on `radius` keep within the tolerance and the step: a
// chord of angle a on radius r strays r (1 - cos(a/2)) from the arc.
int chordCount(double sweep, double radius, double toleranceMm, double maxStepDeg, int maxPoints)
{
    const double tolerance = std::clamp(toleranceMm, 1e-6, radius);
    const double maxStep =
        std::clamp(2 * std::acos(1 - tolerance / radius), 1e-3, std::max(maxStepDeg, 1e-3) * std::numbers::pi / 180);
    const int count = std::max(1, static_cast<int>(std::ceil(sweep / maxStep)));
    return maxPoints > 0 ? std::min(count, maxPoints) : count;
}

}  // namespace

int linearizedPointCount(const Vec3& start, const Arc& arc, double toleranceMm, double maxStepDeg, int maxPoints)
{
    const std::optional<ArcFrame> frame = frameOf(start, arc);
    return frame ? chordCount(frame->sweep, std::max(frame->radiusStart, frame->radiusEnd), toleranceMm, maxStepDeg,
                              maxPoints)
                 : 1;
}

std::vector<Vec3> linearizeArc(const Vec3& start, const Arc& arc, double toleranceMm, double maxStepDeg, int maxPoints)
{
    const std::optional<ArcFrame> frame = frameOf(start, arc);
    if (!frame)
        return {arc.to};
    const int count =
        chordCount(frame->sweep, std::max(frame->radiusStart, frame->radiusEnd), toleranceMm, maxStepDeg, maxPoints);
    std::vector<Vec3> points;
    points.reserve(count);
    for (int i = 1; i < count; ++i)
        points.push_back(frame->at(static_cast<double>(i) / count));
    points.push_back(arc.to);
    return points;
}

void extendByArc(Vec3& min, Vec3& max, const Vec3& start, const Arc& arc)
{
    auto extend = [&min, &max](const Vec3& p) {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    };
    extend(start);
    extend(arc.to);
    const std::optional<ArcFrame> frame = frameOf(start, arc, false);
    if (!frame)
        return;
    const double normal[3] = {frame->normal.x, frame->normal.y, frame->normal.z};
    const double center[3] = {frame->center.x, frame->center.y, frame->center.z};
    const bool principal = std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]) == 1;
    const bool constantRadius = std::abs(frame->radiusStart - frame->radiusEnd) < 1e-12;
    if (!principal || !constantRadius) {
        // Oblique planes (where a helix's rise shifts the extremes) and spirals: sampled every
        // half degree, which misses at most r (1 - cos 0.25 deg) = 1e-5 r.
        const ArcFrame swept = *frameOf(start, arc);
        const int steps = std::max(1, static_cast<int>(std::ceil(swept.sweep / (std::numbers::pi / 360))));
        for (int i = 1; i < steps; ++i)
            extend(swept.at(static_cast<double>(i) / steps));
        return;
    }
    // Most arcs: a principal plane and one radius. An in-plane axis k is extreme where the arc
    // points along +k or -k; whether the arc passes there is a comparison of pseudo-angles measured
    // from the start in the direction of travel, no trigonometry needed. Exact.
    auto pseudoAngle = [](double c, double s) {  // monotonic in the angle of (c, s), in [0, 4)
        if (s >= 0)
            return c >= 0 ? s / (c + s) : 1 - c / (s - c);
        return c < 0 ? 2 - s / (-c - s) : 3 + c / (c - s);
    };
    const bool wholeTurn = frame->wholeTurn;
    const double turn = frame->clockwise ? -1 : 1;  // travel-oriented second axis: turn * v
    const Vec3 end = arc.to - frame->center;
    const double endAngle = pseudoAngle(end.dot(frame->u), turn * end.dot(frame->v));
    const double uk[3] = {frame->u.x, frame->u.y, frame->u.z};
    const double vk[3] = {frame->v.x, frame->v.y, frame->v.z};
    double low[3] = {min.x, min.y, min.z}, high[3] = {max.x, max.y, max.z};
    for (int k = 0; k < 3; ++k) {
        if (normal[k] != 0)
            continue;  // along the axis the extremes are the start and the end
        for (double sign : {1.0, -1.0}) {
            const double angle = pseudoAngle(sign * uk[k], turn * sign * vk[k]);
            if (wholeTurn || angle <= endAngle) {
                const double extreme = center[k] + sign * frame->radiusStart;
                low[k] = std::min(low[k], extreme);
                high[k] = std::max(high[k], extreme);
            }
        }
    }
    min = {low[0], low[1], low[2]};
    max = {high[0], high[1], high[2]};
}

}  // namespace camwb::toolpath
