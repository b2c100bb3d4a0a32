// Property tests of the groove roughing on the turning stock (seed REQ-15..18, spec F1-F6): on
// random grooves of the seed's sweep (§5.3 item 8) and on cylinders, vertical flanks and narrow
// grooves, every path terminates, cuts nothing of the offset contour, never rapids through stock,
// moves its rapids along one axis and leaves nothing above the offset contour; the defect sets of
// seed §5.3 items 1-5; every input check with its message.
#include "GrooveTestUtil.h"
#include "geom/RegionOps.h"
#include "ops/turning/GrooveSweeps.h"
#include "sim/TurningCheck.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>

namespace camwb::ops::test {
namespace {

// The checker's tolerance: cuts shallower than this are touching, not a gouge or a rapid hit.
constexpr double kToleranceMm = 1e-3;
constexpr double kLeftoverMm = 0.01;  // seed REQ-15 d, for R10 <= 1

struct Case {
    sim::GrooveParameters g;
    double r10 = 0.8, r11 = 1, r30 = 1;
};

std::string describe(const Case& c)
{
    const auto& g = c.g;
    std::ostringstream s;
    s.precision(17);
    s << "R0=" << g.r0 << " R1=" << g.r1 << " R2=" << g.r2 << " R3=" << g.r3 << " R4=" << g.r4 << " R5=" << g.r5
      << " R6=" << g.r6 << " R7=" << g.r7 << " R8=" << g.r8 << " R9=" << g.r9 << " R10=" << c.r10 << " R11=" << c.r11
      << " R30=" << c.r30;
    return s.str();
}

base::Result<OpResult> run(const Case& c)
{
    GrooveParams p;
    p.groove = c.g;
    p.stepFactor = c.r10;
    p.infeedMm = c.r11;
    p.safetyMm = c.r30;
    return computeGroove(p, grooveTool(c.g.r9), 0);
}

struct Verdict {
    bool error = false;
    std::string message;
    bool fallback = false;
    double gougeMm = 0, rapidMm = 0, leftoverMm = 0;
    std::size_t moves = 0;
};

// Computes and simulates one case; the failures are reported by gtest (with the case).
Verdict check(const Case& c)
{
    Verdict v;
    SCOPED_TRACE(describe(c));
    auto computed = run(c);
    if (!computed) {
        v.error = true;
        v.message = computed.error().message;
        return v;
    }
    const toolpath::Toolpath& path = computed->toolpath;
    for (const auto& r : path.records())
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            EXPECT_TRUE(rapid->axes.bits == toolpath::AxisMask::kX || rapid->axes.bits == toolpath::AxisMask::kZ)
                << "a rapid along more than one axis";
        } else if (const auto* line = std::get_if<toolpath::Linear>(&r)) {
            EXPECT_EQ(line->axes.bits, toolpath::AxisMask::kX | toolpath::AxisMask::kZ);
        }
    const auto& params = std::get<toolpath::SectionBegin>(path.record(0)).strategyParameters;
    v.fallback = params.back().second == 1;
    sim::TurningOptions options;
    options.insert.widthMm = c.g.r9;
    options.toleranceMm = kToleranceMm;
    const sim::TurningRegion part = sim::grooveOffsetPart(c.g);
    const sim::TurningReport r = sim::checkTurning(path, sim::grooveStock(c.g), part, options);
    v.moves = r.moves;
    v.gougeMm = r.maxGougeMm;
    v.rapidMm = r.maxRapidDepthMm;
    v.leftoverMm = r.maxLeftoverMm;
    const base::Vec2 at = r.maxLeftoverAt;
    EXPECT_EQ(r.gouges, 0u) << "gouge " << r.maxGougeMm << " at Z " << r.maxGougeAt.x << " X " << r.maxGougeAt.y;
    EXPECT_EQ(r.rapidsInStock, 0u) << "rapid " << r.maxRapidDepthMm << " into stock";
    EXPECT_LE(v.leftoverMm, kLeftoverMm) << "left over at Z " << at.x << " X " << at.y;
    return v;
}

Case kod1() { return {}; }

// The seed's random sweep (§5.3 item 8) with its own generator: std::mt19937 and explicit
// uniform maps, so the cases are the same on every platform.
class Sweep {
public:
    explicit Sweep(unsigned seed) : m_rng(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * (m_rng() / 4294967296.0); }
    template <std::size_t N> double pick(const double (&values)[N]) { return values[m_rng() % N]; }

    Case next()
    {
        static const double r9s[] = {3, 5, 10, 23.2}, r10s[] = {0.5, 0.6, 0.8, 1.0}, r11s[] = {0.5, 1, 2, 3};
        Case c;
        c.g.r0 = 350;
        c.g.r1 = 500;
        c.g.r9 = pick(r9s);
        c.g.r2 = uniform(3, 30);
        c.g.r3 = uniform(20, 120);
        c.g.r4 = uniform(1.5 * c.g.r9, 80);
        c.g.r5 = uniform(1, 15);
        c.g.r6 = uniform(1, 15);
        c.g.r7 = c.g.r8 = 0.5;
        c.r10 = pick(r10s);
        c.r11 = pick(r11s);
        c.r30 = 1;
        return c;
    }

private:
    std::mt19937 m_rng;
};

struct Tally {
    int cases = 0, errors = 0, fallbacks = 0;
    double gouge = 0, rapid = 0, leftover = 0;
    void add(const Verdict& v)
    {
        ++cases;
        errors += v.error;
        fallbacks += v.fallback;
        gouge = std::max(gouge, v.gougeMm);
        rapid = std::max(rapid, v.rapidMm);
        leftover = std::max(leftover, v.leftoverMm);
    }
    void print(const char* what) const
    {
        std::printf("%s: %d cases, %d input errors, %d fallbacks; max gouge %.2e, rapid %.2e, leftover %.2e mm\n", what,
                    cases, errors, fallbacks, gouge, rapid, leftover);
    }
};

TEST(GrooveProperties, SeedRandomSweepIsClean)
{
    Sweep sweep(1);
    Tally tally;
    for (int k = 0; k < 150; ++k) {
        const Case c = sweep.next();
        SCOPED_TRACE("case " + std::to_string(k));
        const Verdict v = check(c);
        if (v.error) {
            EXPECT_NE(v.message.find("(R"), std::string::npos) << v.message;
            std::printf("  case %d refused: %s\n", k, v.message.c_str());
        }
        tally.add(v);
    }
    tally.print("seed sweep");
    EXPECT_LE(tally.errors, 150 * 5 / 100);  // a generator that refuses everything must fail
}

// Cylinders (R2 = 0), vertical flanks (R5 = 0, R6 = 0) and grooves barely wider than the insert.
TEST(GrooveProperties, CylindersVerticalFlanksAndNarrowGroovesAreClean)
{
    Sweep sweep(2);
    Tally tally;
    for (int k = 0; k < 360; ++k) {
        Case c = sweep.next();
        switch (k % 6) {
        case 0:
            c.g.r2 = 0;
            break;
        case 1:
            c.g.r5 = 0;
            break;
        case 2:
            c.g.r6 = 0;
            break;
        case 3:
            c.g.r2 = c.g.r5 = c.g.r6 = 0;
            break;
        case 4:  // offset bottom 1.0 .. 1.8 insert widths
            c.g.r4 = c.g.r9 * sweep.uniform(1.0, 1.8) + 1.2;
            break;
        case 5:
            c.g.r2 = 0;
            c.g.r4 = c.g.r9 * sweep.uniform(1.0, 1.5) + 1.2;
            break;
        }
        SCOPED_TRACE("case " + std::to_string(k));
        const Verdict v = check(c);
        if (v.error)
            EXPECT_NE(v.message.find("(R"), std::string::npos) << v.message;
        tally.add(v);
    }
    tally.print("R2/R5/R6 = 0 and narrow");
    EXPECT_LE(tally.errors, 360 * 5 / 100);
    EXPECT_GT(tally.fallbacks, 0);
}

// Beyond the seed's ranges: steeper cones and flanks, other allowances, no safety distance.
TEST(GrooveProperties, WiderRangesAreClean)
{
    Sweep sweep(3);
    Tally tally;
    for (int k = 0; k < 450; ++k) {
        Case c = sweep.next();
        c.g.r3 = sweep.uniform(50, 120);  // shallower ones are mostly refused (Rx <= Sx) at these cones
        c.g.r2 = sweep.uniform(0, 40);
        c.g.r5 = sweep.uniform(0, 30);
        c.g.r6 = sweep.uniform(0, 30);
        c.g.r7 = sweep.uniform(0, 2);
        c.g.r8 = sweep.uniform(0, 2);
        c.r30 = sweep.uniform(0, 2);
        c.r10 = sweep.uniform(0.3, 1);
        if (k % 5 == 0)  // no allowances and no safety distance: the rapids touch, never cut
            c.g.r7 = c.g.r8 = c.r30 = 0;
        SCOPED_TRACE("case " + std::to_string(k));
        const Verdict v = check(c);
        if (v.error) {
            EXPECT_NE(v.message.find("(R"), std::string::npos) << v.message;
            std::printf("  case %d refused: %s\n", k, v.message.c_str());
        }
        tally.add(v);
    }
    tally.print("wider ranges");
    EXPECT_LE(tally.errors, 450 * 5 / 100);
}

TEST(GrooveProperties, Kod1AndItsCylinderAndVerticalFlanksAreClean)
{
    const Verdict v = check(kod1());
    EXPECT_FALSE(v.error) << v.message;
    for (auto set : {+[](Case& c) { c.g.r2 = 0; }, +[](Case& c) { c.g.r5 = 0; }, +[](Case& c) { c.g.r6 = 0; },
                     +[](Case& c) { c.g.r2 = c.g.r5 = c.g.r6 = 0; }}) {
        Case c = kod1();
        set(c);
        SCOPED_TRACE(describe(c));
        const Verdict w = check(c);
        EXPECT_FALSE(w.error) << w.message;
        EXPECT_FALSE(w.fallback);
    }
}

// Found by sweeps ten times larger (fixes G3 in docs/groove-strategy.md): the rapid to a flank
// plunge passes over a staircase cell one infeed higher than the sweep's retract clears (2 mm and
// 1 mm into the stock before the fix).
TEST(GrooveProperties, RapidsToAFlankPlungeClearTheStaircase)
{
    Case a;
    a.g = {350, 500, 11.312, 70.1017, 4.60558, 8.51472, 14.9373, 0.5, 0.5, 3};
    a.r10 = 0.5;
    a.r11 = 3;
    Case b;
    b.g = {350, 500, 0, 53.7394, 76.0301, 13.6712, 13.4685, 0.5, 0.5, 10};
    b.r10 = 0.6;
    b.r11 = 2;
    Case p1;  // the mode-B author's case for the same rapid (G3): 0.338 mm before G3
    p1.g = {350, 500, 19.4508, 109.2035, 20.9253, 0.5596, 27.774, 1.4435, 1.2603, 5};
    p1.r10 = 0.51402;
    p1.r11 = 1;
    p1.r30 = 0.66203;
    for (const Case& c : {a, b, p1}) {
        const Verdict v = check(c);
        EXPECT_FALSE(v.error) << v.message;
        EXPECT_FALSE(v.fallback);
    }
}

// Fix G5: in the first pass the right-flank clean-up's rapids rise over the surface at the
// insert's right corner, where the thesis' heights (taken at the regular plunges) are short by up
// to tan R2 tan R5 R11 - R30 (0.24 mm and 0.36 mm into the stock before the fix).
TEST(GrooveProperties, FirstPassFlankCleanUpRisesOverTheSurface)
{
    Case a;
    a.g = {
        350, 500, 14.099997542798519, 110.57875990169123, 24.738170055206865, 22.158851539716125, 21.470171611290425, 0,
        0,   10};
    a.r10 = 0.46919938912615178;
    a.r11 = 3;
    a.r30 = 0;
    Case b;
    b.g = {350,
           500,
           24.222297798842192,
           52.418549512512982,
           11.595912560587749,
           21.452150365803391,
           3.6514632613398135,
           0.67323407251387835,
           0.070180295966565609,
           5};
    b.r10 = 0.55159296221099785;
    b.r11 = 3;
    b.r30 = 0.031098342966288328;
    for (const Case& c : {a, b}) {
        const Verdict v = check(c);
        EXPECT_FALSE(v.error) << v.message;
    }
}

// Fix G4: where F3 clamps the half-step start of the final bottom sweep, its retract heights count
// the steps the clamp skipped (0.69 mm and 1.24 mm into the staircase before the fix).
TEST(GrooveProperties, ClampedBottomSweepRetractsOverTheStaircase)
{
    Case a;
    a.g = {350, 500, 17.3078, 73.7303, 23.3031, 0, 6.93919, 0.5, 0.5, 3};
    a.r10 = 0.5;
    a.r11 = 2;
    Case b;
    b.g = {350, 500, 25.3985, 91.9919, 9.24829, 10.0849, 8.54834, 0.5, 0.5, 5};
    b.r10 = 0.5;
    b.r11 = 3;
    for (const Case& c : {a, b}) {
        const Verdict v = check(c);
        EXPECT_FALSE(v.error) << v.message;
    }
}

// Seed §5.3 item 1: Kod 1 with R3 = 160 ends through DNO_ZP, which the printed code got wrong
// (25.4994 mm gouge); F2 programs the left corner. Item 2: the half-step start (F3).
TEST(GrooveProperties, DefectSetsOneAndTwoAreClean)
{
    // R3 = 160: item 1 (F2), and its half-step start left of Sz (item 2, F3 in DNO_ZP); 150, 155:
    // clean with F2 (the seed); R11 = 2, R3 = 158: item 2's start right of Tz - R9 (F3 in DNO_ZL).
    struct Set {
        double r3, r11;
        const char* bottomPhase;
    };
    for (const Set& set :
         {Set{160, 1, "DNO_ZP"}, Set{150, 1, "DNO_ZP"}, Set{155, 1, "DNO_ZP"}, Set{158, 2, "DNO_ZL"}}) {
        Case c = kod1();
        c.g.r3 = set.r3;
        c.r11 = set.r11;
        SCOPED_TRACE(describe(c));
        const Verdict v = check(c);
        EXPECT_FALSE(v.error) << v.message;
        auto moves = turning::grooveMoves({sim::grooveGeometry(c.g), 3, 0.8, set.r11, 1}, "g", {});
        ASSERT_TRUE(moves.ok());
        EXPECT_EQ(moves->calls.back(), set.bottomPhase);
    }
}

// Item 3: the groove is narrower than R9 (1 + R10) at depth: the thesis loops forever; F5's
// fallback finishes it and says so in the section's parameters.
TEST(GrooveProperties, DefectSetThreeTerminatesThroughTheFallback)
{
    Case c;
    c.g = {350, 500, 20.899, 37.27, 44.84, 4.844, 9.585, 0.5, 0.5, 23.2};
    c.r10 = 1.0;
    c.r11 = 2;
    const Verdict v = check(c);
    ASSERT_FALSE(v.error) << v.message;
    EXPECT_TRUE(v.fallback);
    auto moves = turning::grooveMoves({sim::grooveGeometry(c.g), 23.2, 1.0, 2, 1}, "g", {});
    ASSERT_TRUE(moves.ok());
    EXPECT_EQ(moves->calls.back(), "FALLBACK");
}

// Item 4: after DNO_ZL the thesis re-enters ZP on a finished groove (F4 stops it).
TEST(GrooveProperties, DefectSetFourEndsAfterTheBottomPhase)
{
    Case c;
    c.g = {350, 500, 10, 60, 40, 5, 5, 0.5, 0.5, 10};
    c.r10 = 0.8;
    c.r11 = 2;
    const Verdict v = check(c);
    ASSERT_FALSE(v.error) << v.message;
    auto moves = turning::grooveMoves({sim::grooveGeometry(c.g), 10, 0.8, 2, 1}, "g", {});
    ASSERT_TRUE(moves.ok());
    EXPECT_EQ(moves->calls,
              (std::vector<std::string>{"ZL", "ZP", "ZL", "ZP", "ZL", "ZP", "ZL", "DNO_ZL"}));  // no ZP after it
}

// Item 5: the left flank's offset meets the surface below the bottom's offset: an input error.
TEST(GrooveProperties, DefectSetFiveIsAnInputError)
{
    Case c;
    c.g = {350, 500, 24.295, 30.29, 64.26, 9.73, 13.055, 0.5, 0.5, 10};
    c.r10 = 1.0;
    c.r11 = 1;
    auto computed = run(c);
    ASSERT_FALSE(computed.ok());
    EXPECT_NE(computed.error().message.find("left flank's offset (R8) meets the surface"), std::string::npos)
        << computed.error().message;
}

// Fix V1: where the staircase of plunges is steeper than a flank the plunges walk into it (a
// 26.4 mm gouge of this left flank without the check); an input error, and clean with a smaller
// infeed.
TEST(GrooveProperties, StaircaseSteeperThanAFlankIsRefused)
{
    Case c;
    c.g = {350, 500, 2.41443, 84.6513, 12.5608, 5.18225, 25.771, 1.5685, 1.32945, 3};
    c.r10 = 0.32291;
    c.r11 = 3;
    c.r30 = 1.60823;
    const Verdict v = check(c);
    ASSERT_TRUE(v.error);
    EXPECT_NE(v.message.find("steeper than the left flank angle (R6)"), std::string::npos) << v.message;
    c.r11 = 1.9;  // tan(25.771) * 1.9 = 0.917 <= 3 * 0.32291
    const Verdict w = check(c);
    EXPECT_FALSE(w.error) << w.message;
}

// REQ-06 / F6: each check with its message (the operation's name, the value's name and R name).
TEST(GrooveProperties, Req06EveryInputCheckHasItsMessage)
{
    struct Bad {
        std::function<void(GrooveParams&, ToolController&)> set;
        std::string message;
    };
    const std::vector<Bad> bad = {
        {[](GrooveParams&, ToolController& t) { t.tool.kind = "flat"; }, "the tool must be a grooving insert"},
        {[](GrooveParams&, ToolController& t) { t.tool.diameterMm = 0; },
         "insert width (R9, the tool's width) must be positive, got 0 mm"},
        {[](GrooveParams& p, ToolController&) { p.infeedMm = 0; }, "infeed (R11) must be positive, got 0 mm"},
        {[](GrooveParams& p, ToolController&) { p.stepFactor = 0; }, "step factor (R10) must be above 0 and at most 1"},
        {[](GrooveParams& p, ToolController&) { p.stepFactor = 1.2; },
         "step factor (R10) must be above 0 and at most 1 (a larger step leaves ribs), got 1.2"},
        {[](GrooveParams& p, ToolController&) { p.safetyMm = -1; },
         "safety distance (R30) must not be negative, got -1 mm"},
        {[](GrooveParams& p, ToolController&) { p.groove.r7 = -0.1; }, "bottom allowance (R7) must not be negative"},
        {[](GrooveParams& p, ToolController&) { p.groove.r8 = -0.1; }, "flank allowance (R8) must not be negative"},
        {[](GrooveParams& p, ToolController&) { p.groove.r3 = 0; }, "groove depth (R3) must be positive"},
        {[](GrooveParams& p, ToolController&) { p.groove.r3 = 200; },
         "groove depth (R3) must be less than the start point's radius (R0 = 180)"},
        {[](GrooveParams& p, ToolController&) { p.groove.r4 = 0; }, "bottom width (R4) must be positive"},
        {[](GrooveParams& p, ToolController&) { p.groove.r2 = -1; },
         "cone angle (R2) must be at least 0 and below 90 degrees, got -1"},
        {[](GrooveParams& p, ToolController&) { p.groove.r2 = 90; },
         "cone angle (R2) must be at least 0 and below 90 degrees, got 90"},
        {[](GrooveParams& p, ToolController&) { p.groove.r5 = 90; },
         "right flank angle (R5) must be at least 0 and below 90 degrees"},
        {[](GrooveParams& p, ToolController&) { p.groove.r6 = -3; },
         "left flank angle (R6) must be at least 0 and below 90 degrees"},
        {[](GrooveParams& p, ToolController&) {
             p.groove.r2 = 50;
             p.groove.r5 = 45;
         },
         "cone angle (R2) plus right flank angle (R5) must be below 90 degrees"},
        {[](GrooveParams& p, ToolController&) {
             p.stepFactor = 0.1;
             p.infeedMm = 3;
         },
         "the staircase of plunges (R11 = 3 mm deeper every R9*R10 = 0.3 mm) is steeper than the right flank angle "
         "(R5)"},
        {[](GrooveParams& p, ToolController&) {
             p.stepFactor = 0.2;
             p.infeedMm = 3;
             p.groove.r6 = 20;
         },
         "steeper than the left flank angle (R6): the plunges would cut the flank; take a smaller infeed (R11 <= "
         "1.648"},
        {[](GrooveParams& p, ToolController&) {
             p.groove.r3 = 5;
             p.groove.r7 = 6;
         },
         "right flank's offset (R8) meets the surface"},
        {[](GrooveParams& p, ToolController&) {
             p.groove.r4 = 2;
             p.groove.r3 = 20;
             p.groove.r2 = 0;
         },
         "narrower than the 3 mm insert (R9)"},
        {[](GrooveParams& p, ToolController&) { p.finalRetractMm = 0; }, "final retract must be positive"},
        {[](GrooveParams& p, ToolController&) { p.feedMmPerRev = 0; }, "feed must be positive"},
        {[](GrooveParams& p, ToolController&) { p.maxRpm = 0; }, "cutting speed and speed limit must be positive"},
        {[](GrooveParams& p, ToolController&) { p.groove.r1 = std::nan(""); }, "start point Z (R1) must be a number"},
    };
    for (const Bad& b : bad) {
        GrooveParams p;
        p.name = "G";
        ToolController tc = grooveTool();
        b.set(p, tc);
        auto computed = computeGroove(p, tc, 0);
        ASSERT_FALSE(computed.ok()) << b.message;
        EXPECT_EQ(computed.error().message.rfind("groove \"G\": ", 0), 0u) << computed.error().message;
        EXPECT_NE(computed.error().message.find(b.message), std::string::npos) << computed.error().message;
    }
}

}  // namespace
}  // namespace camwb::ops::test
