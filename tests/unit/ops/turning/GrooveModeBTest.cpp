// Seed REQ-22: the two output modes of the groove give the same toolpath. Mode A is
// ops::computeGroove's moves; mode B is the post's subprograms (posts/sinumerik840d-turn/groove)
// called from a main program with the input block, read by the SINUMERIK interpreter. Compared
// move by move (G0/G1, X and Z within 1e-4 mm) for Kod 1, the spec's defect sets and a random
// sweep; where the op takes its narrow-groove fallback, mode B stops with alarm 65010 instead,
// and where the op refuses the inputs, mode B stops with an input alarm.
#include "../../sim/GrooveSubprogramsSupport.h"
#include "GrooveTestUtil.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace camwb::ops::test {
namespace {

using sim::groove_test::GrooveRun;
using sim::groove_test::Inputs;

GrooveParams paramsOf(const Inputs& in)
{
    GrooveParams p;
    p.groove = sim::groove_test::grooveParameters(in);
    p.stepFactor = in.r10;
    p.infeedMm = in.r11;
    p.safetyMm = in.r30;
    return p;
}

struct Comparison {
    std::size_t moves = 0;
    double worst = 0;  // largest X or Z difference
};

// Mode A's moves after its first rapid (to X = R0 + 100, where the main program parks at R0 + 200)
// against mode B's subprogram moves; the first move's X is the caller's and is not compared.
Comparison expectSameMoves(const OpResult& a, const GrooveRun& b)
{
    std::vector<ResolvedMove> op = resolvedMoves(a.toolpath);
    const std::vector<ResolvedMove> nc = resolvedMoves(b.path, [](const toolpath::SourceRef& s) { return s.file > 0; });
    Comparison c;
    if (op.empty()) {
        ADD_FAILURE() << "mode A has no moves";
        return c;
    }
    op.erase(op.begin());
    EXPECT_EQ(op.size(), nc.size());
    c.moves = std::min(op.size(), nc.size());
    for (std::size_t k = 0; k < c.moves; ++k) {
        const double dx = k > 0 ? std::abs(op[k].x - nc[k].x) : 0, dz = std::abs(op[k].z - nc[k].z);
        c.worst = std::max({c.worst, dx, dz});
        if (op[k].rapid != nc[k].rapid || dx > 1e-4 || dz > 1e-4) {
            // One misaligned move makes all after it differ: report the first.
            ADD_FAILURE() << "move " << k << ": mode A " << (op[k].rapid ? "G0" : "G1") << " X" << op[k].x << " Z"
                          << op[k].z << ", mode B " << (nc[k].rapid ? "G0" : "G1") << " X" << nc[k].x << " Z"
                          << nc[k].z;
            break;
        }
    }
    return c;
}

bool fallbackOf(const OpResult& r)
{
    for (const auto& rec : r.toolpath.records())
        if (const auto* begin = std::get_if<toolpath::SectionBegin>(&rec))
            for (const auto& [name, value] : begin->strategyParameters)
                if (name == "fallback")
                    return value != 0;
    return false;
}

// One case: "same", "fallback" (op fallback = mode B alarm 65010) or "refused" (op error = mode B
// input alarm).
std::string compareCase(const Inputs& in, Comparison* out = nullptr)
{
    SCOPED_TRACE(sim::groove_test::describe(in));
    const auto a = computeGroove(paramsOf(in), grooveTool(in.r9), 0);
    const GrooveRun b = sim::groove_test::runGroove(in);
    const int alarm = b.alarm();
    if (!a.ok()) {
        EXPECT_NE(alarm, 0) << "mode A refused (" << a.error().message << "), mode B ran";
        EXPECT_NE(alarm, 65010) << a.error().message;
        return "refused";
    }
    if (fallbackOf(a.value())) {
        EXPECT_EQ(alarm, 65010) << b.diagnostics();
        return "fallback";
    }
    EXPECT_EQ(alarm, 0) << b.diagnostics();
    EXPECT_TRUE(b.result.diagnostics.empty()) << b.diagnostics();
    const Comparison c = expectSameMoves(a.value(), b);
    if (out)
        *out = c;
    return "same";
}

TEST(GrooveModeB, Req22Kod1)
{
    Comparison c;
    EXPECT_EQ(compareCase({}, &c), "same");
    EXPECT_EQ(c.moves, 574u);
    EXPECT_LT(c.worst, 1e-9);
}

// The spec's defect sets (seed §5.3 items 1-6) and the zero angles of F1.
TEST(GrooveModeB, Req22DefectSets)
{
    const auto with = [](auto change) {
        Inputs in;
        change(in);
        return in;
    };
    const std::pair<Inputs, const char*> cases[] = {
        {with([](Inputs& i) { i.r3 = 160; }), "same"},
        {with([](Inputs& i) { i.r3 = 150; }), "same"},
        {with([](Inputs& i) { i.r3 = 155; }), "same"},
        {with([](Inputs& i) { i.r11 = 2, i.r3 = 158; }), "same"},
        {with([](Inputs& i) { i.r10 = 1; }), "same"},
        {with([](Inputs& i) { i.r2 = 0; }), "same"},
        {with([](Inputs& i) { i.r5 = 0; }), "same"},
        {with([](Inputs& i) { i.r6 = 0; }), "same"},
        {with([](Inputs& i) { i.r2 = 0, i.r5 = 0, i.r6 = 0; }), "same"},
        {Inputs{350, 500, 20.899, 37.27, 44.84, 4.844, 9.585, 0.5, 0.5, 23.2, 1.0, 2, 1}, "fallback"},
        {Inputs{350, 500, 10, 60, 40, 5, 5, 0.5, 0.5, 10, 0.8, 2, 1}, "same"},
        {Inputs{350, 500, 24.295, 30.29, 64.26, 9.73, 13.055, 0.5, 0.5, 10, 1.0, 1, 1}, "refused"},
    };
    for (const auto& [in, expected] : cases)
        EXPECT_EQ(compareCase(in), expected) << sim::groove_test::describe(in);
}

void expectSameOverSweep(const std::vector<Inputs>& cases)
{
    std::map<std::string, int> outcomes;
    double worst = 0;
    for (const Inputs& in : cases) {
        Comparison c;
        ++outcomes[compareCase(in, &c)];
        worst = std::max(worst, c.worst);
    }
    std::printf("REQ-22 sweep: same %d, fallback %d, refused %d; worst difference %.3g mm\n", outcomes["same"],
                outcomes["fallback"], outcomes["refused"], worst);
    EXPECT_GE(outcomes["same"], static_cast<int>(cases.size()) * 3 / 5);
}

// The random sweeps of the subprogram tests (seed §5.3 item 8's ranges, zero angles and narrow
// grooves, wider ranges; fixed seeds).
TEST(GrooveModeB, Req22RandomSweep) { expectSameOverSweep(sim::groove_test::sweepCases(400)); }
TEST(GrooveModeB, Req22ZeroAnglesAndNarrowGrooves)
{
    expectSameOverSweep(sim::groove_test::sweepCases(400, sim::groove_test::Sweep::ZeroAnglesAndNarrow));
}
TEST(GrooveModeB, Req22WiderRanges)
{
    expectSameOverSweep(sim::groove_test::sweepCases(400, sim::groove_test::Sweep::Wider));
}

}  // namespace
}  // namespace camwb::ops::test
