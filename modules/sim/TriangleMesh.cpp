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

namespace {

void putFloat(std::string& out, float value)
{
    char bytes[4];
    std::memcpy(bytes, &value, 4);  // STL is little-endian, as every machine this builds on
    out.append(bytes, 4);
}

}  // namespace

base::Status writeStl(const TriangleMesh& mesh, const std::string& path, const std::string& header)
{
    std::string out(80, ' ');
    std::copy_n(header.begin(), std::min<std::size_t>(header.size(), 80), out.begin());
    const auto count = static_cast<std::uint32_t>(mesh.triangleCount());
    char countBytes[4];
    std::memcpy(countBytes, &count, 4);
    out.append(countBytes, 4);
    out.reserve(out.size() + std::size_t(count) * 50);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const base::Vec3 a = mesh.vertex(mesh.triangles[3 * t]), b = mesh.vertex(mesh.triangles[3 * t + 1]),
                         c = mesh.vertex(mesh.triangles[3 * t + 2]);
        const base::Vec3 n = (b - a).cross(c - a).normalized();
        for (const base::Vec3& v : {n, a, b, c}) {
            putFloat(out, float(v.x));
            putFloat(out, float(v.y));
            putFloat(out, float(v.z));
        }
        out.append(2, '\0');
    }
    return base::writeFileAtomically(path, out);
}

}  // namespace camwb::sim
