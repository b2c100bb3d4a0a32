#include "sim/TriangleMesh.h"

#include "base/AtomicFile.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace camwb::sim {

base::Box3 TriangleMesh::bounds() const
{
    base::Box3 box;
    for (std::size_t i = 0; i < vertexCount(); ++i)
        box.add(vertex(i));
    return box;
}

double TriangleMesh::volumeMm3() const
{
    double sixTimes = 0;
    for (std::size_t t = 0; t < triangleCount(); ++t) {
        const base::Vec3 a = vertex(triangles[3 * t]), b = vertex(triangles[3 * t + 1]),
                         c = vertex(triangles[3 * t + 2]);
        sixTimes += a.dot(b.cross(c));
    }
    return sixTimes / 6;
}

TriangleMesh cylinderMesh(const base::Box3& box, double chordToleranceMm)
{
    TriangleMesh mesh;
    const double r = (box.max.x - box.min.x) / 2;
    if (!(r > 0) || !(box.max.z > box.min.z))
        return mesh;
    const double cx = (box.min.x + box.max.x) / 2, cy = (box.min.y + box.max.y) / 2;
    // The sagitta of a side is r (1 - cos(pi / n)).
    const double half = std::acos(std::clamp(1 - chordToleranceMm / r, -1.0, 1.0));
    const int sides = std::clamp(static_cast<int>(std::ceil(3.14159265358979323846 / std::max(half, 1e-6))), 16, 4096);
    auto add = [&mesh](double x, double y, double z) {
        mesh.positions.insert(mesh.positions.end(), {float(x), float(y), float(z)});
        return static_cast<std::uint32_t>(mesh.vertexCount() - 1);
    };
    const std::uint32_t bottomCentre = add(cx, cy, box.min.z), topCentre = add(cx, cy, box.max.z);
    const std::uint32_t first = static_cast<std::uint32_t>(mesh.vertexCount());
    for (int i = 0; i < sides; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / sides;
        add(cx + r * std::cos(a), cy + r * std::sin(a), box.min.z);
        add(cx + r * std::cos(a), cy + r * std::sin(a), box.max.z);
    }
    for (int i = 0; i < sides; ++i) {
        const std::uint32_t b0 = first + 2 * i, t0 = b0 + 1;
        const std::uint32_t b1 = first + 2 * ((i + 1) % sides), t1 = b1 + 1;
        // Counter-clockwise seen from outside.
        mesh.triangles.insert(mesh.triangles.end(), {b0, b1, t1, b0, t1, t0, bottomCentre, b1, b0, topCentre, t0, t1});
    }
    return mesh;
}

// Binary STL: an 80-byte header, the count, then 50 bytes a triangle (normal, three corners as
// little-endian floats, two attribute bytes). The buffer is sized once and filled in place: a
// cut stock at 0.1 mm has over a million triangles.
base::Status writeStl(const TriangleMesh& mesh, const std::string& path, const std::string& header)
{
    const std::size_t count = mesh.triangleCount();
    std::string out(84 + 50 * count, '\0');
    std::fill_n(out.begin(), 80, ' ');
    std::copy_n(header.begin(), std::min<std::size_t>(header.size(), 80), out.begin());
    const auto count32 = static_cast<std::uint32_t>(count);
    std::memcpy(&out[80], &count32, 4);  // STL is little-endian, as every machine this builds on
    char* at = &out[84];
    for (std::size_t t = 0; t < count; ++t, at += 50) {
        const float* corner[3];
        for (int k = 0; k < 3; ++k)
            corner[k] = &mesh.positions[3 * std::size_t(mesh.triangles[3 * t + k])];
        const base::Vec3 a{corner[0][0], corner[0][1], corner[0][2]}, b{corner[1][0], corner[1][1], corner[1][2]},
            c{corner[2][0], corner[2][1], corner[2][2]};
        const base::Vec3 n = (b - a).cross(c - a).normalized();
        const float normal[3] = {float(n.x), float(n.y), float(n.z)};
        std::memcpy(at, normal, 12);
        for (int k = 0; k < 3; ++k)
            std::memcpy(at + 12 + 12 * k, corner[k], 12);
    }
    return base::writeFileAtomically(path, out);
}

TriangleMesh weldVertices(const TriangleMesh& mesh, double toleranceMm)
{
    // Each vertex joins a kept vertex within the tolerance in its own or a neighbouring grid cell
    // (two copies of one point can fall on either side of a cell boundary), else is kept itself.
    const double cell = std::max(toleranceMm, 1e-9);
    auto key = [](long long i, long long j, long long k) {
        return static_cast<std::uint64_t>(i * 73856093LL ^ j * 19349663LL ^ k * 83492791LL);
    };
    std::unordered_multimap<std::uint64_t, std::uint32_t> cells;
    TriangleMesh out;
    std::vector<std::uint32_t> newIndex(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const base::Vec3 p = mesh.vertex(v);
        const long long ci = std::llround(p.x / cell), cj = std::llround(p.y / cell), ck = std::llround(p.z / cell);
        std::int64_t found = -1;
        for (long long di = -1; di <= 1 && found < 0; ++di)
            for (long long dj = -1; dj <= 1 && found < 0; ++dj)
                for (long long dk = -1; dk <= 1 && found < 0; ++dk) {
                    auto [first, last] = cells.equal_range(key(ci + di, cj + dj, ck + dk));
                    for (auto it = first; it != last; ++it)
                        if (base::distance(out.vertex(it->second), p) <= toleranceMm) {
                            found = it->second;
                            break;
                        }
                }
        if (found < 0) {
            found = static_cast<std::int64_t>(out.vertexCount());
            out.positions.insert(out.positions.end(),
                                 {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]});
            cells.emplace(key(ci, cj, ck), static_cast<std::uint32_t>(found));
        }
        newIndex[v] = static_cast<std::uint32_t>(found);
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t a = newIndex[mesh.triangles[3 * t]], b = newIndex[mesh.triangles[3 * t + 1]],
                            c = newIndex[mesh.triangles[3 * t + 2]];
        if (a != b && b != c && a != c)  // a sliver whose corners merged has no area left
            out.triangles.insert(out.triangles.end(), {a, b, c});
    }
    return out;
}

}  // namespace camwb::sim
