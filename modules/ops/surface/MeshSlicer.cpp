// Mesh slicing in one sweep: triangles sorted by their lowest Z once, levels swept upwards with
// the set of triangles that span the current level. Each spanning triangle gives one segment whose
// ends are keyed by the mesh edge they lie on, so that loops chain by integer keys, not by
// comparing coordinates (the mesh welded by the caller: sim::weldVertices).
#include "ops/surface/MeshSlicer.h"

#include "geom/RegionOps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace camwb::ops::surface {

namespace {

using Key = std::uint64_t;  // an undirected mesh edge: (smaller vertex index << 32) | larger

// One crossing of a level by a triangle, from where the surface goes down through the level to
// where it comes up (travelling so, the material lies on the left).
struct Crossing {
    Key from, to;
    base::Vec2 start;
};

Key edgeKey(std::uint32_t a, std::uint32_t b) { return a < b ? (Key(a) << 32) | b : (Key(b) << 32) | a; }

// What a sweep needs of the mesh: its triangles (dropping those with a repeated index, an index
// out of range or a non-finite Z) and each one's Z range.
struct SweepMesh {
    std::vector<std::uint32_t> tris;  // vertex indices, three per triangle
    std::vector<float> zMin, zMax;
    std::vector<std::uint32_t> byZMin;  // triangles in ascending zMin
};

SweepMesh prepare(const sim::TriangleMesh& mesh)
{
    SweepMesh s;
    const std::size_t n = mesh.vertexCount();
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        if (v[0] >= n || v[1] >= n || v[2] >= n)
            continue;
        const std::uint32_t a = v[0], b = v[1], c = v[2];
        if (a == b || b == c || c == a)
            continue;
        const float za = mesh.positions[3 * a + 2], zb = mesh.positions[3 * b + 2], zc = mesh.positions[3 * c + 2];
        if (!std::isfinite(za) || !std::isfinite(zb) || !std::isfinite(zc))
            continue;
        s.tris.insert(s.tris.end(), {a, b, c});
        s.zMin.push_back(std::min({za, zb, zc}));
        s.zMax.push_back(std::max({za, zb, zc}));
    }
    s.byZMin.resize(s.zMin.size());
    std::iota(s.byZMin.begin(), s.byZMin.end(), 0u);
    std::sort(s.byZMin.begin(), s.byZMin.end(),
              [&](std::uint32_t a, std::uint32_t b) { return s.zMin[a] < s.zMin[b]; });
    return s;
}

// Where the level crosses the edge from `below` (Z <= z) to `above` (Z > z); computed the same
// way from both triangles of the edge.
base::Vec2 crossingPoint(const sim::TriangleMesh& mesh, std::uint32_t below, std::uint32_t above, double z)
{
    const float* p = &mesh.positions[3 * std::size_t(below)];
    const float* q = &mesh.positions[3 * std::size_t(above)];
    const double t = (z - p[2]) / (double(q[2]) - p[2]);
    return {p[0] + t * (double(q[0]) - p[0]), p[1] + t * (double(q[1]) - p[1])};
}

// The triangle's crossing of a level it spans (one vertex or two at Z <= z, the others above;
// a vertex on the level counts as below: the level is taken as infinitesimally above it).
Crossing crossTriangle(const sim::TriangleMesh& mesh, const std::uint32_t* v, double z)
{
    Crossing c{};
    for (int i = 0; i < 3; ++i) {
        const std::uint32_t p = v[i], q = v[(i + 1) % 3];
        const bool pAbove = mesh.positions[3 * std::size_t(p) + 2] > z;
        const bool qAbove = mesh.positions[3 * std::size_t(q) + 2] > z;
        if (pAbove && !qAbove) {  // going down through the level: the segment starts here
            c.from = edgeKey(p, q);
            c.start = crossingPoint(mesh, q, p, z);
        } else if (!pAbove && qAbove) {
            c.to = edgeKey(p, q);
        }
    }
    return c;
}

// Chains the crossings into closed loops: each crossing's `to` edge is the `from` edge of the
// next. A chain that finds no successor (an open or non-manifold mesh) is dropped whole and
// counted, so a hole in the mesh loses that loop rather than giving an open one.
std::vector<std::vector<base::Vec2>> chainLoops(std::vector<Crossing>& crossings, std::size_t& openChains)
{
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.from < b.from; });
    std::vector<char> used(crossings.size(), 0);
    auto successor = [&](Key key) -> std::ptrdiff_t {
        auto it = std::lower_bound(crossings.begin(), crossings.end(), key,
                                   [](const Crossing& c, Key k) { return c.from < k; });
        for (; it != crossings.end() && it->from == key; ++it)
            if (!used[std::size_t(it - crossings.begin())])
                return it - crossings.begin();
        return -1;
    };
    std::vector<std::vector<base::Vec2>> loops;
    for (std::size_t first = 0; first < crossings.size(); ++first) {
        if (used[first])
            continue;
        std::vector<base::Vec2> loop;
        std::size_t at = first;
        bool closed = false;
        for (;;) {
            used[at] = 1;
            if (loop.empty() || !(loop.back() == crossings[at].start))
                loop.push_back(crossings[at].start);  // a level through a vertex repeats it
            if (crossings[at].to == crossings[first].from) {
                closed = true;
                break;
            }
            const std::ptrdiff_t next = successor(crossings[at].to);
            if (next < 0)
                break;
            at = std::size_t(next);
        }
        if (closed && loop.size() > 1 && loop.back() == loop.front())
            loop.pop_back();
        if (!closed)
            ++openChains;
        else if (loop.size() >= 3)
            loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace

std::vector<MeshSection> sliceMesh(const sim::TriangleMesh& mesh, const std::vector<double>& levels)
{
    std::vector<MeshSection> sections(levels.size());
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        sections[i].z = levels[i];
        if (std::isfinite(levels[i]))
            order.push_back(i);
    }
    if (order.empty() || mesh.empty())
        return sections;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return levels[a] < levels[b]; });

    const SweepMesh s = prepare(mesh);
    std::vector<std::uint32_t> active;  // triangles with zMin <= z, those with zMax <= z removed
    std::vector<Crossing> crossings;
    std::size_t next = 0;
    for (const std::size_t level : order) {
        const double z = levels[level];
        for (; next < s.byZMin.size() && s.zMin[s.byZMin[next]] <= z; ++next)
            active.push_back(s.byZMin[next]);
        std::erase_if(active, [&](std::uint32_t t) { return s.zMax[t] <= z; });
        crossings.clear();
        for (const std::uint32_t t : active)
            crossings.push_back(crossTriangle(mesh, &s.tris[3 * std::size_t(t)], z));
        sections[level].loops = chainLoops(crossings, sections[level].openChains);
    }
    return sections;
}

std::vector<geom::Region> sectionRegions(const MeshSection& section, double toleranceMm)
{
    std::vector<geom::Profile> profiles;
    for (const std::vector<base::Vec2>& loop : section.loops) {
        geom::Profile profile;
        for (std::size_t i = 0; i < loop.size(); ++i)
            profile.segments.push_back(geom::Segment::line(loop[i], loop[(i + 1) % loop.size()]));
        profiles.push_back(std::move(profile));
    }
    return geom::regionsFromLoops(profiles, toleranceMm);
}

std::vector<double> flatLevels(const sim::TriangleMesh& mesh, double maxAngleDeg, double minAreaMm2, double toleranceMm)
{
    const double minCos = std::cos(maxAngleDeg * 3.14159265358979323846 / 180);
    struct Flat {
        double z, area;
    };
    std::vector<Flat> flats;
    const std::size_t n = mesh.vertexCount();
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        if (v[0] >= n || v[1] >= n || v[2] >= n)
            continue;
        const base::Vec3 a = mesh.vertex(v[0]), b = mesh.vertex(v[1]), c = mesh.vertex(v[2]);
        const base::Vec3 normal = (b - a).cross(c - a);
        const double twiceArea = normal.length();
        const double zSpan = std::max({a.z, b.z, c.z}) - std::min({a.z, b.z, c.z});
        if (!(twiceArea > 0) || normal.z < minCos * twiceArea || zSpan > toleranceMm)
            continue;
        flats.push_back({(a.z + b.z + c.z) / 3, twiceArea / 2});
    }
    std::sort(flats.begin(), flats.end(), [](const Flat& a, const Flat& b) { return a.z < b.z; });
    // Runs of triangles whose Z follow each other within the tolerance are one floor, at the Z of
    // its largest triangle (exactly the floor's Z where the floor is flat: no averaging error).
    std::vector<double> levels;
    for (std::size_t i = 0; i < flats.size();) {
        std::size_t j = i, largest = i;
        double area = 0;
        for (; j < flats.size() && (j == i || flats[j].z - flats[j - 1].z <= toleranceMm); ++j) {
            area += flats[j].area;
            if (flats[j].area > flats[largest].area)
                largest = j;
        }
        if (area >= minAreaMm2)
            levels.push_back(flats[largest].z);
        i = j;
    }
    return levels;
}

}  // namespace camwb::ops::surface
