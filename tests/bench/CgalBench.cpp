// CGAL measured beside our own kernels (the brief: measure the field's libraries before writing a
// geometry kernel of our own). Built only where CGAL is installed (`scripts/install-deps.sh
// --external`); the product does not link CGAL. Two questions, same input on both sides:
// - Slicing: CGAL::Polygon_mesh_slicer (an AABB tree of the edges, one plane at a time) against
//   ops::surface::sliceMesh (all levels in one pass), a 100-level stack of the 1M-triangle sphere
//   and of the mould example's mesh. CGAL's rows include building its Surface_mesh from our mesh
//   (its input format) as a separate row, so the slicer's own cost is visible.
// - The drop-cutter's spatial query: which triangles lie under a D6 tool at 40,000 points of the
//   1M-triangle wavy model (DropCutterBench's), CGAL::AABB_tree box queries against our bucket grid
//   (TriangleGrid::visit with nothing pruned), then our whole drop (the grid with its highest-first
//   pruning and the exact contacts) for scale.
// The counts (loops, candidates) are printed as counters so the two sides are seen to do the same
// work. Figures in docs/benchmarks.md; never asserted.
#include "SliceTestUtil.h"
#include "WavyModel.h"

#include "ops/surface/DropCutter.h"
#include "ops/surface/MeshSlicer.h"
#include "ops/surface/TriangleGrid.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

using namespace camwb;

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Epick::Point_3>;

constexpr int kLevels = 100;

const sim::TriangleMesh& sphere()
{
    static const sim::TriangleMesh mesh = ops::surface::test::sphereMesh({}, 50, 1000, 500);
    return mesh;
}

std::vector<double> sphereLevels()
{
    std::vector<double> levels;
    for (int i = 0; i < kLevels; ++i)
        levels.push_back(-50 + 100 * (i + 0.5) / kLevels);
    return levels;
}

Mesh toSurfaceMesh(const sim::TriangleMesh& in)
{
    Mesh out;
    out.reserve(Mesh::size_type(in.vertexCount()), Mesh::size_type(in.triangleCount() * 3 / 2),
                Mesh::size_type(in.triangleCount()));
    std::vector<Mesh::Vertex_index> v;
    v.reserve(in.vertexCount());
    for (std::size_t i = 0; i < in.vertexCount(); ++i) {
        const base::Vec3 p = in.vertex(i);
        v.push_back(out.add_vertex(Epick::Point_3(p.x, p.y, p.z)));
    }
    for (std::size_t t = 0; t < in.triangleCount(); ++t)
        out.add_face(v[in.triangles[3 * t]], v[in.triangles[3 * t + 1]], v[in.triangles[3 * t + 2]]);
    return out;
}

void BM_SphereToSurfaceMesh(benchmark::State& state)
{
    for (auto _ : state)
        benchmark::DoNotOptimize(toSurfaceMesh(sphere()));
    state.counters["triangles"] = double(sphere().triangleCount());
}

void BM_SphereCgalSlicer(benchmark::State& state)
{
    const Mesh mesh = toSurfaceMesh(sphere());
    std::size_t polylines = 0;
    for (auto _ : state) {
        // Built inside the loop: its AABB tree is part of its cost, as our sort is part of ours.
        CGAL::Polygon_mesh_slicer<Mesh, Epick> slicer(mesh);
        polylines = 0;
        for (const double z : sphereLevels()) {
            std::vector<std::vector<Epick::Point_3>> out;
            slicer(Epick::Plane_3(0, 0, 1, -z), std::back_inserter(out));
            polylines += out.size();
        }
    }
    state.counters["loops"] = double(polylines);
}

void BM_SphereSliceMesh(benchmark::State& state)
{
    std::size_t loops = 0;
    for (auto _ : state) {
        loops = 0;
        for (const auto& s : ops::surface::sliceMesh(sphere(), sphereLevels()))
            loops += s.loops.size();
    }
    state.counters["loops"] = double(loops);
}

BENCHMARK(BM_SphereToSurfaceMesh)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SphereCgalSlicer)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SphereSliceMesh)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- The drop-cutter's spatial query (DropCutterBench's model and points).

const sim::TriangleMesh& wavy() { return bench::wavyModel(); }
std::vector<base::Vec2> gridPoints() { return bench::wavyGridPoints(); }

constexpr double kRadius = 3;  // a D6 tool

using Sc = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Sc::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Sc, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Sc, Primitive>>;

Triangles cgalTriangles(const sim::TriangleMesh& m)
{
    Triangles out;
    out.reserve(m.triangleCount());
    auto p = [&](std::uint32_t i) {
        const base::Vec3 v = m.vertex(i);
        return Sc::Point_3(v.x, v.y, v.z);
    };
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        out.emplace_back(p(m.triangles[3 * t]), p(m.triangles[3 * t + 1]), p(m.triangles[3 * t + 2]));
    return out;
}

void BM_CgalAabbBuild(benchmark::State& state)
{
    const Triangles triangles = cgalTriangles(wavy());
    for (auto _ : state) {
        Tree tree(triangles.begin(), triangles.end());
        tree.build();
        benchmark::DoNotOptimize(tree.size());
    }
}

void BM_GridBuild(benchmark::State& state)
{
    for (auto _ : state)
        benchmark::DoNotOptimize(ops::surface::TriangleGrid(wavy(), kRadius));
}

// Candidates: every triangle whose box meets the tool's square column (CGAL) or whose box is
// within the radius of the centre (the grid; nothing pruned: `best` stays at -inf).
void BM_CgalAabbCandidates(benchmark::State& state)
{
    const Triangles triangles = cgalTriangles(wavy());
    Tree tree(triangles.begin(), triangles.end());
    tree.build();
    const std::vector<base::Vec2> points = gridPoints();
    std::vector<Tree::Primitive_id> hits;
    std::size_t candidates = 0;
    for (auto _ : state) {
        candidates = 0;
        for (const base::Vec2& c : points) {
            hits.clear();
            const CGAL::Bbox_3 column(c.x - kRadius, c.y - kRadius, -1e9, c.x + kRadius, c.y + kRadius, 1e9);
            tree.all_intersected_primitives(column, std::back_inserter(hits));
            candidates += hits.size();
        }
    }
    state.counters["candidates"] = double(candidates);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(points.size()));
}

void BM_GridCandidates(benchmark::State& state)
{
    const ops::surface::TriangleGrid grid(wavy(), kRadius);
    const std::vector<base::Vec2> points = gridPoints();
    const double best = -std::numeric_limits<double>::infinity();
    std::size_t candidates = 0;
    for (auto _ : state) {
        candidates = 0;
        for (const base::Vec2& c : points)
            grid.visit(
                c, kRadius, [](double) { return 0.0; }, best, [&](std::uint32_t) { ++candidates; });
    }
    state.counters["candidates"] = double(candidates);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(points.size()));
}

void BM_DropCutterBallOneThread(benchmark::State& state)
{
    toolpath::Tool tool;
    tool.kind = "ball";
    tool.diameterMm = 2 * kRadius;
    tool.fluteLengthMm = 40;
    const ops::surface::DropCutter cutter(wavy(), tool);
    const std::vector<base::Vec2> points = gridPoints();
    for (auto _ : state)
        benchmark::DoNotOptimize(cutter.dropZ(points, -100, 1));
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(points.size()));
}

BENCHMARK(BM_CgalAabbBuild)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GridBuild)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CgalAabbCandidates)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GridCandidates)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DropCutterBallOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
