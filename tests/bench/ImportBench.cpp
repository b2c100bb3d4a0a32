// Importer speed and memory: the FreeCAD dump and APT readers on the benchmark program at 1M
// moves, read from a file as camwb-cli does (toolpath::readClFile streams it a chunk at a time).
// `camwb_import_bench --read <file>` imports one file once, for /usr/bin/time -v to give the peak
// memory of an import alone. Figures live in docs/benchmarks.md; no test asserts a time.
#include "BenchProgram.h"

#include "base/AtomicFile.h"
#include "toolpath/ClImport.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>

namespace {

using namespace camwb;

// The inputs written so far, by format and size; removed when the run ends.
std::map<std::pair<int, std::size_t>, std::string>& inputFiles()
{
    static std::map<std::pair<int, std::size_t>, std::string> files;
    return files;
}

// The benchmark program in `format`, written once per size into the temp folder (repetitions of
// a case read the same file).
std::string inputFile(toolpath::ClFormat format, std::size_t moves)
{
    auto& files = inputFiles();
    const auto key = std::make_pair(static_cast<int>(format), moves);
    if (const auto found = files.find(key); found != files.end())
        return found->second;
    const bool apt = format == toolpath::ClFormat::Apt;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("camwb-import-bench-" + std::to_string(moves) + (apt ? ".apt" : ".dump")))
                                 .string();
    const toolpath::Toolpath program = bench::benchProgram(moves);
    if (auto written =
            base::writeFileAtomically(path, apt ? bench::asAptSource(program) : bench::asFreeCadDump(program));
        !written) {
        std::fprintf(stderr, "%s\n", written.error().toString().c_str());
        std::exit(1);
    }
    return files.emplace(key, path).first->second;
}

void readFile(benchmark::State& state, toolpath::ClFormat format)
{
    const std::string path = inputFile(format, static_cast<std::size_t>(state.range(0)));
    std::size_t records = 0;
    long held = 0;  // what the imported toolpath occupies while it is held
    for (auto _ : state) {
        const long before = bench::currentRssKb();
        auto imported = toolpath::readClFile(path, format);
        if (!imported) {
            state.SkipWithError(imported.error().toString().c_str());
            return;
        }
        held = bench::currentRssKb() - before;
        records = imported->toolpath.size();
        benchmark::DoNotOptimize(imported->toolpath.records().data());
    }
    const auto bytes = static_cast<double>(std::filesystem::file_size(path));
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * records));
    state.SetBytesProcessed(static_cast<int64_t>(static_cast<double>(state.iterations()) * bytes));
    state.counters["records"] = static_cast<double>(records);
    state.counters["input_MB"] = bytes / 1e6;
    state.counters["held_MB"] = static_cast<double>(held) / 1024;
}

void BM_ReadFreeCadDump(benchmark::State& state) { readFile(state, toolpath::ClFormat::FreeCadDump); }
void BM_ReadAptSource(benchmark::State& state) { readFile(state, toolpath::ClFormat::Apt); }

BENCHMARK(BM_ReadFreeCadDump)->Arg(200000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadAptSource)->Arg(200000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--read") == 0) {
        const auto format = toolpath::clFormatFromExtension(argv[2]);
        auto imported = format ? toolpath::readClFile(argv[2], *format)
                               : base::Result<toolpath::ClImport>(base::makeError("unknown CL format", argv[2]));
        if (!imported) {
            std::fprintf(stderr, "%s\n", imported.error().toString().c_str());
            return 1;
        }
        std::printf("%zu records\n", imported->toolpath.size());
        return 0;
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    for (const auto& [key, path] : inputFiles())
        std::filesystem::remove(path);
    return 0;
}
