// Five-axis speed: inverse kinematics poses per second on the MAS MCVL 1000's B/C chain, and a
// 1M-move five-axis CL (one operation, the tool axis swinging and turning) posted by the iTNC 530
// post in each TCPM mode, streamed to a file as camwb-cli does. Figures in docs/benchmarks.md.
#include "kinematics/Machine.h"
#include "kinematics/PoseSolver.h"
#include "post/PostProcessor.h"
#include "post/PostRegistry.h"

#include <QCoreApplication>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

using namespace camwb;

constexpr double kPi = 3.14159265358979323846;

const kinematics::Machine& machine()
{
    static const kinematics::Machine m = [] {
        auto found = kinematics::findMachine("mas-mcvl1000", kinematics::defaultMachineDirs());
        if (!found || !found.value().kinematics.fiveAxis()) {
            std::fprintf(stderr, "mas-mcvl1000 with a five-axis chain not found\n");
            std::exit(1);
        }
        return found.value();
    }();
    return m;
}

// The tool pose of move i: a zig-zag over 150 x 100 mm with the axis tilted 10..40 degrees and
// its direction turning once every 20000 moves (C goes round and round, B swings).
kinematics::ToolPose toolPose(std::size_t i)
{
    const double t = static_cast<double>(i);
    const double tilt = (25 + 15 * std::sin(t / 700)) * kPi / 180;
    const double azimuth = t / 20000 * 2 * kPi;
    const double x = std::fmod(t * 0.05, 150) - 75;
    const double y = 50 * std::sin(t / 3000);
    return {{x, y, -5 + 2 * std::cos(t / 500)},
            {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt)}};
}

const toolpath::Toolpath& fiveAxisProgram(std::size_t moves)
{
    static std::map<std::size_t, toolpath::Toolpath> programs;
    auto found = programs.find(moves);
    if (found != programs.end())
        return found->second;
    toolpath::Toolpath tp;
    toolpath::SectionBegin section;
    section.operationName = "Five-axis bench";
    section.toolNumber = 1;
    tp.add(section);
    toolpath::ToolChange change;
    change.tool.number = 1;
    change.tool.kind = "ball";
    change.tool.diameterMm = 6;
    change.tool.lengthMm = 60;
    tp.add(change);
    tp.add(toolpath::Spindle{6000, true});
    for (std::size_t i = 0; i < moves; ++i) {
        const kinematics::ToolPose pose = toolPose(i);
        tp.add(toolpath::ToolAxisMove{pose.tip, pose.axis, i == 0 ? 0.0 : 1200.0});
    }
    tp.add(toolpath::SectionEnd{});
    return programs.emplace(moves, std::move(tp)).first->second;
}

void BM_InverseKinematics(benchmark::State& state)
{
    const kinematics::KinematicChain& chain = machine().kinematics;
    std::size_t i = 0;
    for (auto _ : state)
        benchmark::DoNotOptimize(kinematics::inverseKinematics(chain, toolPose(i++)));
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

void BM_PlanBranches(benchmark::State& state)
{
    const kinematics::PoseSolver solver(machine());
    std::vector<kinematics::ToolPose> tools;
    for (std::size_t i = 0; i < static_cast<std::size_t>(state.range(0)); ++i)
        tools.push_back(toolPose(i));
    for (auto _ : state) {
        auto plan = kinematics::planBranches(solver, tools, nullptr);
        if (!plan) {
            state.SkipWithError(plan.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(plan.value().data());
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * tools.size()));
}

void postFiveAxis(benchmark::State& state, const std::string& tcpm)
{
    const toolpath::Toolpath& path = fiveAxisProgram(static_cast<std::size_t>(state.range(0)));
    static const post::PostProcessor post = [] {
        auto loaded = post::PostProcessor::load(post::findPost("heidenhain-itnc530", post::defaultPostDirs()).value());
        if (!loaded) {
            std::fprintf(stderr, "%s\n", loaded.error().toString().c_str());
            std::exit(1);
        }
        return std::move(loaded).value();
    }();
    post::RunOptions options;
    options.context.programName = "BENCH";
    options.context.user = "bench";
    options.context.version = "bench";
    options.machine = machine();
    options.properties["tcpm"] = tcpm;
    options.scriptBudget = std::chrono::minutes(5);
    const std::string out = (std::filesystem::temp_directory_path() / ("camwb-bench-5x-" + tcpm + ".h")).string();
    std::size_t lines = 0;
    for (auto _ : state) {
        auto summary = post.runToFile(path, options, out);
        if (!summary) {
            state.SkipWithError(summary.error().toString().c_str());
            return;
        }
        lines = summary->lines;
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * lines));
    state.counters["blocks"] = static_cast<double>(lines);
    std::filesystem::remove(out);
}

void BM_HeidenhainFiveAxisM128(benchmark::State& state) { postFiveAxis(state, "m128"); }
void BM_HeidenhainFiveAxisFunctionTcpm(benchmark::State& state) { postFiveAxis(state, "function-tcpm"); }
void BM_HeidenhainFiveAxisOff(benchmark::State& state) { postFiveAxis(state, "off"); }

BENCHMARK(BM_InverseKinematics);
BENCHMARK(BM_PlanBranches)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_HeidenhainFiveAxisM128)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_HeidenhainFiveAxisFunctionTcpm)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_HeidenhainFiveAxisOff)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);  // QJSEngine needs one
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
