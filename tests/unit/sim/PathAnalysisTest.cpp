// Seed 003's path analysis: the thesis' sample vector, reversals by the §6 item 11 rule (sine,
// ramp, stop-and-continue, stop between opposite directions), central differences, the tip feed
// relative to the workpiece on a case worked by hand, its parts from the rotary axes (v_A, v_C,
// eqs. 23-26), and the rotation per unit of tip travel N.
#include "sim/PathAnalysis.h"

#include "kinematics/KinematicChain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace camwb;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStep = 0.003;

// A trace of `n` samples 3 ms apart with `fill(sample, t)` setting what each holds.
template <class F> sim::Trace traceOf(std::size_t n, F fill)
{
    sim::Trace trace(n);
    for (std::size_t k = 0; k < n; ++k) {
        trace[k].time = double(k) * kStep;
        fill(trace[k], trace[k].time);
    }
    return trace;
}

std::vector<double> reversalTimes(const sim::Trace& trace, const std::vector<std::size_t>& at)
{
    std::vector<double> times;
    for (std::size_t k : at)
        times.push_back(trace[k].time);
    return times;
}

}  // namespace

TEST(PathAnalysis, TheThesisSampleVector)
{
    const double x[] = {2.302, 2.311, 2.319, 2.323};
    const sim::Trace trace = traceOf(4, [&](sim::TraceSample& s, double t) { s.linear.x = x[std::lround(t / kStep)]; });
    const sim::PathAnalysis a = sim::analysePath(trace, false);
    const auto& v = a.linearVelocity[0];
    ASSERT_EQ(v.value.size(), 3u);
    EXPECT_EQ(v.firstSample, 1u);  // aligned to the later sample (t2)
    EXPECT_NEAR(v.value[0], 3.000, 1e-3);
    EXPECT_NEAR(v.value[1], 2.6667, 1e-3);
    EXPECT_NEAR(v.value[2], 1.3333, 1e-3);
    const auto& acc = a.linearAcceleration[0];
    ASSERT_EQ(acc.value.size(), 2u);
    EXPECT_EQ(acc.firstSample, 2u);
    EXPECT_NEAR(acc.value[0], -111.11, 1e-2);
    EXPECT_NEAR(acc.value[1], -444.44, 1e-2);
    EXPECT_NEAR(a.pathSpeed.value[0], 3.000, 1e-3);  // only X moves
}

TEST(PathAnalysis, ASineOnCReversesExactlyFourTimes)
{
    // C = 10°·sin(πt) over 4 s: C turns back at 0.5, 1.5, 2.5 and 3.5 s.
    const sim::Trace trace = traceOf(std::size_t(4 / kStep) + 1,
                                     [](sim::TraceSample& s, double t) { s.rotaryDeg[1] = 10 * std::sin(kPi * t); });
    const sim::PathAnalysis a = sim::analysePath(trace, true);
    const std::vector<double> at = reversalTimes(trace, a.reversals[4]);
    ASSERT_EQ(at.size(), 4u);
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(at[i], 0.5 + i, kStep) << i;
    EXPECT_TRUE(a.reversals[3].empty());                                    // A stands
    EXPECT_NEAR(a.rotaryVelocity[1].value[0], 10 * kPi / 180 * kPi, 1e-3);  // rad/s: ω = 10°·π·cos(0)
}

TEST(PathAnalysis, ARampAndAStopAndContinueAreNoReversals)
{
    const sim::Trace ramp = traceOf(1000, [](sim::TraceSample& s, double t) { s.rotaryDeg[0] = 20 * t; });
    EXPECT_TRUE(sim::analysePath(ramp, true).reversals[3].empty());
    // X moves at 10 mm/s, stands 0.3 s, then moves on the same way: the stop is no reversal.
    auto stopAndGo = [](double t) { return t < 1 ? 10 * t : t < 1.3 ? 10 : 10 + 10 * (t - 1.3); };
    const sim::Trace go = traceOf(1000, [&](sim::TraceSample& s, double t) { s.linear.x = stopAndGo(t); });
    EXPECT_TRUE(sim::analysePath(go, false).reversals[0].empty());
    // Stopping and going back counts once, at the last sample of the stop, which the axis leaves
    // in the new direction.
    auto stopAndBack = [](double t) { return t < 1 ? 10 * t : t < 1.3 ? 10 : 10 - 10 * (t - 1.3); };
    const sim::Trace back = traceOf(1000, [&](sim::TraceSample& s, double t) { s.linear.x = stopAndBack(t); });
    const auto at = sim::analysePath(back, false).reversals[0];
    ASSERT_EQ(at.size(), 1u);
    EXPECT_NEAR(back[at[0]].time, 1.3, kStep + 1e-12);
    EXPECT_NEAR(back[at[0]].linear.x, 10, 1e-12);
    EXPECT_LT(back[at[0] + 1].linear.x, 10);
}

TEST(PathAnalysis, NoiseInsideTheDeadBandIsNoReversal)
{
    // A standing axis dithering by one 0.1 µm step: ±0.033 mm/s, inside the 0.05 mm/s dead band.
    const sim::Trace dither =
        traceOf(200, [](sim::TraceSample& s, double t) { s.linear.y = 5 + (std::lround(t / kStep) % 2) * 1e-4; });
    EXPECT_TRUE(sim::analysePath(dither, false).reversals[1].empty());
    sim::AnalysisOptions tight;
    tight.reversal.linearDeadBand = 0.01;
    EXPECT_EQ(sim::analysePath(dither, false, tight).reversals[1].size(), 198u);  // every step turns
}

TEST(PathAnalysis, CentralDifferencesAreExactOnAParabola)
{
    const sim::Trace trace = traceOf(10, [](sim::TraceSample& s, double t) { s.linear.z = t * t; });
    sim::AnalysisOptions central;
    central.difference = sim::Difference::Central;
    const auto v = sim::analysePath(trace, false, central).linearVelocity[2];
    ASSERT_EQ(v.value.size(), 9u);
    for (std::size_t k = 0; k + 1 < v.value.size(); ++k)
        EXPECT_NEAR(v.value[k], 2 * trace[v.firstSample + k].time, 1e-12);  // d(t²)/dt at the sample
    const auto backward = sim::analysePath(trace, false).linearVelocity[2];
    EXPECT_NEAR(backward.value[0], kStep, 1e-12);  // (0.003² − 0) / 0.003: half a step late
}

// Worked by hand: seed 003's A/C table (r = P = 0), linear axes standing at X 50, C turning at
// 10°/s. Eq. 14 sees no motion at all, yet the tip cuts the workpiece at ω·r = 10·π/180·50 =
// 8.7266 mm/s (the table turns under it: v_C = ω_C·r_v2 with r_v2 = 50, eq. 24).
TEST(PathAnalysis, TipFeedRelativeToTheWorkpieceOnATurningTable)
{
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::TableTable;
    chain.joints = {{"A", true, {-1, 0, 0}, {}}, {"C", true, {0, 0, -1}, {}}};
    const sim::Trace trace = traceOf(300, [&](sim::TraceSample& s, double t) {
        s.linear = {50, 0, 0};
        s.rotaryDeg = {0, 10 * t};
        s.tip = kinematics::forwardKinematics(chain, {s.linear, s.rotaryDeg}).tip;
    });
    const sim::PathAnalysis a = sim::analysePath(trace, true);
    EXPECT_NEAR(a.pathSpeed.value[100], 0, 1e-12);
    EXPECT_NEAR(a.tipFeed.value[100], 10 * kPi / 180 * 50, 1e-4);
    EXPECT_NEAR(a.rotaryVelocity[1].value[100], 10 * kPi / 180, 1e-9);
}

TEST(PathAnalysis, RotationPerUnitOfTipTravel)
{
    // 0.5 mm of tip travel and 0.1° of C per sample; A stands. Then a rotation in place.
    const sim::Trace trace = traceOf(20, [](sim::TraceSample& s, double t) {
        const double k = std::round(t / kStep);
        s.tip = {std::min(k, 10.0) * 0.5, 0, 0};
        s.rotaryDeg = {0, 0.1 * k};
    });
    const sim::PathAnalysis a = sim::analysePath(trace, true);
    EXPECT_NEAR(a.rotationPerTravel[1].value[0], 0.1 * kPi / 180 / 0.5, 1e-12);
    EXPECT_NEAR(a.rotationPerTravel[0].value[0], 0, 1e-12);
    EXPECT_NEAR(a.rotationPerTravelCombined.value[0], 0.1 * kPi / 180 / 0.5, 1e-12);
    EXPECT_TRUE(std::isnan(a.rotationPerTravel[1].value[15]));  // the tip stands: N undefined
}

// Worked by hand on seed 003's chain (eq. 9: T_z(r)·R_x(−α)·R_z(−γ)·T_z(P), r = 100, P = 20): the
// linear axes stand at the machine tip (30, 40, 20) while A goes 29.7° → 30° and C 10° → 10.6° in
// one 3 ms step, ω_A = 100°/s, ω_C = 200°/s at the later sample (α = 30°). With the pivot
// (x2, y2, z2) = (0, 0, 100):
//   r_v1 = √((40 − 0)² + (20 − 100)²) = 89.44272 (eq. 25), v_A = 1.745329 rad/s · r_v1 = 156.1070;
//   r_v2 = √([cos30°·(100·sin30° + 40 − 0) + sin30°·(100 − 100·cos30° − 20)]² + (30 − 0)²)
//        = √(74.64102² + 30²) = 80.44427 (eq. 26), v_C = 3.490659 rad/s · r_v2 = 280.8035.
// The C axis must be the one the tilt has turned: untilted, r_v2 would be 50.
TEST(PathAnalysis, TipSpeedFromEachRotaryAxisByTheThesisFormulas)
{
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::TableTable;
    chain.joints = {{"A", true, {-1, 0, 0}, {0, 0, 100}}, {"C", true, {0, 0, -1}, {0, 0, 100}}};
    chain.workpieceZero = {0, 0, 120};
    sim::Trace trace(2);
    trace[0] = {0.0, {30, 40, 20}, {29.7, 10.0}, {}};
    trace[1] = {kStep, {30, 40, 20}, {30.0, 10.6}, {}};
    for (sim::TraceSample& s : trace)
        s.tip = kinematics::forwardKinematics(chain, {s.linear, s.rotaryDeg}).tip;
    const sim::PathAnalysis a = sim::analysePath(trace, chain);
    ASSERT_EQ(a.rotaryTipSpeed[0].value.size(), 1u);
    EXPECT_EQ(a.rotaryTipSpeed[0].firstSample, 1u);
    EXPECT_NEAR(a.rotaryTipSpeed[0].value[0], 156.1070, 1e-3);
    EXPECT_NEAR(a.rotaryTipSpeed[1].value[0], 280.8035, 1e-3);
    // Turning the other way gives the same speeds, signed as ω.
    trace[0].rotaryDeg = {30.3, 11.2};
    trace[0].tip = kinematics::forwardKinematics(chain, {trace[0].linear, trace[0].rotaryDeg}).tip;
    const sim::PathAnalysis back = sim::analysePath(trace, chain);
    EXPECT_NEAR(back.rotaryTipSpeed[0].value[0], -156.1070, 1e-3);
    EXPECT_NEAR(back.rotaryTipSpeed[1].value[0], -280.8035, 1e-3);
    // A three-axis machine has no rotary parts.
    EXPECT_TRUE(sim::analysePath(trace, kinematics::KinematicChain{}).rotaryTipSpeed[0].value.empty());
}

// The radii in general: eq. 26 is the distance from the tip to the tilted C axis through the
// pivot, for any tip and tilt (random points against the errata's closed form).
TEST(PathAnalysis, TipRadiiEqualTheDistanceToEachAxis)
{
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::TableTable;
    const double r = -35;
    chain.joints = {{"A", true, {-1, 0, 0}, {0, 0, r}}, {"C", true, {0, 0, -1}, {0, 0, r}}};
    std::uint32_t seed = 12345;
    auto random = [&seed](double lo, double hi) {
        seed = seed * 1664525u + 1013904223u;
        return lo + (hi - lo) * double(seed >> 8) / double(1u << 24);
    };
    for (int i = 0; i < 50; ++i) {
        const base::Vec3 tip{random(-200, 200), random(-200, 200), random(-100, 300)};
        const double alphaDeg = random(-120, 120), gammaDeg = random(-360, 360);
        const double al = alphaDeg * kPi / 180;
        const auto radii = kinematics::tipRadii(chain, {tip, {alphaDeg, gammaDeg}});
        EXPECT_NEAR(radii[0], std::hypot(tip.y, tip.z - r), 1e-9);
        const double across = std::cos(al) * (r * std::sin(al) + tip.y) + std::sin(al) * (r - r * std::cos(al) - tip.z);
        EXPECT_NEAR(radii[1], std::hypot(across, tip.x), 1e-9);
    }
}

// A head-head chain (C carries B, both through a pivot 100 mm above the gauge point) with a
// 50 mm tool: the tip is 150 mm from the B axis at any pose, and with B at 30° it swings
// 150·sin 30° = 75 mm out from the C axis, whichever way C has turned B's axis.
TEST(PathAnalysis, TipRadiiOfAHeadFollowTheToolLength)
{
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::HeadHead;
    chain.joints = {{"C", false, {0, 0, 1}, {0, 0, 100}}, {"B", false, {0, 1, 0}, {0, 0, 100}}};
    for (double c : {0.0, 90.0, -135.0}) {
        const auto radii = kinematics::tipRadii(chain, {{10, -20, 30}, {c, 30}}, 50);
        EXPECT_NEAR(radii[0], 75, 1e-9) << c;
        EXPECT_NEAR(radii[1], 150, 1e-9) << c;
    }
}
