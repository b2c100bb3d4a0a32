#include "toolpath/ClArcs.h"

#include "toolpath/ClText.h"

#include <cmath>

namespace camwb::toolpath {

namespace {

constexpr double kPrincipalTolerance = 1e-9;

// Distance of `p` from the line through `center` along the unit vector `n`.
double radialDistance(const Vec3& p, const Vec3& center, const Vec3& n)
{
    const Vec3 d = p - center;
    return (d - n * d.dot(n)).length();
}

}  // namespace

std::optional<Vec3> unitVector(const Vec3& v)
{
    const double length = v.length();
    if (!(length > 1e-12))
        return std::nullopt;
    return v * (1.0 / length);
}

bool isPlusZ(const Vec3& axis) { return std::abs(axis.x) < 1e-7 && std::abs(axis.y) < 1e-7 && axis.z > 0; }

Arc makeArc(const Vec3& start, const Vec3& to, const Vec3& center, const Vec3& axis, bool counterClockwiseAboutAxis,
            int turns, double feed)
{
    Vec3 n = unitVector(axis).value_or(Vec3{0, 0, 1});
    bool clockwise = !counterClockwiseAboutAxis;
    // Exact principal axes keep plane detection in the posts exact; a negative one is the same
    // plane seen from the other side, so it flips together with the direction.
    const double components[3] = {n.x, n.y, n.z};
    for (int i = 0; i < 3; ++i) {
        if (std::abs(std::abs(components[i]) - 1) < kPrincipalTolerance) {
            const double sign = components[i] > 0 ? 1.0 : -1.0;
            n = {i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
            if (sign < 0)
                clockwise = !clockwise;
            break;
        }
    }
    Arc arc;
    arc.to = to;
    arc.center = center + n * (start - center).dot(n);
    arc.normal = n;
    arc.clockwise = clockwise;
    arc.turns = turns;
    arc.feedMmPerMin = feed;
    return arc;
}

std::vector<std::string> arcRadiusProblems(const Vec3& start, const Arc& arc, std::optional<double> radiusMm,
                                           double toleranceMm)
{
    std::vector<std::string> problems;
    const double startRadius = radialDistance(start, arc.center, arc.normal);
    const double endRadius = radialDistance(arc.to, arc.center, arc.normal);
    if (radiusMm) {
        const double r = *radiusMm;
        if (std::abs(startRadius - r) > toleranceMm)
            problems.push_back("the arc starts " + formatForMessage(std::abs(startRadius - r)) +
                               " mm off its circle (radius " + formatForMessage(r) + ")");
        if (std::abs(endRadius - r) > toleranceMm)
            problems.push_back("the arc ends " + formatForMessage(std::abs(endRadius - r)) +
                               " mm off its circle (radius " + formatForMessage(r) + ")");
    } else if (std::abs(startRadius - endRadius) > toleranceMm) {
        problems.push_back("the arc's start and end radii differ by " +
                           formatForMessage(std::abs(startRadius - endRadius)) + " mm (" +
                           formatForMessage(startRadius) + " and " + formatForMessage(endRadius) + ")");
    }
    return problems;
}

}  // namespace camwb::toolpath
