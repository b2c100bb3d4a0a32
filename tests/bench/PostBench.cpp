// Posting speed: blocks per second of a 1M-move program (lines and arcs) through the SINUMERIK
// 828D post, streamed to a file as camwb-cli does, and in memory as the GUI does. Peak memory is
// reported beside it: streaming must stay flat in the size of the output. Never asserted in tests;
// figures and the FreeCAD comparison live in docs/benchmarks.md.
#include "BenchProgram.h"

#include "post/PostProcessor.h"
#include "post/PostRegistry.h"

#include <QCoreApplication>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace {

using namespace camwb;

long peakRssKb()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

const post::PostProcessor& loadPost(const std::string& id)
{
    static std::map<std::string, post::PostProcessor> posts;
    auto found = posts.find(id);
    if (found == posts.end()) {
        auto path = post::findPost(id, post::defaultPostDirs());
        auto loaded = post::PostProcessor::load(path.value());
        if (!loaded) {
            std::fprintf(stderr, "%s\n", loaded.error().toString().c_str());
            std::exit(1);
        }
        found = posts.emplace(id, std::move(loaded).value()).first;
    }
    return found->second;
}

const toolpath::Toolpath& program(std::size_t moves)
{
    static std::map<std::size_t, toolpath::Toolpath> programs;
    auto found = programs.find(moves);
    if (found == programs.end())
        found = programs.emplace(moves, bench::benchProgram(moves)).first;
    return found->second;
}

post::RunOptions options()
{
    post::RunOptions o;
    o.context.programName = "BENCH";
    o.context.user = "bench";
    o.context.version = "bench";
    return o;
}

void postToFile(benchmark::State& state, const std::string& postId)
{
    const toolpath::Toolpath& path = program(static_cast<std::size_t>(state.range(0)));
    const post::PostProcessor& post = loadPost(postId);
    const std::string out = (std::filesystem::temp_directory_path() / ("camwb-bench-" + postId + ".nc")).string();
    const long before = bench::currentRssKb();
    std::size_t lines = 0, bytes = 0;
    for (auto _ : state) {
        auto summary = post.runToFile(path, options(), out);
        if (!summary) {
            state.SkipWithError(summary.error().toString().c_str());
            return;
        }
        lines = summary->lines;
        bytes = summary->bytes;
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * lines));
    state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
    state.counters["blocks"] = static_cast<double>(lines);
    state.counters["output_MB"] = static_cast<double>(bytes) / 1e6;
    state.counters["peak_rss_MB"] = static_cast<double>(peakRssKb()) / 1024;
    state.counters["rss_growth_MB"] = static_cast<double>(bench::currentRssKb() - before) / 1024;
    std::filesystem::remove(out);
}

void postInMemory(benchmark::State& state, const std::string& postId)
{
    const toolpath::Toolpath& path = program(static_cast<std::size_t>(state.range(0)));
    const post::PostProcessor& post = loadPost(postId);
    std::size_t lines = 0;
    long held = 0;  // what the finished output occupies while it is held
    for (auto _ : state) {
        const long before = bench::currentRssKb();
        auto output = post.run(path, options());
        if (!output) {
            state.SkipWithError(output.error().toString().c_str());
            return;
        }
        held = bench::currentRssKb() - before;
        lines = output->lineOperation.size();
        benchmark::DoNotOptimize(output->text.data());
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * lines));
    state.counters["blocks"] = static_cast<double>(lines);
    state.counters["rss_growth_MB"] = static_cast<double>(held) / 1024;
}

void BM_Sinumerik828dToFile(benchmark::State& state) { postToFile(state, "sinumerik828d-emco"); }
void BM_Sinumerik828dInMemory(benchmark::State& state) { postInMemory(state, "sinumerik828d-emco"); }
void BM_LinuxCncToFile(benchmark::State& state) { postToFile(state, "linuxcnc"); }
void BM_HeidenhainToFile(benchmark::State& state) { postToFile(state, "heidenhain-itnc530"); }

BENCHMARK(BM_Sinumerik828dToFile)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Sinumerik828dInMemory)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LinuxCncToFile)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_HeidenhainToFile)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);  // QJSEngine needs one
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
