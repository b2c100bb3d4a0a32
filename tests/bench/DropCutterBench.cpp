// Drop-cutter speed (issue 16): CL points per second of surface::DropCutter on a generated
// freeform model of about 1M triangles (a 100 x 100 mm wavy surface with a dome, 708 x 708 squares
// of two triangles), a 6 mm ball and a 6 mm flat end mill, on 1 and 2 threads; building its index;
// and ops::computeParallel on the same model (ball 6 mm, stepover 0.5 mm, tolerance 0.01 mm).
// Figures in docs/benchmarks.md; never asserted in tests.
#include "WavyModel.h"
#include "ops/ParallelOp.h"
#include "ops/surface/DropCutter.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace camwb;

const sim::TriangleMesh& model() { return bench::wavyModel(); }

toolpath::Tool tool(bool ball)
{
    toolpath::Tool t;
    t.kind = ball ? "ball" : "flat";
    t.diameterMm = 6;
    t.fluteLengthMm = 40;
    return t;
}

// Index build (the bucket grid of 1M triangles).
void BM_DropCutterIndex(benchmark::State& state)
{
    for (auto _ : state) {
        ops::surface::DropCutter cutter(model(), tool(state.range(0) != 0));
        benchmark::DoNotOptimize(cutter);
    }
    state.counters["triangles"] = double(model().triangleCount());
}
BENCHMARK(BM_DropCutterIndex)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// 40 000 points on a 0.5 x 0.5 mm grid over the model (ball: range 0 = 1, flat 0), threads range 1
// (0: all cores).
void BM_DropCutterPoints(benchmark::State& state)
{
    const ops::surface::DropCutter cutter(model(), tool(state.range(0) != 0));
    const std::vector<base::Vec2> points = bench::wavyGridPoints();
    for (auto _ : state)
        benchmark::DoNotOptimize(cutter.dropZ(points, -100, int(state.range(1))));
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(points.size()));
}
BENCHMARK(BM_DropCutterPoints)
    ->ArgNames({"ball", "threads"})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 0})  // threads 0: all cores
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The whole parallel finishing operation on the model (all cores).
void BM_Parallel(benchmark::State& state)
{
    ops::SurfaceInput input;
    input.model = &model();
    input.stock.add({0, 0, -20});
    input.stock.add({100, 100, 20});
    ops::ParallelParams p;
    p.heights = {40, 30, 20, -20};
    p.stepoverMm = 0.5;
    p.toleranceMm = 0.01;
    ops::ToolController tc;
    tc.tool = tool(true);
    tc.spindleRpm = 10000;
    tc.cuttingFeedMmPerMin = 2000;
    tc.plungeFeedMmPerMin = 500;
    std::size_t records = 0;
    for (auto _ : state) {
        auto result = ops::computeParallel(input, p, tc, 0);
        if (!result) {
            state.SkipWithError(result.error().message.c_str());
            return;
        }
        records = result.value().toolpath.size();
    }
    state.counters["records"] = double(records);
}
BENCHMARK(BM_Parallel)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
