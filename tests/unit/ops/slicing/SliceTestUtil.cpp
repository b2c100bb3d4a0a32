// Analytic test meshes (surfaces of revolution about Z) and loop distances for the slicing tests.
#include "SliceTestUtil.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::ops::surface::test {

namespace {

constexpr double kPi = std::numbers::pi;

struct RZ {
    double r, z;
};

// The profile (r, z) turned about Z: a point with r == 0 is one vertex (a pole), any other a ring
// of `segments`. A profile running counter-clockwise in the (r, z) plane gives outward normals;
// `closed` joins its last point to its first (a torus).
sim::TriangleMesh revolve(const std::vector<RZ>& profile, bool closed, int segments, base::Vec3 centre = {})
{
    sim::TriangleMesh mesh;
    std::vector<std::uint32_t> first;  // first vertex of each profile point's ring
    for (const RZ& p : profile) {
        first.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
        const int count = p.r == 0 ? 1 : segments;
        for (int j = 0; j < count; ++j) {
            const double a = 2 * kPi * j / segments;
            mesh.positions.insert(mesh.positions.end(), {float(centre.x + p.r * std::cos(a)),
                                                         float(centre.y + p.r * std::sin(a)), float(centre.z + p.z)});
        }
    }
    auto vertex = [&](std::size_t k, int j) { return profile[k].r == 0 ? first[k] : first[k] + j % segments; };
    const std::size_t bands = closed ? profile.size() : profile.size() - 1;
    for (std::size_t k = 0; k < bands; ++k) {
        const std::size_t l = (k + 1) % profile.size();
        for (int j = 0; j < segments; ++j) {
            const std::uint32_t a = vertex(k, j), b = vertex(k, j + 1), c = vertex(l, j + 1), d = vertex(l, j);
            if (a != b)
                mesh.triangles.insert(mesh.triangles.end(), {a, b, c});
            if (c != d)
                mesh.triangles.insert(mesh.triangles.end(), {a, c, d});
        }
    }
    return mesh;
}

sim::TriangleMesh asSoup(const sim::TriangleMesh& mesh)
{
    sim::TriangleMesh soup;
    for (const std::uint32_t v : mesh.triangles) {
        soup.triangles.push_back(static_cast<std::uint32_t>(soup.vertexCount()));
        soup.positions.insert(soup.positions.end(), mesh.positions.begin() + 3 * v, mesh.positions.begin() + 3 * v + 3);
    }
    return soup;
}

double pointToSegment(base::Vec2 p, base::Vec2 a, base::Vec2 b)
{
    const base::Vec2 ab = b - a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
}

}  // namespace

sim::TriangleMesh sphereMesh(base::Vec3 centre, double radius, int rings, int segments, bool soup)
{
    std::vector<RZ> profile;
    for (int i = 0; i <= rings; ++i) {
        const double phi = kPi * i / rings;
        profile.push_back({i == 0 || i == rings ? 0.0 : radius * std::sin(phi), -radius * std::cos(phi)});
    }
    const sim::TriangleMesh mesh = revolve(profile, false, segments, centre);
    return soup ? asSoup(mesh) : mesh;
}

sim::TriangleMesh frustumMesh(double r0, double z0, double r1, double z1, int segments, int bands)
{
    std::vector<RZ> profile{{0, z0}};
    for (int i = 0; i <= bands; ++i)
        profile.push_back({r0 + (r1 - r0) * i / bands, z0 + (z1 - z0) * i / bands});
    profile.push_back({0, z1});
    return revolve(profile, false, segments);
}

sim::TriangleMesh torusMesh(double major, double minor, int around, int tube)
{
    std::vector<RZ> profile;
    for (int i = 0; i < tube; ++i) {
        const double a = 2 * kPi * i / tube;
        profile.push_back({major + minor * std::cos(a), minor * std::sin(a)});
    }
    return revolve(profile, true, around);
}

sim::TriangleMesh withoutTriangles(const sim::TriangleMesh& mesh, std::size_t first, std::size_t count)
{
    sim::TriangleMesh open = mesh;
    open.triangles.erase(open.triangles.begin() + 3 * first, open.triangles.begin() + 3 * (first + count));
    return open;
}

double oneSidedDistance(const Loops& from, const Loops& to)
{
    // The segments of `to` in a grid of cells about as large as a segment is long on average, so
    // that a point looks at the cells around it ring by ring until no nearer segment can remain.
    struct Seg {
        base::Vec2 a, b;
    };
    std::vector<Seg> segs;
    base::Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi = -lo;
    for (const auto& loop : to)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            segs.push_back({loop[i], loop[(i + 1) % loop.size()]});
            lo = {std::min(lo.x, loop[i].x), std::min(lo.y, loop[i].y)};
            hi = {std::max(hi.x, loop[i].x), std::max(hi.y, loop[i].y)};
        }
    if (segs.empty())
        return from.empty() || from.front().empty() ? 0.0 : std::numeric_limits<double>::infinity();
    const double cell = std::max({perimeter(to) / segs.size(), (hi.x - lo.x + hi.y - lo.y) / 2048, 1e-6});
    const int nx = int((hi.x - lo.x) / cell) + 1, ny = int((hi.y - lo.y) / cell) + 1;
    std::vector<std::vector<std::uint32_t>> grid(std::size_t(nx) * ny);
    auto cellOf = [&](double v, double origin, int n) { return std::clamp(int((v - origin) / cell), 0, n - 1); };
    for (std::size_t i = 0; i < segs.size(); ++i)
        for (int x = cellOf(std::min(segs[i].a.x, segs[i].b.x), lo.x, nx);
             x <= cellOf(std::max(segs[i].a.x, segs[i].b.x), lo.x, nx); ++x)
            for (int y = cellOf(std::min(segs[i].a.y, segs[i].b.y), lo.y, ny);
                 y <= cellOf(std::max(segs[i].a.y, segs[i].b.y), lo.y, ny); ++y)
                grid[std::size_t(y) * nx + x].push_back(std::uint32_t(i));
    double worst = 0;
    for (const auto& loop : from)
        for (const base::Vec2 p : loop) {
            const int cx = cellOf(p.x, lo.x, nx), cy = cellOf(p.y, lo.y, ny);
            // Cells outside the grid hold nothing; a point outside it is that much farther away.
            const double outside =
                std::hypot(std::max({lo.x - p.x, p.x - hi.x, 0.0}), std::max({lo.y - p.y, p.y - hi.y, 0.0}));
            double nearest = std::numeric_limits<double>::infinity();
            for (int ring = 0; ring <= std::max(nx, ny) && nearest > std::max(outside, (ring - 1) * cell); ++ring)
                for (int y = cy - ring; y <= cy + ring; ++y)
                    for (int x = cx - ring; x <= cx + ring; ++x) {
                        if (x < 0 || y < 0 || x >= nx || y >= ny ||
                            (std::abs(x - cx) != ring && std::abs(y - cy) != ring))
                            continue;
                        for (const std::uint32_t i : grid[std::size_t(y) * nx + x])
                            nearest = std::min(nearest, pointToSegment(p, segs[i].a, segs[i].b));
                    }
            worst = std::max(worst, nearest);
        }
    return worst;
}

double hausdorff(const Loops& a, const Loops& b) { return std::max(oneSidedDistance(a, b), oneSidedDistance(b, a)); }

double signedArea(const std::vector<base::Vec2>& loop)
{
    double twice = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        twice += loop[i].cross(loop[(i + 1) % loop.size()]);
    return twice / 2;
}

double signedArea(const Loops& loops)
{
    double sum = 0;
    for (const auto& loop : loops)
        sum += signedArea(loop);
    return sum;
}

double perimeter(const Loops& loops)
{
    double sum = 0;
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i)
            sum += distance(loop[i], loop[(i + 1) % loop.size()]);
    return sum;
}

}  // namespace camwb::ops::surface::test
