// Plain 2D/3D vectors in millimetres for the CL model and profiles. Kept tiny (no Eigen) because
// nearly every header includes it; heavy linear algebra uses Eigen inside .cpp files.
#pragma once

#include <array>
#include <cmath>

namespace camwb::base {

struct Vec2 {
    double x = 0, y = 0;

    Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    Vec2 operator*(double s) const { return {x * s, y * s}; }
    Vec2 operator-() const { return {-x, -y}; }
    bool operator==(const Vec2&) const = default;
    double dot(Vec2 o) const { return x * o.x + y * o.y; }
    double cross(Vec2 o) const { return x * o.y - y * o.x; }
    double length() const { return std::hypot(x, y); }
    Vec2 normalized() const
    {
        const double l = length();
        return l > 0 ? Vec2{x / l, y / l} : Vec2{};
    }
    Vec2 leftNormal() const { return {-y, x}; }   // rotated +90 degrees
    Vec2 rightNormal() const { return {y, -x}; }  // rotated -90 degrees
};

struct Vec3 {
    double x = 0, y = 0, z = 0;

    Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    bool operator==(const Vec3&) const = default;
    double dot(Vec3 o) const { return x * o.x + y * o.y + z * o.z; }
    Vec3 cross(Vec3 o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
    double length() const { return std::sqrt(x * x + y * y + z * z); }
    // The unit vector along this one; the zero vector stays zero.
    Vec3 normalized() const
    {
        const double l = length();
        return l > 0 ? *this * (1 / l) : *this;
    }
    // The angle to `o` in radians, 0..pi (atan2: exact for tiny and for nearly opposite angles).
    double angleTo(Vec3 o) const { return std::atan2(cross(o).length(), dot(o)); }
    Vec2 xy() const { return {x, y}; }
};

// Axis-aligned box of the points added to it; empty until the first one.
struct Box3 {
    Vec3 min, max;
    bool empty = true;

    void add(const Vec3& p)
    {
        if (empty) {
            min = max = p;
            empty = false;
            return;
        }
        min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
        max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
    }
};

// The eight corners of the box from `min` to `max` (a box's extent in a turned frame lies within
// the corners turned there).
inline std::array<Vec3, 8> boxCorners(const Vec3& min, const Vec3& max)
{
    std::array<Vec3, 8> out;
    for (int c = 0; c < 8; ++c)
        out[c] = {(c & 1) ? max.x : min.x, (c & 2) ? max.y : min.y, (c & 4) ? max.z : min.z};
    return out;
}

inline double distance(Vec2 a, Vec2 b) { return (a - b).length(); }
inline double distance(Vec3 a, Vec3 b) { return (a - b).length(); }

}  // namespace camwb::base
