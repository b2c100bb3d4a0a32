#include "toolpath/PlaneFrames.h"

#include <cmath>

namespace camwb::toolpath {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// Exact zeros where rounding left a trace, so that a plane along Z or X is written as such.
Vec3 tidy(Vec3 v)
{
    for (double* c : {&v.x, &v.y, &v.z})
        if (std::abs(*c) < 1e-15)
            *c = 0;
    return v;
}

}  // namespace

WorkingPlane planeAlong(const Vec3& normal, const Vec3& origin)
{
    const Vec3 z = normal.normalized();
    const Vec3 reference = std::abs(z.x) > 1 - 1e-9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    const Vec3 x = (reference - z * reference.dot(z)).normalized();
    return {origin, tidy(x), tidy(z)};
}

WorkingPlane planeFromSpatialAngles(double aDeg, double bDeg, double cDeg, const Vec3& origin)
{
    const double ca = std::cos(aDeg * kDeg), sa = std::sin(aDeg * kDeg);
    const double cb = std::cos(bDeg * kDeg), sb = std::sin(bDeg * kDeg);
    const double cc = std::cos(cDeg * kDeg), sc = std::sin(cDeg * kDeg);
    // The first and third columns of Rz(C)·Ry(B)·Rx(A).
    const Vec3 x{cc * cb, sc * cb, -sb};
    const Vec3 z{cc * sb * ca + sc * sa, sc * sb * ca - cc * sa, cb * ca};
    return {origin, tidy(x), tidy(z)};
}

std::array<double, 3> spatialAngles(const WorkingPlane& plane)
{
    const Vec3 x = plane.xAxis, y = plane.yAxis(), z = plane.zAxis;  // the columns of R
    const double cosB = std::hypot(x.x, x.y);
    double a = 0, b = std::atan2(-x.z, cosB), c = 0;
    if (cosB > 1e-9) {
        a = std::atan2(y.z, z.z);
        c = std::atan2(x.y, x.x);
    } else {  // B = ±90: only A ∓ C is fixed; A = 0
        c = std::atan2(-y.x, y.y);
    }
    auto degrees = [](double r) {
        const double d = r / kDeg;
        return std::abs(d) < 1e-12 ? 0.0 : (d <= -180 ? d + 360 : d);
    };
    return {degrees(a), degrees(b), degrees(c)};
}

}  // namespace camwb::toolpath
