// Small builders for the stock tests: tools, moves, box meshes, an STL reader (reading STL is
// occ's in the product; the tests only need the volume back) and a closedness check.
#pragma once

#include "sim/Moves.h"
#include "sim/Stock.h"
#include "sim/TriangleMesh.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <utility>

namespace camwb::sim::test {

inline toolpath::Tool makeTool(const std::string& kind, double diameter, double corner = 0, double flute = 30,
                               double length = 40, const std::string& holder = "ER32")
{
    toolpath::Tool t;
    t.kind = kind;
    t.diameterMm = diameter;
    t.cornerRadiusMm = corner;
    t.fluteLengthMm = flute;
    t.lengthMm = length;
    t.holder = holder;
    return t;
}

inline Move makeMove(Vec3 from, Vec3 to, MoveKind kind = MoveKind::Feed)
{
    Move m;
    m.from = from;
    m.to = to;
    m.kind = kind;
    m.feedMmPerMin = 1000;
    return m;
}

// The box from `lo` to `hi`.
inline base::Box3 box(Vec3 lo, Vec3 hi)
{
    base::Box3 b;
    b.add(lo);
    b.add(hi);
    return b;
}

// A closed box, outward-facing.
inline TriangleMesh boxMesh(Vec3 lo, Vec3 hi)
{
    TriangleMesh m;
    for (const Vec3& c : base::boxCorners(lo, hi))
        m.positions.insert(m.positions.end(), {float(c.x), float(c.y), float(c.z)});
    // Corner c has bit 0 = x, 1 = y, 2 = z set at max.
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces)
        m.triangles.insert(m.triangles.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    return m;
}

// Gives a stock a design wholly under its floor: no cut gouges it, and the stock keeps each
// column's last cut (it keeps them only with a design, for the comparison's reports).
inline void keepLastCuts(Stock& stock)
{
    const base::Box3 b = stock.bounds();
    stock.setDesign(boxMesh({b.min.x, b.min.y, b.min.z - 2}, {b.max.x, b.max.y, b.min.z - 1}), 0);
}

inline void append(TriangleMesh& into, const TriangleMesh& more)
{
    const auto base = std::uint32_t(into.vertexCount());
    into.positions.insert(into.positions.end(), more.positions.begin(), more.positions.end());
    for (std::uint32_t v : more.triangles)
        into.triangles.push_back(base + v);
}

inline double stlVolume(const std::string& path, std::size_t& triangles)
{
    std::ifstream in(path, std::ios::binary);
    char header[80];
    std::uint32_t count = 0;
    in.read(header, 80);
    in.read(reinterpret_cast<char*>(&count), 4);
    triangles = count;
    double six = 0;
    for (std::uint32_t t = 0; t < count && in; ++t) {
        float f[12];
        char attr[2];
        in.read(reinterpret_cast<char*>(f), 48);
        in.read(attr, 2);
        const Vec3 a{f[3], f[4], f[5]}, b{f[6], f[7], f[8]}, c{f[9], f[10], f[11]};
        six += a.dot(b.cross(c));
    }
    return six / 6;
}

// Every directed edge appears once and its reverse once: closed and consistently oriented.
inline bool closedAndOriented(const TriangleMesh& m)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            ++edges[{m.triangles[3 * t + k], m.triangles[3 * t + (k + 1) % 3]}];
    for (const auto& [e, n] : edges) {
        const auto back = edges.find({e.second, e.first});
        if (n != 1 || back == edges.end() || back->second != 1)
            return false;
    }
    return true;
}

}  // namespace camwb::sim::test
