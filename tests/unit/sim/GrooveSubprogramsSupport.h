// Helpers of the mode-B groove subprogram tests: a main program as the post writes it (Kod 5's
// frame, the input block R0..R11 R30, PODPROG_ZAPICH) run on posts/sinumerik840d-turn/groove,
// the groove's stock and offset contour for the turning check (general intersections, so R2 = 0
// and R6 = 0 work too: sim::grooveGeometry has the thesis' closed forms), and the moves.
#pragma once

#include "geom/RegionOps.h"
#include "nc/Interpreter.h"
#include "sim/TurningCheck.h"
#include "sim/TurningProfile.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
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

// The groove's corners (X, Z) by general line intersections (groove-spec F1).
struct Contour {
    double sx, sz, tx, tz, ux, uz, rx, rz, c1x, c1z;
};

inline Contour contour(const Inputs& in)
{
    const auto rad = [](double deg) { return deg * std::numbers::pi / 180; };
    const double t2 = std::tan(rad(in.r2)), t5 = std::tan(rad(in.r5)), t6 = std::tan(rad(in.r6));
    Contour c;
    c.sx = c.tx = in.r0 - in.r3 + in.r7;
    c.tz = in.r1 - in.r3 * t5 - (in.r8 / std::cos(rad(in.r5)) - in.r7 * t5);
    c.sz = in.r1 - in.r3 * t5 - in.r4 + in.r8 / std::cos(rad(in.r6)) - in.r7 * t6;
    c.ux = (in.r0 + (c.tz - in.r1 - t5 * c.tx) * t2) / (1 - t2 * t5);
    c.uz = c.tz + t5 * (c.ux - c.tx);
    c.rx = (in.r0 + (c.sz + t6 * c.sx - in.r1) * t2) / (1 + t2 * t6);
    c.rz = c.sz - t6 * (c.rx - c.sx);
    const double blz = in.r1 - in.r3 * t5 - in.r4, blx = in.r0 - in.r3;
    c.c1x = (in.r0 + (blz + t6 * blx - in.r1) * t2) / (1 + t2 * t6);
    c.c1z = blz - t6 * (c.c1x - blx);
    return c;
}

// The shaft (margin beyond C1 and P) and the part that must stay: the shaft less the offset groove.
inline TurningRegion shaft(const Inputs& in, bool withGroove, double margin = 20)
{
    const Contour c = contour(in);
    const double t2 = std::tan(in.r2 * std::numbers::pi / 180);
    const double zl = c.c1z - margin, zr = in.r1 + margin;
    const auto surface = [&](double z) { return in.r0 + (z - in.r1) * t2; };
    std::string points = number(surface(zl)) + "," + number(zl) + "\n";
    if (withGroove)
        for (const auto& [x, z] : {std::pair{c.rx, c.rz}, {c.sx, c.sz}, {c.tx, c.tz}, {c.ux, c.uz}})
            points += number(x) + "," + number(z) + "\n";
    points += number(surface(zr)) + "," + number(zr) + "\n";
    auto region = parseProfilePoints(points, "groove");
    EXPECT_TRUE(region.ok()) << region.error().toString();
    return region ? region.value() : TurningRegion{};
}

inline TurningReport check(const GrooveRun& r, const Inputs& in)
{
    TurningOptions options;
    options.insert.widthMm = in.r9;
    return checkTurning(r.path, shaft(in, false), shaft(in, true), options);
}

}  // namespace camwb::sim::groove_test
