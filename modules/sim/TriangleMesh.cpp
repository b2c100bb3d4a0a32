#include "sim/TriangleMesh.h"

#include "base/AtomicFile.h"

#include <algorithm>
#include <cstring>

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

}  // namespace camwb::sim
