// Helpers of the mode-B groove subprogram tests: a main program as the post writes it (Kod 5's
// frame, the input block R0..R11 R30, PODPROG_ZAPICH) run on posts/sinumerik840d-turn/groove,
// the turning check on the groove's stock and offset contour, the moves, and the random cases of
// the sweeps (seed §5.3 item 8's ranges).
#pragma once

#include "geom/RegionOps.h"
#include "nc/Interpreter.h"
#include "sim/TurningCheck.h"
#include "sim/TurningProfile.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace camwb::sim::groove_test {

// The thesis' inputs, Kod 1 by default.
struct Inputs {
    double r0 = 180, r1 = 185, r2 = 21.801, r3 = 170, r4 = 45, r5 = 6.71, r6 = 4.09, r7 = 0.5, r8 = 0.5, r9 = 3,
           r10 = 0.8, r11 = 1, r30 = 1;
};

inline std::string repoDir() { return CAMWB_TEST_DATA_DIR; }
inline std::string grooveDir() { return repoDir() + "/posts/sinumerik840d-turn/groove"; }
inline std::string seedDir() { return repoDir() + "/tests/data/nc/seed-001"; }

inline std::string number(double v)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

// The input block, Kod 5's frame and the call; `after` goes between the call and M30.
inline std::string mainProgram(const Inputs& in, const std::string& after = {})
{
    const double values[] = {in.r0, in.r1, in.r2, in.r3, in.r4, in.r5, in.r6, in.r7, in.r8, in.r9, in.r10, in.r11};
    std::string text = "; groove test: input block, Kod 5 frame, call\n";
    for (int i = 0; i < 12; ++i)
        text += "R" + std::to_string(i) + "=" + number(values[i]) + "\n";
    text += "R30=" + number(in.r30) + "\n";
    text += "G54 G18\nG90 G71\nG0 X=R0+200\nT=5 D1\nG96 S300 LIMS=3000 M3 M8\nG95 F0.2\nPODPROG_ZAPICH\n";
    return text + after + "M30\n";
}

struct GrooveRun {
    nc::InterpretResult result;
    toolpath::Toolpath path;

    std::string diagnostics() const
    {
        std::string out;
        for (const nc::Diagnostic& d : result.diagnostics)
            out += nc::formatDiagnostic(d) + '\n';
        return out;
    }
    // The alarm number of a SETAL error (0: none) and its diagnostic as file:line: message.
    int alarm(std::string* message = nullptr) const
    {
        for (const nc::Diagnostic& d : result.diagnostics) {
            const auto at = d.message.find("sets alarm ");
            if (at != std::string::npos) {
                if (message)
                    *message = nc::formatDiagnostic(d);
                return std::stoi(d.message.substr(at + 11));
            }
        }
        return 0;
    }
};

inline GrooveRun interpretText(const std::string& text, const std::string& folder, std::int64_t maxBlocks = 2'000'000)
{
    nc::InterpretOptions options;
    options.dialect = nc::Dialect::Sinumerik;
    options.fileName = "GROOVE.MPF";
    options.resolveProgram = nc::folderResolver(folder, {".SPF"});
    options.maxBlocks = maxBlocks;
    toolpath::ToolpathRecorder recorder;
    GrooveRun r;
    r.result = nc::interpret(text, options, recorder);
    r.path = recorder.take();
    return r;
}

inline GrooveRun runGroove(const Inputs& in, const std::string& after = {})
{
    return interpretText(mainProgram(in, after), grooveDir());
}

struct Move {
    bool rapid = false;
    double x = 0, z = 0;
    int file = 0, line = 0;
};

// The moves the subprograms make (file index > 0), in order.
inline std::vector<Move> subprogramMoves(const GrooveRun& r)
{
    std::vector<Move> out;
    for (std::size_t i = 0; i < r.path.size(); ++i) {
        const toolpath::SourceRef& source = r.path.source(i);
        if (source.file <= 0)
            continue;
        const auto& rec = r.path.record(i);
        if (const auto* m = std::get_if<toolpath::Rapid>(&rec))
            out.push_back({true, m->to.x, m->to.z, source.file, source.line});
        else if (const auto* l = std::get_if<toolpath::Linear>(&rec))
            out.push_back({false, l->to.x, l->to.z, source.file, source.line});
    }
    return out;
}

inline GrooveParameters grooveParameters(const Inputs& in)
{
    return {in.r0, in.r1, in.r2, in.r3, in.r4, in.r5, in.r6, in.r7, in.r8, in.r9};
}

inline TurningReport check(const GrooveRun& r, const Inputs& in)
{
    TurningOptions options;
    options.insert.widthMm = in.r9;
    return checkTurning(r.path, grooveStock(grooveParameters(in)), grooveOffsetPart(grooveParameters(in)), options);
}

// splitmix64: the same numbers on every platform (std distributions are not specified exactly).
class Random {
public:
    explicit Random(std::uint64_t seed) : m_state(seed) {}
    double uniform(double a, double b) { return a + (b - a) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
    template <typename T, std::size_t N> T pick(const T (&values)[N]) { return values[next() % N]; }

private:
    std::uint64_t next()
    {
        std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    std::uint64_t m_state;
};

// Which random grooves: the ranges of seed-001 §5.3 item 8; the same with each of R2, R5, R6 = 0
// in a third of the cases (docs/groove-strategy.md F1) and every fourth groove's offset bottom only 1.0 to
// 1.8 insert widths wide (F5); wider ranges (steeper cones and flanks, other allowances, R10
// anywhere in range), as the op's property tests have them.
enum class Sweep { Seed, ZeroAnglesAndNarrow, Wider };

inline std::vector<Inputs> sweepCases(int count, Sweep kind = Sweep::Seed)
{
    Random random(kind == Sweep::Seed ? 17 : kind == Sweep::Wider ? 41 : 29);
    const double widths[] = {3, 5, 10, 23.2}, steps[] = {0.5, 0.6, 0.8, 1.0}, infeeds[] = {0.5, 1, 2, 3};
    std::vector<Inputs> out;
    for (int i = 0; i < count; ++i) {
        Inputs in;
        in.r0 = 350;
        in.r1 = 500;
        in.r2 = random.uniform(3, 30);
        in.r3 = random.uniform(20, 120);
        in.r9 = random.pick(widths);
        in.r4 = random.uniform(1.5 * in.r9, 80);
        in.r5 = random.uniform(1, 15);
        in.r6 = random.uniform(1, 15);
        in.r7 = in.r8 = 0.5;
        in.r10 = random.pick(steps);
        in.r11 = random.pick(infeeds);
        in.r30 = 1;
        if (kind == Sweep::ZeroAnglesAndNarrow) {
            const double keep[] = {0, 1, 1};
            in.r2 *= random.pick(keep);
            in.r5 *= random.pick(keep);
            in.r6 *= random.pick(keep);
            if (i % 4 == 3)
                in.r4 = in.r9 * random.uniform(1.0, 1.8) + 1.2;
        } else if (kind == Sweep::Wider) {
            in.r3 = random.uniform(50, 120);
            in.r2 = random.uniform(0, 40);
            in.r5 = random.uniform(0, 30);
            in.r6 = random.uniform(0, 30);
            in.r7 = random.uniform(0, 2);
            in.r8 = random.uniform(0, 2);
            in.r30 = random.uniform(0, 2);
            in.r10 = random.uniform(0.3, 1);
        }
        out.push_back(in);
    }
    return out;
}

inline std::string describe(const Inputs& in)
{
    return "R0=" + number(in.r0) + " R1=" + number(in.r1) + " R2=" + number(in.r2) + " R3=" + number(in.r3) +
           " R4=" + number(in.r4) + " R5=" + number(in.r5) + " R6=" + number(in.r6) + " R7=" + number(in.r7) +
           " R8=" + number(in.r8) + " R9=" + number(in.r9) + " R10=" + number(in.r10) + " R11=" + number(in.r11) +
           " R30=" + number(in.r30);
}

}  // namespace camwb::sim::groove_test
