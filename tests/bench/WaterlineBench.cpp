// Waterline speed (issue 16: "drop-cutter and waterline take seconds, not minutes, on a 1M-triangle
// model"): ops::computeWaterline around a closed sphere of R50 (SliceTestUtil's sphereMesh) at
// about 19k, 200k and 1M triangles, a 6 mm ball, no slope limit, contours from Z 45 down to Z 0
// (scallop 1 mm: 115 levels; or, where a second argument gives it, that many levels evenly apart,
// to time a slow build on the 1M model in minutes), tolerance 0.01 mm, all cores. The rows show
// how the cost grows with the triangles; the CL records' count is printed so runs are seen to do
// the same work. The 3D pocket's roughing round the same spheres is timed beside it. Figures in
// docs/benchmarks.md; never asserted.
#include "SliceTestUtil.h"

#include "ops/Pocket3dOp.h"
#include "ops/WaterlineOp.h"

#include <benchmark/benchmark.h>

namespace {

using namespace camwb;

// A cutter of `kind` and `diameter` at the feeds both rows use.
ops::ToolController cutter(const char* kind, double diameter, double fluteLength, double rpm)
{
    ops::ToolController tc;
    tc.tool.kind = kind;
    tc.tool.diameterMm = diameter;
    tc.tool.fluteLengthMm = fluteLength;
    tc.spindleRpm = rpm;
    tc.cuttingFeedMmPerMin = 2000;
    tc.plungeFeedMmPerMin = 500;
    return tc;
}

// Times `compute(input)` once on the closed R50 sphere of `rings` rings (segments twice that) in
// the stock box from -60 to 60, and counts its triangles and the CL records it gave.
template <class Compute> void aroundTheSphere(benchmark::State& state, int rings, Compute compute)
{
    const sim::TriangleMesh sphere = ops::surface::test::sphereMesh({}, 50, rings, 2 * rings);
    ops::SurfaceInput input;
    input.model = &sphere;
    input.stock.add({-60, -60, -50});
    input.stock.add({60, 60, 50});
    std::size_t records = 0;
    for (auto _ : state) {
        auto result = compute(input);
        if (!result) {
            state.SkipWithError(result.error().message.c_str());
            return;
        }
        records = result.value().toolpath.size();
    }
    state.counters["triangles"] = double(sphere.triangleCount());
    state.counters["records"] = double(records);
}

// range(0): rings: 70 -> 19k triangles, 224 -> 200k, 500 -> 1.0M (a closed sphere: half of them
// face up). range(1): the levels, 0 for the scallop's 115.
void BM_WaterlineSphere(benchmark::State& state)
{
    ops::WaterlineParams p;
    p.heights = {70, 60, 45, 0};
    p.scallopMm = 1;
    p.maxStepDownMm = 5;
    if (state.range(1) > 0) {
        p.scallopMm = 100;  // not the limit: the step-down is
        p.maxStepDownMm = 45.0 / double(state.range(1));
    }
    p.minSlopeDeg = 0;
    p.toleranceMm = 0.01;
    const ops::ToolController tc = cutter("ball", 6, 40, 10000);
    aroundTheSphere(state, int(state.range(0)),
                    [&](const ops::SurfaceInput& input) { return ops::computeWaterline(input, p, tc, 0); });
}
BENCHMARK(BM_WaterlineSphere)
    ->Args({70, 0})
    ->Args({224, 0})
    ->Args({500, 0})
    ->Args({500, 12})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The 3D pocket's roughing round the same spheres: a flat D10, 2 mm levels from Z 50 down to Z 0
// (25 levels), 50 % stepover, offset pattern, 0.3 mm side and 0.2 mm bottom stock, tolerance
// 0.01 mm: the material round the upper half cleared.
void BM_Pocket3dSphere(benchmark::State& state)
{
    ops::Pocket3dParams p;
    p.heights = {70, 60, 50, 0};
    p.stepDownMm = 2;
    const ops::ToolController tc = cutter("flat", 10, 60, 8000);
    aroundTheSphere(state, int(state.range(0)),
                    [&](const ops::SurfaceInput& input) { return ops::computePocket3d(input, p, tc, 0); });
}
BENCHMARK(BM_Pocket3dSphere)->Arg(70)->Arg(224)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
