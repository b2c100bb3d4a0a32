// Motion in time (issue 14): the motion plan of a 1M-move program on a three- and a five-axis machine (the benchmark
// program's lines and arcs, arcs split by sim::buildMoves) and its 3 ms samples streamed through a callback, on a
// three-axis machine; and the samples of a five-axis machine, where each sample goes through the inverse kinematics, on
// the first 10 s of machine time. Reports moves/s and samples/s, and the held memory (the plan; the streamed samples
// hold none).
#include "BenchProgram.h"

#include "kinematics/Machine.h"
#include "sim/MotionPlan.h"
#include "sim/MotionSamples.h"

#include <benchmark/benchmark.h>

using namespace camwb;

namespace {

kinematics::Machine machineFor(const char* id)
{
    auto m = kinematics::findMachine(id, kinematics::defaultMachineDirs());
    if (!m)
        throw std::runtime_error(m.error().toString());
    return m.value();
}

const sim::MoveList& moves(std::size_t count)
{
    static std::size_t built = 0;
    static sim::MoveList list;
    if (built != count) {
        list = sim::buildMoves(bench::benchProgram(count));
        built = count;
    }
    return list;
}

void BM_PlanMotion(benchmark::State& state, const char* machineId)
{
    const sim::MoveList& list = moves(static_cast<std::size_t>(state.range(0)));
    const kinematics::Machine machine = machineFor(machineId);
    const long before = bench::currentRssKb();
    double seconds = 0;
    for (auto _ : state) {
        const sim::MotionPlan plan = sim::planMotion(list, machine);
        seconds = plan.totalSeconds;
        state.counters["held_MB"] = double(bench::currentRssKb() - before) / 1024;
        benchmark::DoNotOptimize(plan.moves.data());
    }
    state.counters["moves/s"] =
        benchmark::Counter(double(list.moves.size()), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["moves"] = double(list.moves.size());
    state.counters["machine_s"] = seconds;
}

void BM_SampleMotion(benchmark::State& state, const char* machineId, double limitSeconds)
{
    const sim::MoveList& list = moves(static_cast<std::size_t>(state.range(0)));
    const kinematics::Machine machine = machineFor(machineId);
    const sim::MotionPlan plan = sim::planMotion(list, machine);
    std::size_t samples = 0;
    double sum = 0;
    for (auto _ : state) {
        samples = 0;
        sim::sampleMotion(list, plan, machine, [&](const sim::MotionSample& s) {
            sum += s.at.linear.x;
            ++samples;
            return s.at.time < limitSeconds;
        });
    }
    benchmark::DoNotOptimize(sum);
    state.counters["samples/s"] = benchmark::Counter(double(samples), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["samples"] = double(samples);
}

}  // namespace

BENCHMARK_CAPTURE(BM_PlanMotion, three_axis, "emco-concept-mill-105")->Arg(1000000)->Unit(benchmark::kMillisecond);
// Five-axis: each move's machine axes at its quarter points through the inverse kinematics.
BENCHMARK_CAPTURE(BM_PlanMotion, five_axis, "mas-mcvl1000")->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SampleMotion, three_axis, "emco-concept-mill-105", 1e300)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SampleMotion, five_axis_first_10s, "mas-mcvl1000", 10.0)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
