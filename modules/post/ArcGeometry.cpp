#include "post/ArcGeometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::post {

using toolpath::Vec3;

namespace {

constexpr double kAxisTolerance = 1e-9;   // |normal . axis| within this of 1 counts as principal
constexpr double kPointTolerance = 1e-7;  // mm: start and end this close make a full circle
constexpr double kSweepTolerance = 1e-6;  // radians of slack before a piece counts as too long

Vec3 unit(const Vec3& v)
{
    const double length = v.length();
    return length > 0 ? v * (1.0 / length) : Vec3{0, 0, 1};
}

}  // namespace

std::string arcPlane(const Vec3& normal)
{
    const Vec3 n = unit(normal);
    if (std::abs(std::abs(n.z) - 1) < kAxisTolerance)
        return "XY";
    if (std::abs(std::abs(n.y) - 1) < kAxisTolerance)
        return "ZX";
    if (std::abs(std::abs(n.x) - 1) < kAxisTolerance)
        return "YZ";
    return {};
}

std::vector<ArcPiece> splitArc(const Vec3& start, const toolpath::Arc& arc, double maxSweepDeg)
{
    Vec3 n = unit(arc.normal);
    bool clockwise = arc.clockwise;
    // Seen against -Z, clockwise is counter-clockwise seen against +Z: flip both to the positive axis.
    const std::string plane = arcPlane(n);
    if ((plane == "XY" && n.z < 0) || (plane == "ZX" && n.y < 0) || (plane == "YZ" && n.x < 0)) {
        n = n * -1.0;
        clockwise = !clockwise;
    }
    if (plane == "XY")
        n = {0, 0, 1};
    else if (plane == "ZX")
        n = {0, 1, 0};
    else if (plane == "YZ")
        n = {1, 0, 0};

    const Vec3 s = start - arc.center;
    const Vec3 e = arc.to - arc.center;
    const double axialStart = s.dot(n);
    const double axialEnd = e.dot(n);
    const Vec3 u = s - n * axialStart;  // in-plane radius vectors
    const Vec3 v = e - n * axialEnd;
    const double radiusStart = u.length();
    const double radiusEnd = v.length();
    if (radiusStart < kPointTolerance || radiusEnd < kPointTolerance)
        return {};

    constexpr double twoPi = 2 * std::numbers::pi;
    double sweep;  // radians, positive, in the direction of travel
    if ((u - v).length() < kPointTolerance) {
        sweep = twoPi;
    } else {
        const double ccw = std::atan2(n.dot(u.cross(v)), u.dot(v));  // (-pi, pi], about +n
        sweep = clockwise ? -ccw : ccw;
        if (sweep <= 0)
            sweep += twoPi;
    }
    sweep += twoPi * std::max(0, arc.turns);

    const double maxSweep = std::clamp(maxSweepDeg, 1.0, 360.0) * std::numbers::pi / 180;
    const int count = std::max(1, static_cast<int>(std::ceil((sweep - kSweepTolerance) / maxSweep)));
    const double direction = clockwise ? -1 : 1;
    const Vec3 uUnit = u * (1.0 / radiusStart);
    const Vec3 uPerp = n.cross(uUnit);  // +90 degrees about n
    const bool helical = std::abs(axialEnd - axialStart) > kAxisTolerance;

    std::vector<ArcPiece> pieces;
    pieces.reserve(count);
    Vec3 pieceStart = start;
    for (int i = 1; i <= count; ++i) {
        Vec3 pieceEnd = arc.to;
        if (i < count) {
            const double t = static_cast<double>(i) / count;
            const double angle = direction * sweep * t;
            const double radius = radiusStart + (radiusEnd - radiusStart) * t;
            const double axial = axialStart + (axialEnd - axialStart) * t;
            pieceEnd = arc.center + (uUnit * std::cos(angle) + uPerp * std::sin(angle)) * radius + n * axial;
        }
        pieces.push_back(
            {pieceStart, pieceEnd, arc.center, n, clockwise, sweep / count * 180 / std::numbers::pi, helical});
        pieceStart = pieceEnd;
    }
    return pieces;
}

}  // namespace camwb::post
