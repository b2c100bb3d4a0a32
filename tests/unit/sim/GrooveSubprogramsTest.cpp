// The mode-B groove subprograms (posts/sinumerik840d-turn/groove, docs/groove-strategy.md F1..F6, seed-001
// REQ-21) run by the SINUMERIK interpreter from a main program as the post writes it, checked
// move for move against the reconstructed thesis programs for Kod 1 and by the turning check
// (no gouge of the offset contour, no rapid through stock) on the seed's defect sets.
#include "GrooveSubprogramsSupport.h"

#include <algorithm>
#include <fstream>

namespace camwb::sim::groove_test {
namespace {

std::string baseName(const std::string& path)
{
    const auto slash = path.find_last_of('/');
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return name.substr(0, name.find('.'));
}

// The subprograms in the order their moves come (a name once per run of moves).
std::vector<std::string> calls(const GrooveRun& r)
{
    std::vector<std::string> out;
    int last = -1;
    for (const Move& m : subprogramMoves(r))
        if (m.file != last) {
            last = m.file;
            out.push_back(baseName(r.result.files[static_cast<std::size_t>(m.file)]));
        }
    return out;
}

// Clean by the turning check, no diagnostics, and the groove ends with the bottom phase
// `bottom`: its final retract G0 X=R0+100 is the last move, no sweep after it (F4).
void expectFinishedClean(const GrooveRun& r, const Inputs& in, const std::string& bottom)
{
    EXPECT_TRUE(r.result.completed);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics();
    const TurningReport report = check(r, in);
    EXPECT_EQ(report.gouges, 0u) << "max gouge " << report.maxGougeMm;
    EXPECT_EQ(report.rapidsInStock, 0u) << "max rapid depth " << report.maxRapidDepthMm;
    const std::vector<Move> moves = subprogramMoves(r);
    ASSERT_FALSE(moves.empty());
    EXPECT_TRUE(moves.back().rapid);
    EXPECT_NEAR(moves.back().x, in.r0 + 100, 1e-9);
    const std::vector<std::string> c = calls(r);
    EXPECT_EQ(c.back(), bottom);
    EXPECT_EQ(std::count(c.begin(), c.end(), bottom), 1);
    EXPECT_EQ(std::count_if(c.begin(), c.end(), [](const std::string& n) { return n.starts_with("PODPROG_DNO"); }), 1);
}

// REQ-21: what the control needs of the files themselves: PROC with the file's name, M17 at the
// end, one block per line with balanced parentheses, G0 (never GO), `=` before every expression
// value of an axis, plain ASCII.
TEST(GrooveSubprograms, FilesAreWrittenAsTheControlReadsThem)
{
    for (const std::string name : {"PODPROG_ZAPICH", "PODPROG_ZL", "PODPROG_ZP", "PODPROG_DNO_ZL", "PODPROG_DNO_ZP"}) {
        SCOPED_TRACE(name);
        std::ifstream file(grooveDir() + "/" + name + ".SPF", std::ios::binary);
        ASSERT_TRUE(file) << grooveDir();
        std::vector<std::string> lines;
        for (std::string line; std::getline(file, line);)
            lines.push_back(line);
        ASSERT_GT(lines.size(), 2u);
        EXPECT_EQ(lines.front(), "PROC " + name);
        EXPECT_EQ(lines.back(), "M17");
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string& text = lines[i];
            SCOPED_TRACE("line " + std::to_string(i + 1) + ": " + text);
            EXPECT_TRUE(std::all_of(text.begin(), text.end(), [](char c) { return c >= 32 && c < 127; }));
            std::string code = text.substr(0, text.find(';'));
            if (const auto quote = code.find('"'); quote != std::string::npos)
                code.erase(quote, code.rfind('"') - quote + 1);  // MSG text
            int depth = 0;
            for (const char c : code) {
                depth += c == '(' ? 1 : c == ')' ? -1 : 0;
                EXPECT_GE(depth, 0);
            }
            EXPECT_EQ(depth, 0);
            for (std::size_t at = 0; at + 1 < code.size(); ++at) {
                const bool wordStart = at == 0 || code[at - 1] == ' ';
                if (wordStart && code.compare(at, 3, "GO ") == 0)
                    ADD_FAILURE() << "GO for G0";
                if (wordStart && (code[at] == 'X' || code[at] == 'Z') && code[at + 1] != '=')
                    ADD_FAILURE() << "axis value without '='";
            }
        }
    }
}

// Kod 1 gives the reconstructed thesis programs' 574 moves: same G0/G1, X and Z within 1e-4 mm
// (seed REQ-14; the fixes change nothing where the thesis' program was right).
TEST(GrooveSubprograms, Kod1IsTheThesisProgramMoveForMove)
{
    const GrooveRun ours = runGroove({});
    EXPECT_TRUE(ours.result.completed);
    EXPECT_TRUE(ours.result.diagnostics.empty()) << ours.diagnostics();
    std::string kod5 = "G54 G18\nG90 G71\nG0 X380\nT=5 D1\nG96 S300 LIMS=3000 M3 M8\nG95 F0.2\nPODPROG_ZAPICH\nM30\n";
    const GrooveRun thesis = interpretText(kod5, seedDir() + "/reconstructed");
    ASSERT_TRUE(thesis.result.completed) << thesis.diagnostics();
    const std::vector<Move> a = subprogramMoves(ours), b = subprogramMoves(thesis);
    ASSERT_EQ(b.size(), 574u);
    ASSERT_EQ(a.size(), b.size());
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].rapid, b[i].rapid) << "move " << i;
        worst = std::max({worst, std::abs(a[i].x - b[i].x), std::abs(a[i].z - b[i].z)});
        EXPECT_NEAR(a[i].x, b[i].x, 1e-4) << "move " << i << " line " << a[i].line;
        EXPECT_NEAR(a[i].z, b[i].z, 1e-4) << "move " << i << " line " << a[i].line;
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(calls(ours),
              (std::vector<std::string>{"PODPROG_ZAPICH", "PODPROG_ZL", "PODPROG_ZP", "PODPROG_ZL", "PODPROG_ZP",
                                        "PODPROG_ZL", "PODPROG_ZP", "PODPROG_ZL", "PODPROG_DNO_ZL"}));
    expectFinishedClean(ours, {}, "PODPROG_DNO_ZL");
}

// The thesis' closed forms (seed §2.5: Rov. 7, 9, 20-23, 31-33, 43-46, 54-55), only defined for
// R2, R5, R6 > 0: T, U, R, S as (X, Z), and H1.
struct ClosedForms {
    double tx, tz, ux, uz, rx, rz, sx, sz, h1;
};
ClosedForms closedForms(const Inputs& in)
{
    const auto tanD = [](double deg) { return std::tan(deg * std::numbers::pi / 180); };
    const auto cosD = [](double deg) { return std::cos(deg * std::numbers::pi / 180); };
    const double t2 = tanD(in.r2), t5 = tanD(in.r5), t6 = tanD(in.r6);
    const double d = in.r3 * t5, c = (in.r3 - t2 * (in.r4 + in.r3 * t5)) / (t2 + 1 / t6), h1 = in.r3 - c / t6;
    const double dRx = (in.r8 * tanD(in.r2 - in.r6) + in.r8 * t6) * cosD(in.r6);
    const double dUx = (in.r8 * tanD(in.r2 + in.r5) - in.r8 * t5) * cosD(in.r5);
    const double xb = in.r0 - in.r3 + in.r7;
    return {xb,
            in.r1 - d - (in.r8 / cosD(in.r5) - in.r7 * t5),
            in.r0 - dUx,
            in.r1 - dUx / t2,
            in.r0 - h1 + dRx,
            in.r1 - d - in.r4 - c + dRx / t2,
            xb,
            in.r1 - d - in.r4 + in.r8 / cosD(in.r6) - in.r7 * t6,
            h1};
}

// F1: the offset corners T, U, R, S and H1 the subprograms compute by line intersections equal
// the thesis' closed forms to 1e-9 wherever those exist (R2, R5, R6 > 0). The main program moves
// to them after the call, so the moves show the R parameters.
TEST(GrooveSubprograms, GeneralIntersectionsEqualTheClosedForms)
{
    const std::string show = "G0 X=R14 Z=R15\nG0 X=R16 Z=R17\nG0 X=R23 Z=R24\nG0 X=R25 Z=R26\nG0 X=R38\n";
    for (const Inputs in : {Inputs{}, Inputs{350, 500, 12, 60, 40, 5, 9, 0.5, 0.5, 10, 0.8, 2, 1},
                            Inputs{350, 500, 29, 110, 70, 14, 1.5, 0.3, 0.7, 5, 0.6, 1, 1}}) {
        const GrooveRun r = runGroove(in, show);
        ASSERT_TRUE(r.result.completed) << r.diagnostics();
        std::vector<toolpath::Vec3> at;
        for (std::size_t i = 0; i < r.path.size(); ++i)
            if (const auto* m = std::get_if<toolpath::Rapid>(&r.path.record(i)); m && r.path.source(i).file == 0)
                at.push_back(m->to);
        ASSERT_GE(at.size(), 5u);
        at.erase(at.begin(), at.end() - 5);
        const ClosedForms f = closedForms(in);
        const double expected[4][2] = {{f.tx, f.tz}, {f.ux, f.uz}, {f.rx, f.rz}, {f.sx, f.sz}};
        for (int i = 0; i < 4; ++i) {
            EXPECT_NEAR(at[i].x, expected[i][0], 1e-9) << i;
            EXPECT_NEAR(at[i].z, expected[i][1], 1e-9) << i;
        }
        EXPECT_NEAR(at[4].x, f.h1, 1e-9);  // R38 = H1
    }
}

// Seed §5.3 item 1 (issue 17's 25.4994 mm gouge): Kod 1 with R3 = 160 ends through the bottom
// phase after a right-to-left sweep; with F2 (left corner) and F3 (clamp) it is clean.
TEST(GrooveSubprograms, Kod1DeeperEndsThroughDnoZpClean)
{
    Inputs in;
    in.r3 = 160;
    const GrooveRun r = runGroove(in);
    expectFinishedClean(r, in, "PODPROG_DNO_ZP");
    // R3 = 150 and 155 end there too (the seed: clean with the F2 fix).
    for (const double depth : {150.0, 155.0}) {
        in.r3 = depth;
        expectFinishedClean(runGroove(in), in, "PODPROG_DNO_ZP");
    }
}

// Seed §5.3 item 2: Kod 1 with R11 = 2 and R3 = 158 started the final sweep 5.83 mm past the flank.
TEST(GrooveSubprograms, HalfStepStartIsClamped)
{
    Inputs in;
    in.r11 = 2;
    in.r3 = 158;
    const GrooveRun r = runGroove(in);
    const std::vector<std::string> c = calls(r);
    ASSERT_FALSE(c.empty());
    expectFinishedClean(r, in, c.back());
    EXPECT_TRUE(c.back().starts_with("PODPROG_DNO_"));
}

// Seed §5.3 item 3 ran forever: the groove is too narrow for a sweep to go deeper (F5): alarm
// 65010 with its message, the program stops, what ran before is clean.
TEST(GrooveSubprograms, NarrowGrooveStopsWithAlarm65010)
{
    const Inputs in{350, 500, 20.899, 37.27, 44.84, 4.844, 9.585, 0.5, 0.5, 23.2, 1.0, 2, 1};
    const GrooveRun r = runGroove(in);
    std::string message;
    EXPECT_EQ(r.alarm(&message), 65010) << r.diagnostics();
    EXPECT_NE(message.find("too narrow"), std::string::npos) << message;
    EXPECT_NE(message.find("PODPROG_ZAPICH"), std::string::npos) << r.diagnostics();
    EXPECT_FALSE(r.result.completed);
    EXPECT_LT(r.result.blocksExecuted, 100'000);
    const TurningReport report = check(r, in);
    EXPECT_EQ(report.gouges, 0u);
    EXPECT_EQ(report.rapidsInStock, 0u);
}

// Seed §5.3 item 4: after DNO_ZL had finished, the thesis' loop ran ZP and DNO_ZP again (60.26 mm
// gouge). F4: the groove ends with the bottom phase.
TEST(GrooveSubprograms, NoSweepAfterTheBottomPhase)
{
    const Inputs in{350, 500, 10, 60, 40, 5, 5, 0.5, 0.5, 10, 0.8, 2, 1};
    const GrooveRun r = runGroove(in);
    expectFinishedClean(r, in, "PODPROG_DNO_ZL");
}

// Seed §5.3 item 5: the left flank offset meets the surface below the bottom offset: F6 alarm.
TEST(GrooveSubprograms, DegenerateLeftFlankIsAnInputAlarm)
{
    const Inputs in{350, 500, 24.295, 30.29, 64.26, 9.73, 13.055, 0.5, 0.5, 10, 1.0, 1, 1};
    const GrooveRun r = runGroove(in);
    std::string message;
    EXPECT_EQ(r.alarm(&message), 65014) << r.diagnostics();
    EXPECT_NE(message.find("Rx<=Sx"), std::string::npos) << message;
    EXPECT_TRUE(subprogramMoves(r).empty());
}

// Seed §5.3 item 6 (REQ-04): a cylinder (R2 = 0), a radial right or left flank (R5 = 0, R6 = 0)
// and all three together run clean.
TEST(GrooveSubprograms, ZeroAnglesRunClean)
{
    for (const auto& [r2, r5, r6] :
         {std::tuple{0.0, 6.71, 4.09}, {21.801, 0.0, 4.09}, {21.801, 6.71, 0.0}, {0.0, 0.0, 0.0}, {0.0, 6.71, 0.0}}) {
        SCOPED_TRACE("R2=" + number(r2) + " R5=" + number(r5) + " R6=" + number(r6));
        Inputs in;
        in.r2 = r2;
        in.r5 = r5;
        in.r6 = r6;
        const GrooveRun r = runGroove(in);
        const std::vector<std::string> c = calls(r);
        ASSERT_FALSE(c.empty()) << r.diagnostics();
        expectFinishedClean(r, in, c.back());
    }
}

// F6 (REQ-06): each invalid input stops before any move with its own alarm and a message naming
// the parameter.
TEST(GrooveSubprograms, EachInvalidInputHasItsAlarm)
{
    struct Case {
        void (*set)(Inputs&);
        int alarm;
        const char* names;
    };
    const Case cases[] = {
        {[](Inputs& i) { i.r9 = 0; }, 65001, "R9"},
        {[](Inputs& i) { i.r11 = -1; }, 65002, "R11"},
        {[](Inputs& i) { i.r10 = 0; }, 65003, "R10"},
        {[](Inputs& i) { i.r10 = 1.2; }, 65003, "R10"},
        {[](Inputs& i) { i.r30 = -0.1; }, 65004, "R30"},
        {[](Inputs& i) { i.r7 = -0.5; }, 65005, "R7"},
        {[](Inputs& i) { i.r8 = -0.5; }, 65006, "R8"},
        {[](Inputs& i) { i.r3 = 0; }, 65007, "R3"},
        {[](Inputs& i) { i.r4 = 0; }, 65008, "R4"},
        {[](Inputs& i) { i.r2 = -5; }, 65009, "R2"},
        {[](Inputs& i) { i.r2 = 90; }, 65009, "R2"},
        {[](Inputs& i) { i.r5 = 90; }, 65011, "R5"},
        {[](Inputs& i) { i.r6 = -1; }, 65012, "R6"},
        {[](Inputs& i) { i.r2 = 60, i.r5 = 30; }, 65013, "R2 plus right flank angle R5"},
        {[](Inputs& i) {
             i.r3 = 30.29, i.r0 = 350, i.r1 = 500, i.r2 = 24.295, i.r4 = 64.26, i.r5 = 9.73, i.r6 = 13.055;
         },
         65014, "Rx<=Sx"},
        {[](Inputs& i) { i.r2 = 50, i.r3 = 9, i.r4 = 7, i.r5 = 17, i.r6 = 25, i.r7 = 2, i.r8 = 4.5; }, 65015, "Ux<=Tx"},
        {[](Inputs& i) { i.r9 = 44.5; }, 65016, "R9"},
        // docs/groove-strategy.md V1: 3 mm deeper every 0.96 mm is steeper than a 30 (25.8) degree flank
        {[](Inputs& i) { i.r5 = 30, i.r10 = 0.32, i.r11 = 3; }, 65017, "right flank angle R5"},
        {[](Inputs& i) { i.r6 = 25.8, i.r10 = 0.32, i.r11 = 3; }, 65018, "left flank angle R6"},
    };
    for (const Case& c : cases) {
        Inputs in;
        c.set(in);
        const GrooveRun r = runGroove(in);
        std::string message;
        EXPECT_EQ(r.alarm(&message), c.alarm) << r.diagnostics();
        EXPECT_NE(message.find(c.names), std::string::npos) << message;
        EXPECT_NE(message.find("PODPROG_ZAPICH.SPF:"), std::string::npos) << r.diagnostics();
        EXPECT_TRUE(subprogramMoves(r).empty()) << c.alarm;
        EXPECT_FALSE(r.result.completed);
        EXPECT_EQ(r.result.diagnostics.size(), 1u) << r.diagnostics();
    }
}

// docs/groove-strategy.md G3 (found here as P1): the sweep's WHILE stops where the next plunge would cut
// the flank, and the flank plunge at the last depth can lie up to tan(R6)*R11 further left than
// one step, over the previous sweep's floor one R11 higher: the rapid at the last plunge's
// retract height ran R11 - R30 = 0.338 mm into it (ZP, G0 Z=R40). Now it rises first.
TEST(GrooveSubprograms, FlankPlungeRapidRisesOverTheStaircase)
{
    const Inputs in{350,
                    500,
                    19.450787599006137,
                    109.20346823480213,
                    20.925334640176771,
                    0.55958420042085733,
                    27.774028049448908,
                    1.4435233532303937,
                    1.260313149129181,
                    5,
                    0.51402154517747134,
                    1,
                    0.66202555505687255};
    const GrooveRun r = runGroove(in);
    const std::vector<std::string> c = calls(r);
    ASSERT_FALSE(c.empty()) << r.diagnostics();
    expectFinishedClean(r, in, c.back());
}

// docs/groove-strategy.md G3, G5 with no safety distance at all, on steep flanks and cones: the first
// pass' clean-up rapids and the flank plunges' rapids only touch (R30 = 0, seed §2.2).
TEST(GrooveSubprograms, NoSafetyDistanceOnSteepFlanksOnlyTouches)
{
    for (Inputs in : sweepCases(60, Sweep::Wider)) {
        in.r30 = 0;
        SCOPED_TRACE(describe(in));
        const GrooveRun r = runGroove(in);
        if (r.alarm())
            continue;
        const TurningReport report = check(r, in);
        EXPECT_EQ(report.gouges, 0u) << report.maxGougeMm;
        EXPECT_EQ(report.rapidsInStock, 0u) << report.maxRapidDepthMm;
    }
}

}  // namespace
}  // namespace camwb::sim::groove_test
