// Slicing speed (issue 16): a 100-level stack over a part, ops::surface::sliceMesh of its
// tessellation (0.01 mm) for all levels in one pass against OCCT's exact section per level
// (occ::Model::sectionLoops, BRepAlgoAPI_Section), with the meshing (and welding) as its own row. The part:
// $CAMWB_SLICE_PART, else resources/examples/example-mould.step where it exists, else the five-axis
// example. `--agreement` prints the largest distance between the two sections over the stack
// instead (scripts/bench-slicing.sh runs both; figures in docs/benchmarks.md). Never asserted.
#include "SliceTestUtil.h"

#include "document/Simulate.h"
#include "occ/Model.h"
#include "ops/surface/MeshSlicer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace {

using namespace camwb;

constexpr double kTolerance = 0.01;  // the mesh's deflection and the exact sections' chords
constexpr int kLevels = 100;

std::string partPath()
{
    if (const char* path = std::getenv("CAMWB_SLICE_PART"))
        return path;
    const std::string examples = std::string(CAMWB_SOURCE_DIR) + "/resources/examples/";
    if (std::filesystem::exists(examples + "example-mould.step"))
        return examples + "example-mould.step";
    return examples + "example-five-axis.step";
}

const occ::Model& part()
{
    static const occ::Model model = [] {
        base::Result<occ::Model> loaded = occ::Model::load(partPath());
        if (!loaded) {
            std::fprintf(stderr, "camwb_slice_bench: %s\n", loaded.error().toString().c_str());
            std::exit(1);
        }
        return loaded.value();
    }();
    return model;
}

const sim::TriangleMesh& partMesh()
{
    static const sim::TriangleMesh mesh = sim::weldVertices(document::designMesh(part(), kTolerance));
    return mesh;
}

// kLevels levels evenly through the part's height, none on its bottom or top, and none on a flat
// face (moved 1 µm up from it: OCCT's section there is the face, the slicer's just above it).
std::vector<double> stack()
{
    const double bottom = part().boundsMin().z, top = part().boundsMax().z;
    const std::vector<double> flats = ops::surface::flatLevels(partMesh());
    std::vector<double> levels;
    for (int i = 0; i < kLevels; ++i) {
        double z = bottom + (top - bottom) * (i + 0.5) / kLevels;
        for (const double flat : flats)
            if (std::abs(z - flat) < 1e-3)
                z = flat + 1e-3;
        levels.push_back(z);
    }
    return levels;
}

// Meshing alone, welded as the 3D operations take it: a fresh copy of the part each time (a model
// keeps its triangulation).
void BM_MeshPart(benchmark::State& state)
{
    std::size_t triangles = 0;
    for (auto _ : state) {
        state.PauseTiming();
        base::Result<occ::Model> fresh = occ::Model::load(partPath());
        state.ResumeTiming();
        triangles = sim::weldVertices(document::designMesh(fresh.value(), kTolerance)).triangleCount();
    }
    state.counters["triangles"] = double(triangles);
}

void BM_SliceMesh(benchmark::State& state)
{
    const sim::TriangleMesh& mesh = partMesh();
    const std::vector<double> levels = stack();
    std::size_t loops = 0;
    for (auto _ : state) {
        const std::vector<ops::surface::MeshSection> sections = ops::surface::sliceMesh(mesh, levels);
        loops = 0;
        for (const auto& s : sections)
            loops += s.loops.size();
        benchmark::DoNotOptimize(loops);
    }
    state.counters["triangles"] = double(mesh.triangleCount());
    state.counters["loops"] = double(loops);
}

void BM_OcctSection(benchmark::State& state)
{
    const std::vector<double> levels = stack();
    std::size_t loops = 0;
    for (auto _ : state) {
        loops = 0;
        for (const double z : levels) {
            const auto section = part().sectionLoops(z, kTolerance);
            if (!section) {
                state.SkipWithError(section.error().toString().c_str());
                return;
            }
            loops += section.value().size();
        }
    }
    state.counters["loops"] = double(loops);
}

// Scaling: a sphere of about a million triangles (1000 rings of 500), range(0) levels (1 shows
// the fixed cost: welding and sorting the triangles).
void BM_SliceMillionTriangles(benchmark::State& state)
{
    static const sim::TriangleMesh sphere = ops::surface::test::sphereMesh({}, 50, 1000, 500);
    std::vector<double> levels;
    const auto count = static_cast<int>(state.range(0));
    for (int i = 0; i < count; ++i)
        levels.push_back(-50 + 100 * (i + 0.5) / count);
    for (auto _ : state)
        benchmark::DoNotOptimize(ops::surface::sliceMesh(sphere, levels));
    state.counters["triangles"] = double(sphere.triangleCount());
}

BENCHMARK(BM_MeshPart)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_SliceMesh)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OcctSection)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_SliceMillionTriangles)->Arg(kLevels)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The largest distance between the mesh's and OCCT's sections over the stack (exact chords 1 µm),
// and the levels where the loop counts differ.
int agreement()
{
    const std::vector<double> levels = stack();
    const std::vector<ops::surface::MeshSection> sections = ops::surface::sliceMesh(partMesh(), levels);
    double worst = 0, worstZ = 0;
    int differ = 0;
    for (const auto& s : sections) {
        const auto exact = part().sectionLoops(s.z, 0.001);
        if (!exact) {
            std::fprintf(stderr, "camwb_slice_bench: %s\n", exact.error().toString().c_str());
            return 1;
        }
        differ += exact.value().size() != s.loops.size();
        const double d = ops::surface::test::hausdorff(s.loops, exact.value());
        if (d > worst)
            worst = d, worstZ = s.z;
    }
    std::printf("agreement %s: %zu triangles, %d levels, largest distance %.4f mm (at Z %.3f), loop counts "
                "differ at %d levels\n",
                partPath().c_str(), partMesh().triangleCount(), kLevels, worst, worstZ, differ);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc == 2 && std::strcmp(argv[1], "--agreement") == 0)
        return agreement();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    std::fprintf(stderr, "part: %s\n", partPath().c_str());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
