// Waterline speed (issue 16: "drop-cutter and waterline take seconds, not minutes, on a 1M-triangle
// model"): ops::computeWaterline around a closed sphere of R50 (SliceTestUtil's sphereMesh) at
// about 10k, 100k and 1M triangles, a 6 mm ball, 10 contours from Z 45 down to Z 0 (step-down
// 5 mm), tolerance 0.01 mm, all cores. The rows show how the cost grows with the triangles; the
// contours' count is printed so runs are seen to do the same work. Figures in docs/benchmarks.md;
// never asserted.
#include "SliceTestUtil.h"

#include "ops/WaterlineOp.h"

#include <benchmark/benchmark.h>

namespace {

using namespace camwb;

// range(0): rings (segments twice that): 70 -> 9.7k triangles, 224 -> 100k, 707 -> 1.0M.
void BM_WaterlineSphere(benchmark::State& state)
{
    const int rings = int(state.range(0));
    const sim::TriangleMesh sphere = ops::surface::test::sphereMesh({}, 50, rings, 2 * rings);
    ops::SurfaceInput input;
    input.model = &sphere;
    input.stock.add({-60, -60, -50});
    input.stock.add({60, 60, 50});
    ops::WaterlineParams p;
    p.heights = {70, 60, 45, 0};
    p.scallopMm = 1;
    p.maxStepDownMm = 5;
    p.minSlopeDeg = 0;
    p.toleranceMm = 0.01;
    ops::ToolController tc;
    tc.tool.kind = "ball";
    tc.tool.diameterMm = 6;
    tc.tool.fluteLengthMm = 40;
    tc.spindleRpm = 10000;
    tc.cuttingFeedMmPerMin = 2000;
    tc.plungeFeedMmPerMin = 500;
    std::size_t records = 0;
    for (auto _ : state) {
        auto result = ops::computeWaterline(input, p, tc, 0);
        if (!result) {
            state.SkipWithError(result.error().message.c_str());
            return;
        }
        records = result.value().toolpath.size();
    }
    state.counters["triangles"] = double(sphere.triangleCount());
    state.counters["records"] = double(records);
}
BENCHMARK(BM_WaterlineSphere)->Arg(70)->Arg(224)->Arg(707)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
