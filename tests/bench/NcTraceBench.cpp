// Tracing speed of the plain ISO interpreter: blocks per second for a 1M-move program as
// posts/linuxcnc.js writes it (bench::benchProgram: lines and quarter arcs, 3 decimals, modal
// words), into a counting sink (the interpreter alone), into a ToolpathRecorder (what the GUI and
// camwb-cli keep) and on to the text trace (what `camwb-cli nc trace` prints). Also writes the
// program to a file for scripts/bench-nc.sh, which runs LinuxCNC's rs274 on the same text.
// Usage: camwb_nc_bench [benchmark flags] | camwb_nc_bench --write-program <file> [moves]
#include "BenchProgram.h"

#include "base/NumberFormat.h"
#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

namespace {

using namespace camwb;
using namespace camwb::toolpath;

// Words the way the LinuxCNC post writes them: 3 decimals, axes and F only when they change, the
// motion word when it changes, I and J always.
class IsoWriter {
public:
    std::string take() { return std::move(m_out); }

    void line(const std::string& text)
    {
        m_out += text;
        m_out += '\n';
        ++m_lines;
    }
    void move(const char* motion, const Vec3& to, double feed, const std::string& centre = {})
    {
        std::string block;
        if (m_motion != motion) {
            block += motion;
            m_motion = motion;
        }
        axis(block, 'X', to.x, m_at.x);
        axis(block, 'Y', to.y, m_at.y);
        axis(block, 'Z', to.z, m_at.z);
        block += centre;
        if (feed > 0) {
            const std::string f = base::NumberFormat{3, true}.format(feed);
            if (f != m_feed) {
                append(block, "F" + f);
                m_feed = f;
            }
        }
        m_at = to;
        line(block);
    }
    std::size_t lines() const { return m_lines; }
    const Vec3& at() const { return m_at; }

private:
    static void append(std::string& block, const std::string& word)
    {
        if (!block.empty())
            block += ' ';
        block += word;
    }
    void axis(std::string& block, char letter, double value, double before)
    {
        const std::string text = base::formatFixed(value, 3);
        if (!m_started || text != base::formatFixed(before, 3))
            append(block, letter + text);
    }

public:
    bool m_started = false;

private:
    std::string m_out;
    std::size_t m_lines = 0;
    std::string m_motion;
    std::string m_feed;
    Vec3 m_at;
};

std::string isoProgram(std::size_t moves)
{
    IsoWriter w;
    w.line("%");
    w.line("(benchmark)");
    w.line("G21 G90 G94 G17 G40 G49 G80 G91.1");
    w.line("G54");
    w.line("T1 M6");
    w.line("G43 H1");
    w.line("M3 S4000");
    const Toolpath path = bench::benchProgram(moves);
    for (const Record& record : path.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            w.move("G0", r->to, 0);
            w.m_started = true;
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            w.move("G1", l->to, l->feedMmPerMin);
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            const std::string centre = " I" + base::formatFixed(a->center.x - w.at().x, 3) + " J" +
                                       base::formatFixed(a->center.y - w.at().y, 3);
            w.move(a->clockwise ? "G2" : "G3", a->to, a->feedMmPerMin, centre);
        }
    }
    w.line("M5 M9");
    w.line("M2");
    w.line("%");
    return w.take();
}

const std::string& program(std::size_t moves)
{
    static std::map<std::size_t, std::string> programs;
    auto found = programs.find(moves);
    if (found == programs.end())
        found = programs.emplace(moves, isoProgram(moves)).first;
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
};

nc::InterpretOptions isoOptions()
{
    nc::InterpretOptions options;
    options.dialect = nc::Dialect::Iso;
    return options;
}

void report(benchmark::State& state, const std::string& text)
{
    const double blocks = static_cast<double>(lineCount(text));
    state.counters["blocks/s"] = benchmark::Counter(blocks, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["lines"] = blocks;
}

void BM_IsoTraceCountingSink(benchmark::State& state)
{
    const std::string& text = program(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        CountingSink sink;
        const nc::InterpretResult result = nc::interpret(text, isoOptions(), sink);
        if (result.hasErrors())
            state.SkipWithError("the benchmark program has errors");
        benchmark::DoNotOptimize(sink.records);
    }
    report(state, text);
}

void BM_IsoTraceRecorder(benchmark::State& state)
{
    const std::string& text = program(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        ToolpathRecorder recorder;
        const nc::InterpretResult result = nc::interpret(text, isoOptions(), recorder);
        if (result.hasErrors())
            state.SkipWithError("the benchmark program has errors");
        benchmark::DoNotOptimize(recorder.toolpath().size());
    }
    report(state, text);
}

void BM_IsoTraceText(benchmark::State& state)
{
    const std::string& text = program(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        ToolpathRecorder recorder;
        const nc::InterpretResult result = nc::interpret(text, isoOptions(), recorder);
        const std::string trace = nc::motionTrace(recorder.toolpath(), result.files, nc::TraceFormat::Text);
        benchmark::DoNotOptimize(trace.size());
    }
    report(state, text);
}

BENCHMARK(BM_IsoTraceCountingSink)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IsoTraceRecorder)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IsoTraceText)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv)
{
    if (argc >= 3 && std::strcmp(argv[1], "--write-program") == 0) {
        const std::size_t moves = argc >= 4 ? std::strtoull(argv[3], nullptr, 10) : 1000000;
        const std::string& text = program(moves);
        std::ofstream out(argv[2], std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::fprintf(stderr, "camwb_nc_bench: cannot write %s\n", argv[2]);
            return 1;
        }
        std::printf("%zu lines\n", lineCount(text));
        return 0;
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
