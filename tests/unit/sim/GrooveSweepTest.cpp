// A random sweep of the mode-B groove subprograms over the ranges of seed-001 §5.3 item 8 (the
// sweep that found the thesis' endless loops, re-entries and gouges): every case terminates and
// is either clean by the turning check or stops with one of the documented alarms.
#include "GrooveSubprogramsSupport.h"

#include <map>

namespace camwb::sim::groove_test {
namespace {

// At least `minCleanPercent` of the cases must run to the end: the sweep must test the strategy, not the alarms.
void expectCleanOrAlarm(const std::vector<Inputs>& all, int minCleanPercent = 75)
{
    const int cases = static_cast<int>(all.size());
    std::map<int, int> alarms;
    int clean = 0;
    double worstGouge = 0, worstRapid = 0, worstLeft = 0;
    for (int i = 0; i < cases; ++i) {
        const Inputs& in = all[static_cast<std::size_t>(i)];
        SCOPED_TRACE("case " + std::to_string(i) + ": " + describe(in));
        const GrooveRun r = runGroove(in);
        const int alarm = r.alarm();
        const TurningReport report = check(r, in);
        // Clean up to the end or up to the alarm: no gouge, no rapid through the stock.
        EXPECT_EQ(report.gouges, 0u) << "gouge " << report.maxGougeMm;
        EXPECT_EQ(report.rapidsInStock, 0u) << "rapid " << report.maxRapidDepthMm;
        worstGouge = std::max(worstGouge, report.maxGougeMm);
        worstRapid = std::max(worstRapid, report.maxRapidDepthMm);
        if (alarm) {
            ++alarms[alarm];
            // The narrow-groove alarm, or an input alarm of the offset contour (seed item 5: a
            // left flank too low; the right flank; a bottom narrower than the insert) or of the
            // staircase against a flank (V1): the ranges give no other invalid inputs.
            EXPECT_TRUE(alarm == 65010 || (alarm >= 65014 && alarm <= 65018)) << r.diagnostics();
            EXPECT_EQ(r.result.diagnostics.size(), 1u) << r.diagnostics();
            continue;
        }
        EXPECT_TRUE(r.result.completed) << r.diagnostics();
        EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics();
        ++clean;
        // What stays above the offset contour (seed REQ-15 d: at most 0.01 mm² for R10 <= 1).
        const double left = geom::totalArea(geom::subtract(report.stock, grooveOffsetPart(grooveParameters(in)), 1e-4));
        worstLeft = std::max(worstLeft, left);
        EXPECT_LT(left, 0.01);
    }
    std::string summary = "clean " + std::to_string(clean) + " of " + std::to_string(cases) + "; alarms:";
    for (const auto& [number, count] : alarms)
        summary += " " + std::to_string(number) + " x" + std::to_string(count);
    std::printf("%s; max gouge %.6f mm, max rapid depth %.6f mm, max leftover %.6f mm2\n", summary.c_str(), worstGouge,
                worstRapid, worstLeft);
    EXPECT_GE(clean * 100, cases * minCleanPercent) << summary;
}

TEST(GrooveSubprogramsSweep, RandomGroovesAreCleanOrStopWithAnAlarm) { expectCleanOrAlarm(sweepCases(400)); }

TEST(GrooveSubprogramsSweep, ZeroAnglesAndNarrowGrooves)
{
    expectCleanOrAlarm(sweepCases(400, Sweep::ZeroAnglesAndNarrow), 60);  // a quarter narrow: 65010
}

TEST(GrooveSubprogramsSweep, WiderRanges) { expectCleanOrAlarm(sweepCases(400, Sweep::Wider)); }

}  // namespace
}  // namespace camwb::sim::groove_test
