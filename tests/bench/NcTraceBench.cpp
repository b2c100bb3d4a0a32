// Interpreter speed in all three dialects: blocks executed per CPU second for the programs of
// NcBenchPrograms.h (about 1M blocks each), into a counting sink (the interpreter alone), into
// a ToolpathRecorder (what the GUI and the round trips keep) and, for ISO, on to the text trace
// as `camwb-cli nc trace` writes it (streamed, and from a recorded toolpath as before). Also writes
// a program to a file for scripts/bench-nc.sh, which times `camwb-cli nc trace` and LinuxCNC's rs274
// on the same text in separate processes.
// Usage: camwb_nc_bench [benchmark flags]
//        camwb_nc_bench --write-program <file> [blocks] [iso|sinumerik|sinumerik-loops|heidenhain|heidenhain-labels]
#include "NcBenchPrograms.h"

#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace {

using namespace camwb;
using namespace camwb::toolpath;
using bench::NcProgram;

const std::string& program(NcProgram kind, std::size_t blocks)
{
    static std::map<std::pair<NcProgram, std::size_t>, std::string> programs;
    auto found = programs.find({kind, blocks});
    if (found == programs.end())
        found = programs.emplace(std::pair{kind, blocks}, bench::ncProgram(kind, blocks)).first;
    return found->second;
}

std::size_t lineCount(const std::string& text)
{
    std::size_t n = 0;
    for (const char c : text)
        n += c == '\n';
    return n;
}

// Counts what it is sent: the interpreter's own cost, without storing records.
class CountingSink : public MachineSink {
public:
    std::size_t records = 0;
    void rapid(const Rapid&) override { ++records; }
    void linear(const Linear&) override { ++records; }
    void arc(const Arc&) override { ++records; }
    void toolChange(const ToolChange&) override { ++records; }
    void spindle(const Spindle&) override { ++records; }
    void coolant(const Coolant&) override { ++records; }
    void feedMode(const FeedModeChange&) override { ++records; }
    void workOffset(const WorkOffset&) override { ++records; }
    void dwell(const Dwell&) override { ++records; }
    void cycle(const Cycle&) override { ++records; }
    void toolAxisMove(const ToolAxisMove&) override { ++records; }
    void cutterComp(const CutterComp&) override { ++records; }
    void comment(const Comment&) override { ++records; }
    void sectionBegin(const SectionBegin&) override { ++records; }
    void sectionEnd(const SectionEnd&) override { ++records; }
    void programStop(const ProgramStop&) override { ++records; }
    void passThrough(const PassThrough&) override { ++records; }
    void workingPlane(const WorkingPlane&) override { ++records; }
    void unknownAxes(const UnknownAxes&) override { ++records; }
};

nc::InterpretOptions optionsFor(NcProgram kind)
{
    nc::InterpretOptions options;
    options.dialect = bench::dialectOf(kind);
    options.fileName = std::string("bench.") + (kind == NcProgram::Iso                       ? "ngc"
                                                : options.dialect == nc::Dialect::Heidenhain ? "h"
                                                                                             : "mpf");
    return options;
}

// Interprets the program into `sink`; a benchmark whose program does not run cleanly is an error.
nc::InterpretResult run(benchmark::State& state, const std::string& text, NcProgram kind, MachineSink& sink)
{
    nc::InterpretResult result = nc::interpret(text, optionsFor(kind), sink);
    if (result.hasErrors() || !result.completed)
        state.SkipWithError(("the benchmark program does not run: " +
                             (result.diagnostics.empty() ? std::string("incomplete") : result.diagnostics[0].message))
                                .c_str());
    return result;
}

void report(benchmark::State& state, const std::string& text, std::int64_t blocksExecuted)
{
    const double blocks = static_cast<double>(blocksExecuted);
    state.counters["blocks/s"] = benchmark::Counter(blocks, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["blocks"] = blocks;
    state.counters["lines"] = static_cast<double>(lineCount(text));
}

void BM_CountingSink(benchmark::State& state, NcProgram kind)
{
    const std::string& text = program(kind, static_cast<std::size_t>(state.range(0)));
    std::int64_t blocks = 0;
    for (auto _ : state) {
        CountingSink sink;
        blocks = run(state, text, kind, sink).blocksExecuted;
        benchmark::DoNotOptimize(sink.records);
    }
    report(state, text, blocks);
}

void BM_Recorder(benchmark::State& state, NcProgram kind)
{
    const std::string& text = program(kind, static_cast<std::size_t>(state.range(0)));
    std::int64_t blocks = 0;
    for (auto _ : state) {
        ToolpathRecorder recorder;
        blocks = run(state, text, kind, recorder).blocksExecuted;
        benchmark::DoNotOptimize(recorder.toolpath().size());
    }
    report(state, text, blocks);
}

// The text trace as `camwb-cli nc trace` makes it now: formatted while the interpreter runs, handed
// on in 1 MiB chunks (here counted, not written).
void BM_TraceStream(benchmark::State& state, NcProgram kind)
{
    const std::string& text = program(kind, static_cast<std::size_t>(state.range(0)));
    std::int64_t blocks = 0;
    for (auto _ : state) {
        std::size_t bytes = 0;
        nc::MotionTraceWriter trace(optionsFor(kind).fileName, nc::TraceFormat::Text, [&bytes](std::string_view chunk) {
            bytes += chunk.size();
            return true;
        });
        const nc::InterpretResult result = run(state, text, kind, trace);
        trace.finish(result.files);
        blocks = result.blocksExecuted;
        benchmark::DoNotOptimize(bytes);
    }
    report(state, text, blocks);
}

// The text trace made from a recorded toolpath, all of it in memory (how the trace was made before
// it streamed; the unit tests still trace this way).
void BM_TraceFromRecorder(benchmark::State& state, NcProgram kind)
{
    const std::string& text = program(kind, static_cast<std::size_t>(state.range(0)));
    std::int64_t blocks = 0;
    for (auto _ : state) {
        ToolpathRecorder recorder;
        const nc::InterpretResult result = run(state, text, kind, recorder);
        const std::string trace = nc::motionTrace(recorder.toolpath(), result.files, nc::TraceFormat::Text);
        blocks = result.blocksExecuted;
        benchmark::DoNotOptimize(trace.size());
    }
    report(state, text, blocks);
}

// Rates per CPU second of the benchmark's thread (not wall time): the machine the figures come
// from is shared, and the load stretches wall time, not CPU time.
#define CAMWB_NC_BENCH(function, name, kind)                                                                           \
    BENCHMARK_CAPTURE(function, name, kind)->Arg(1000000)->Unit(benchmark::kMillisecond)

CAMWB_NC_BENCH(BM_CountingSink, iso, NcProgram::Iso);
CAMWB_NC_BENCH(BM_Recorder, iso, NcProgram::Iso);
CAMWB_NC_BENCH(BM_TraceStream, iso, NcProgram::Iso);
CAMWB_NC_BENCH(BM_TraceFromRecorder, iso, NcProgram::Iso);
CAMWB_NC_BENCH(BM_CountingSink, sinumerik, NcProgram::Sinumerik);
CAMWB_NC_BENCH(BM_Recorder, sinumerik, NcProgram::Sinumerik);
CAMWB_NC_BENCH(BM_CountingSink, sinumerik_loops, NcProgram::SinumerikLoops);
CAMWB_NC_BENCH(BM_Recorder, sinumerik_loops, NcProgram::SinumerikLoops);
CAMWB_NC_BENCH(BM_CountingSink, heidenhain, NcProgram::Heidenhain);
CAMWB_NC_BENCH(BM_Recorder, heidenhain, NcProgram::Heidenhain);
CAMWB_NC_BENCH(BM_CountingSink, heidenhain_labels, NcProgram::HeidenhainLabels);
CAMWB_NC_BENCH(BM_Recorder, heidenhain_labels, NcProgram::HeidenhainLabels);

// --write-program <file> [blocks] [program]: the program as the benchmarks read it.
int writeProgram(int argc, char** argv)
{
    const std::size_t blocks = argc >= 4 ? std::strtoull(argv[3], nullptr, 10) : 1000000;
    const std::optional<NcProgram> kind = bench::ncProgramFromName(argc >= 5 ? argv[4] : "iso");
    if (!kind || blocks == 0) {
        std::fprintf(stderr, "camwb_nc_bench: --write-program <file> [blocks] "
                             "[iso|sinumerik|sinumerik-loops|heidenhain|heidenhain-labels]\n");
        return 2;
    }
    const std::string text = bench::ncProgram(*kind, blocks);
    std::ofstream out(argv[2], std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        std::fprintf(stderr, "camwb_nc_bench: cannot write %s\n", argv[2]);
        return 1;
    }
    // The loop programs execute more blocks than they have lines: say how many, and whether the
    // program runs cleanly, so that the figures of scripts/bench-nc.sh can be read per block.
    CountingSink sink;
    const nc::InterpretResult result = nc::interpret(text, optionsFor(*kind), sink);
    std::printf("%zu lines, %lld blocks executed%s\n", lineCount(text), static_cast<long long>(result.blocksExecuted),
                result.hasErrors() || !result.completed ? ", WITH ERRORS" : "");
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc >= 3 && std::strcmp(argv[1], "--write-program") == 0)
        return writeProgram(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
