// Pocket speed (issue 4): ops::computePocket on a face with a 1000-segment outline and 20 islands
// (bench::pocketBenchFace), tool D6, stepover 1 mm, 10 levels, helix entry; offset and zig-zag
// patterns. Reported per run with the toolpath's size (CL records, lines, arcs, helices) and its
// feed length in the XY plane, which scripts/bench-pocket.sh compares with FreeCAD 0.20's pocket
// on the same face (figures in docs/benchmarks.md). Never asserted in tests.
// Usage: camwb_pocket_bench [benchmark flags] | camwb_pocket_bench --once offset|zigzag [levels]
// (--once computes one pocket and prints its counts: for callgrind and perf).
#include "PocketBenchFace.h"

#include "ops/OpCommon.h"
#include "ops/PocketOp.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <variant>

namespace {

using namespace camwb;

// Feed length projected on XY (m): lines and arcs, helices by their XY turns.
double feedLengthXyM(const toolpath::Toolpath& path)
{
    double mm = 0;
    base::Vec3 at;
    for (const toolpath::Record& record : path.records()) {
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&record)) {
            at = rapid->to;
        } else if (const auto* line = std::get_if<toolpath::Linear>(&record)) {
            mm += distance(at.xy(), line->to.xy());
            at = line->to;
        } else if (const auto* arc = std::get_if<toolpath::Arc>(&record)) {
            const base::Vec2 from = at.xy() - arc->center.xy(), to = arc->to.xy() - arc->center.xy();
            double sweep = std::atan2(from.cross(to), from.dot(to));  // (-pi, pi], ccw positive
            if (arc->clockwise)
                sweep = -sweep;
            if (sweep <= 1e-12)
                sweep += 2 * std::numbers::pi;
            mm += from.length() * (sweep + 2 * std::numbers::pi * arc->turns);
            at = arc->to;
        }
    }
    return mm / 1000;
}

base::Result<ops::OpResult> pocketOnce(ops::PocketPattern pattern, int levels)
{
    static const std::vector<geom::Region> regions{bench::pocketBenchFace()};
    static const ops::ToolController tool = bench::pocketBenchTool();
    return ops::computePocket(regions, bench::pocketBenchParams(pattern, levels), tool, 0);
}

void report(benchmark::State& state, const ops::OpResult& result)
{
    const ops::MotionCounts counts = ops::countMotions(result.toolpath);
    state.counters["records"] = static_cast<double>(result.toolpath.size());
    state.counters["lines"] = counts.lines;
    state.counters["arcs"] = counts.arcs;
    state.counters["helices"] = counts.helices;
    state.counters["rapids"] = counts.rapids;
    state.counters["feed_xy_m"] = feedLengthXyM(result.toolpath);
    state.counters["warnings"] = static_cast<double>(result.warnings.size());
}

// range(0): the number of levels (10 is the benchmark; 1 compares one level's work).
void pocket(benchmark::State& state, ops::PocketPattern pattern)
{
    const int levels = static_cast<int>(state.range(0));
    base::Result<ops::OpResult> result = pocketOnce(pattern, levels);  // warm-up, and the figures reported
    if (!result) {
        state.SkipWithError(result.error().toString().c_str());
        return;
    }
    for (auto _ : state) {
        base::Result<ops::OpResult> run = pocketOnce(pattern, levels);
        benchmark::DoNotOptimize(run);
    }
    report(state, result.value());
}

void BM_PocketOffset(benchmark::State& state) { pocket(state, ops::PocketPattern::Offset); }
void BM_PocketZigZag(benchmark::State& state) { pocket(state, ops::PocketPattern::ZigZag); }

BENCHMARK(BM_PocketOffset)->Arg(10)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PocketZigZag)->Arg(10)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

int runOnce(const char* patternName, int levels)
{
    const bool zigzag = std::strcmp(patternName, "zigzag") == 0;
    const base::Result<ops::OpResult> result =
        pocketOnce(zigzag ? ops::PocketPattern::ZigZag : ops::PocketPattern::Offset, levels);
    if (!result) {
        std::fprintf(stderr, "camwb_pocket_bench: %s\n", result.error().toString().c_str());
        return 1;
    }
    const ops::MotionCounts counts = ops::countMotions(result->toolpath);
    std::printf("pocket %s, %d levels: records=%zu lines=%d arcs=%d helices=%d rapids=%d feed_xy_m=%.3f warnings=%zu\n",
                zigzag ? "zigzag" : "offset", levels, result->toolpath.size(), counts.lines, counts.arcs,
                counts.helices, counts.rapids, feedLengthXyM(result->toolpath), result->warnings.size());
    for (const base::Diagnostic& warning : result->warnings)
        std::printf("  warning: %s\n", warning.message.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if ((argc == 3 || argc == 4) && std::strcmp(argv[1], "--once") == 0)
        return runOnce(argv[2], argc == 4 ? std::atoi(argv[3]) : 10);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
