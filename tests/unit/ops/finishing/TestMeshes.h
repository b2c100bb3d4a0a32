// Test parts for the drop-cutter and parallel finishing, built procedurally: height fields z =
// f(x, y) triangulated on a grid (planes, steps, drafted pockets, fillets, random bumps), a UV
// sphere (the tool's lower surface grown by the stock, their reference, is in GrownProfile.h).
#pragma once

#include "GrownProfile.h"
#include "sim/ToolShape.h"
#include "sim/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace camwb::ops::test {

// z = f(x, y) over [x0, x1] x [y0, y1] with n x n squares, two triangles each.
inline sim::TriangleMesh gridMesh(const std::function<double(double, double)>& f, double x0, double x1, double y0,
                                  double y1, int n)
{
    sim::TriangleMesh mesh;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = x0 + (x1 - x0) * i / n, y = y0 + (y1 - y0) * j / n;
            mesh.positions.insert(mesh.positions.end(), {float(x), float(y), float(f(x, y))});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            mesh.triangles.insert(mesh.triangles.end(), {a, b, d, a, d, c});
        }
    return mesh;
}

inline sim::TriangleMesh sphereMesh(double radius, int segments)
{
    sim::TriangleMesh mesh;
    const int rings = segments / 2;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double phi = std::numbers::pi * r / rings, theta = 2 * std::numbers::pi * s / segments;
            mesh.positions.insert(mesh.positions.end(),
                                  {float(radius * std::sin(phi) * std::cos(theta)),
                                   float(radius * std::sin(phi) * std::sin(theta)), float(radius * std::cos(phi))});
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = r * segments + s, b = r * segments + (s + 1) % segments, c = a + segments,
                                d = b + segments;
            mesh.triangles.insert(mesh.triangles.end(), {a, c, d, a, d, b});
        }
    return mesh;
}

// A random part as a height field over [0, 40]^2: a drafted pocket (walls at `draftDeg` from
// vertical) with a filleted floor, a boss and a few smooth bumps on the top.
struct RandomPart {
    double pocketX, pocketY, pocketR, depth, draft, fillet;
    double bumps[4][4];  // x, y, height, width
    double operator()(double x, double y) const
    {
        double z = 0;
        for (const auto& b : bumps)
            z += b[2] * std::exp(-((x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1])) / (b[3] * b[3]));
        // The pocket: a round cavity whose wall rises with the draft, the floor rounded by the fillet.
        const double r = std::hypot(x - pocketX, y - pocketY);
        const double slope = 1 / std::tan(draft);
        const double wall = -depth + std::max(0.0, r - pocketR) * slope;  // a drafted cone
        const double rr = r - (pocketR - fillet);                         // fillet at the foot
        double floor = -depth;
        if (rr > 0)
            floor = -depth + fillet -
                    std::sqrt(std::max(0.0, fillet * fillet - std::min(rr, fillet) * std::min(rr, fillet)));
        return std::min(z, std::max(wall, r < pocketR ? floor : wall));
    }
};

inline RandomPart randomPart(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    RandomPart p{};
    p.pocketX = 14 + 12 * u(rng), p.pocketY = 14 + 12 * u(rng), p.pocketR = 4 + 4 * u(rng);
    p.depth = 3 + 4 * u(rng), p.draft = (5 + 25 * u(rng)) * std::numbers::pi / 180, p.fillet = 0.5 + 2 * u(rng);
    for (auto& b : p.bumps)
        b[0] = 40 * u(rng), b[1] = 40 * u(rng), b[2] = -2 + 5 * u(rng), b[3] = 3 + 6 * u(rng);
    return p;
}

inline toolpath::Tool tool(const char* kind, double diameter, double corner = 0, double pointAngle = 0)
{
    toolpath::Tool t;
    t.kind = kind;
    t.diameterMm = diameter;
    t.cornerRadiusMm = corner;
    t.pointAngleDeg = pointAngle;
    t.fluteLengthMm = 30;
    return t;
}

}  // namespace camwb::ops::test
