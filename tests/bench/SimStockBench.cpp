// Stock removal speed (issue 14): the example job's CL (tests/bench/data/example-block.trace,
// written by `camwb-cli cl resources/examples/example-block.camwb`) on a height field at 0.1 mm,
// and the 1M-move benchmark program at 0.2 mm; counters give moves/s and the ratio of the
// machine's time (feeds from the program, rapids at 10 m/min) to the simulation's. With
// CAMWB_SIM_BENCH_MOVES=<dir> it first writes both programs' straight moves for the FreeCAD
// PathSim peer (tests/bench/peers/freecad_pathsim.py), which then cuts the same pieces.
#include "BenchProgram.h"
#include "sim/HeightField.h"
#include "sim/Moves.h"
#include "sim/StockRun.h"
#include "sim/TriDexel.h"
#include "toolpath/TraceReader.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

using namespace camwb;

namespace {

constexpr double kRapidMmPerMin = 10000;

sim::MoveList exampleMoves()
{
    std::ifstream in(CAMWB_SIM_BENCH_TRACE);
    std::stringstream text;
    text << in.rdbuf();
    auto read = toolpath::readTrace(text.str(), CAMWB_SIM_BENCH_TRACE);
    if (!read) {
        std::fprintf(stderr, "%s\n", read.error().toString().c_str());
        std::exit(1);
    }
    return sim::buildMoves(read.value().toolpath);
}

base::Box3 box(base::Vec3 lo, base::Vec3 hi)
{
    base::Box3 b;
    b.add(lo);
    b.add(hi);
    return b;
}

double machineMinutes(const sim::MoveList& list)
{
    double minutes = 0;
    for (const sim::Move& m : list.moves) {
        if (m.kind == sim::MoveKind::Rapid)
            minutes += m.lengthMm() / kRapidMmPerMin;
        else if (m.kind == sim::MoveKind::Feed)
            minutes += m.minutes > 0 ? m.minutes : m.feedMmPerMin > 0 ? m.lengthMm() / m.feedMmPerMin : 0;
    }
    return minutes;
}

// Cuts every move with its tool as `camwb-cli sim` does (sim::StockRun: a level arc's pieces in
// one pass, the checks judged); the stock is made afresh each iteration outside the timing.
template <class StockT>
void simulate(benchmark::State& state, const sim::MoveList& list, const base::Box3& stockBox, double resolution)
{
    double removed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        StockT stock(stockBox, resolution);
        state.ResumeTiming();
        sim::StockRun run(list, stock);
        run.cutTo(list.moves.size());
        removed = run.removedMm3();
        // Not benchmark::DoNotOptimize(removed): GCC 12 fills its "+m,r" operand of a double
        // from a general register, and the counter below read garbage. The cut is kept anyway.
    }
    const double seconds = 60 * machineMinutes(list);
    state.counters["moves"] = double(list.moves.size());
    state.counters["removed_mm3"] = removed;
    state.counters["moves_per_s"] =
        benchmark::Counter(double(list.moves.size()), benchmark::Counter::kIsIterationInvariantRate);
    // Machine seconds per second of simulation: the "faster than the machine" ratio.
    state.counters["x_machine"] = benchmark::Counter(seconds, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ExampleJobHeightField(benchmark::State& state)
{
    static const sim::MoveList list = exampleMoves();
    simulate<sim::HeightField>(state, list, box({-2, -2, 0}, {92, 62, 16}), 0.1);
}
BENCHMARK(BM_ExampleJobHeightField)->Unit(benchmark::kMillisecond);

void BM_ExampleJobTriDexel(benchmark::State& state)
{
    static const sim::MoveList list = exampleMoves();
    simulate<sim::TriDexel>(state, list, box({-2, -2, 0}, {92, 62, 16}), 0.2);
}
BENCHMARK(BM_ExampleJobTriDexel)->Unit(benchmark::kMillisecond)->Iterations(1);

// The benchmark program's field: x 0..150, y within -6..6, from z 2 down 0.01 every 200 moves.
const base::Box3 kProgramStock = box({-5, -12, -50}, {160, 12, 2.5});

void BM_ProgramHeightField(benchmark::State& state)
{
    const sim::MoveList list = sim::buildMoves(bench::benchProgram(std::size_t(state.range(0))));
    simulate<sim::HeightField>(state, list, kProgramStock, 0.2);
    state.counters["program_moves"] = double(state.range(0));
}
BENCHMARK(BM_ProgramHeightField)->Arg(20000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1);

// Playing: the whole mesh of the example's stock, and one frame's update of a changed rectangle.
void BM_HeightFieldMesh(benchmark::State& state)
{
    sim::HeightField stock(box({-2, -2, 0}, {92, 62, 16}), 0.1);
    for (auto _ : state)
        benchmark::DoNotOptimize(stock.mesh());
    state.counters["triangles"] = double(stock.mesh().triangleCount());
}
BENCHMARK(BM_HeightFieldMesh)->Unit(benchmark::kMillisecond);

void BM_HeightFieldFrameUpdate(benchmark::State& state)
{
    static const sim::MoveList list = exampleMoves();
    sim::HeightField stock(box({-2, -2, 0}, {92, 62, 16}), 0.1);
    sim::TriangleMesh shown = stock.mesh();
    std::map<int, sim::ToolShape> shapes;
    for (const auto& [number, tool] : list.tools)
        shapes.emplace(number, sim::ToolShape(tool));
    std::size_t k = 0;
    for (auto _ : state) {  // one move per frame, then the mesh brought up to date
        const sim::Move& m = list.moves[k % list.moves.size()];
        if (const auto s = shapes.find(m.tool); s != shapes.end())
            stock.cut(m, k, s->second);
        stock.updateMesh(shown, stock.takeChanged());
        ++k;
    }
}
BENCHMARK(BM_HeightFieldFrameUpdate)->Unit(benchmark::kMicrosecond);

// The straight moves as "T <d> <kind> <corner> <angle>", "G0 x y z", "G1 x y z f" lines.
void writeMoves(const sim::MoveList& list, const std::string& path)
{
    std::ofstream out(path);
    int tool = -1;
    char line[160];
    for (const sim::Move& m : list.moves) {
        if (!m.moves())
            continue;
        if (m.tool != tool) {
            tool = m.tool;
            const toolpath::Tool* t = list.tool(tool);
            std::snprintf(line, sizeof line, "T %.4f %s %.4f %.4f %.4f\n", t->diameterMm, t->kind.c_str(),
                          t->cornerRadiusMm, t->pointAngleDeg, t->fluteLengthMm);
            out << line << "G0 " << m.from.x << ' ' << m.from.y << ' ' << m.from.z << '\n';
        }
        std::snprintf(line, sizeof line, "%s %.4f %.4f %.4f %.1f\n", m.kind == sim::MoveKind::Rapid ? "G0" : "G1",
                      m.to.x, m.to.y, m.to.z, m.feedMmPerMin);
        out << line;
    }
}

}  // namespace

int main(int argc, char** argv)
{
    if (const char* dir = std::getenv("CAMWB_SIM_BENCH_MOVES")) {
        writeMoves(exampleMoves(), std::string(dir) + "/example-block.moves");
        writeMoves(sim::buildMoves(bench::benchProgram(20000)), std::string(dir) + "/program-20000.moves");
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
