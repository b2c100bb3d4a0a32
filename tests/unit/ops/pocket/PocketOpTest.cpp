// Specific behaviour of the pocket: errors, levels, arcs kept, helix and ramp geometry, milling
// direction, warnings, progress and cancel, and CL trace goldens (regenerate only with
// CAMWB_UPDATE_GOLDEN=1 and review the diff).
#include "PocketTestSupport.h"

#include "../../geom/GeomTestUtil.h"
#include "../support/FeedKinds.h"
#include "../support/OpsGolden.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <set>
#include <variant>

using namespace camwb;
using namespace camwb::ops::pocket::test;
using geom::Vec2;
constexpr double kPi = std::numbers::pi;

namespace {

const std::vector<geom::Region> kRect{rectRegion(0, 0, 40, 30)};

std::string errorOf(const std::vector<geom::Region>& regions, const ops::PocketParams& p, const ops::ToolController& tc)
{
    auto result = ops::computePocket(regions, p, tc, 0);
    return result.ok() ? std::string("(no error)") : result.error().message;
}

// Z of every flat feed move (start and end at the same height below the start depth).
std::set<double> flatLevels(const toolpath::Toolpath& tp, double below)
{
    std::set<double> levels;
    Vec3 pos;
    for (const toolpath::Record& r : tp.records()) {
        if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            if (l->to.z == pos.z && pos.z < below && distance(l->to, pos) > 0)
                levels.insert(l->to.z);
            pos = l->to;
        } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            if (a->to.z == pos.z && pos.z < below)
                levels.insert(a->to.z);
            pos = a->to;
        } else if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            pos = rapid->to;
        }
    }
    return levels;
}

}  // namespace

TEST(PocketOp, Errors)
{
    const auto tc = toolOf(6);
    auto p = baseParams();
    EXPECT_EQ(errorOf({}, p, tc), "pocket \"Pocket 1\": no regions to pocket (the selection is empty)");
    EXPECT_EQ(errorOf(kRect, p, toolOf(45)), "pocket \"Pocket 1\": tool diameter 45 mm does not fit the pocket");
    p.wallStockMm = 12;
    EXPECT_EQ(errorOf(kRect, p, tc),
              "pocket \"Pocket 1\": tool diameter 6 mm with wall stock 12 mm does not fit the pocket");
    p = baseParams();
    p.stepoverMm = 7;
    EXPECT_EQ(errorOf(kRect, p, tc),
              "pocket \"Pocket 1\": stepover 7 mm must be positive and at most the tool diameter 6 mm");
    p = baseParams();
    p.stepoverPercent = 0;
    EXPECT_NE(errorOf(kRect, p, tc).find("stepover 0 mm must be positive"), std::string::npos);
    p = baseParams();
    p.rampAngleDeg = 0;
    EXPECT_EQ(errorOf(kRect, p, tc), "pocket \"Pocket 1\": ramp angle must be in (0, 90] degrees, got 0");
    p.rampAngleDeg = 91;
    EXPECT_NE(errorOf(kRect, p, tc).find("ramp angle"), std::string::npos);
    p = baseParams();
    p.helixDiameterMm = 7;
    EXPECT_NE(errorOf(kRect, p, tc).find("helix diameter 7 mm must be positive and at most the tool diameter 6 mm"),
              std::string::npos);
    p = baseParams();
    p.helixPitchMm = 0;
    EXPECT_NE(errorOf(kRect, p, tc).find("helix pitch must be positive"), std::string::npos);
    // Slips of the keyboard are refused with the least value: a step-down of 1e-9 mm overflowed the
    // level count into one full-depth level, a helix pitch of 1e-6 mm filled the memory.
    p.helixPitchMm = 1e-6;
    EXPECT_NE(errorOf(kRect, p, tc).find("helix pitch 0.000001 mm makes "), std::string::npos) << errorOf(kRect, p, tc);
    p.entry = ops::EntryKind::Ramp;  // the pitch is not used
    EXPECT_TRUE(ops::computePocket(kRect, p, tc, 0).ok());
    p = baseParams();
    p.stepDownMm = 1e-9;
    EXPECT_NE(errorOf(kRect, p, tc).find("step-down 0.000000001 mm makes "), std::string::npos)
        << errorOf(kRect, p, tc);
    EXPECT_NE(errorOf(kRect, p, tc).find(" levels over "), std::string::npos);
    // A stepover of 1e-9 % overflowed the zig-zag's line count into two lines: the pocket not cleared.
    for (const auto pattern : {ops::PocketPattern::ZigZag, ops::PocketPattern::Offset}) {
        p = baseParams();
        p.pattern = pattern;
        p.stepoverPercent = 1e-9;
        EXPECT_NE(errorOf(kRect, p, tc).find("stepover 0.00000000006 mm makes "), std::string::npos)
            << errorOf(kRect, p, tc);
    }
    p = baseParams();
    p.entry = ops::EntryKind::Plunge;
    EXPECT_EQ(errorOf(kRect, p, toolOf(6, false)),
              "pocket \"Pocket 1\": tool 4 is not centre cutting and cannot plunge; use a helix or ramp entry");
    p = baseParams();
    p.floorStockMm = 4;
    EXPECT_NE(errorOf(kRect, p, tc).find("floor stock 4 mm leaves nothing to cut"), std::string::npos);
    p = baseParams();
    p.heights.safeZ = -1;
    EXPECT_NE(errorOf(kRect, p, tc).find("pocket \"Pocket 1\": safe height"), std::string::npos);
    auto noFeed = tc;
    noFeed.cuttingFeedMmPerMin = 0;
    EXPECT_NE(errorOf(kRect, baseParams(), noFeed).find("cutting feed must be positive"), std::string::npos);
}

TEST(PocketOp, LevelsExactWithFloorStockAndFloorFinish)
{
    auto p = baseParams();
    p.heights.finalZ = -5;
    p.stepDownMm = 2;
    p.floorStockMm = 0.5;
    p.finishFloor = true;
    p.entry = ops::EntryKind::Plunge;
    auto result = ops::computePocket(kRect, p, toolOf(6), 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const std::set<double> levels = flatLevels(result->toolpath, 0);
    const std::vector<double> rough = ops::stepDownLevels(0, -4.5, 2);
    ASSERT_EQ(rough.size(), 3u);
    std::set<double> expected(rough.begin(), rough.end());
    expected.insert(-5);
    EXPECT_EQ(levels, expected);
}

TEST(PocketOp, RoundedPocketKeepsArcs)
{
    auto p = baseParams();
    const std::vector<geom::Region> rounded{{geom::test::roundedRectangle(0, 0, 50, 35, 8), {}}};
    auto result = ops::computePocket(rounded, p, toolOf(6), 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_GT(result->counts.arcs, 8);
    EXPECT_GT(result->counts.lines, 8);
    const ops::MotionCounts recount = ops::countMotions(result->toolpath);
    EXPECT_EQ(recount.arcs, result->counts.arcs);
    // The corners (radius 8) are within the reach of a 6 mm tool: no corner warning.
    for (const base::Diagnostic& w : result->warnings)
        EXPECT_EQ(w.message.find("cannot reach"), std::string::npos) << w.message;
}

TEST(PocketOp, SharpCornersAreReportedNotGouged)
{
    auto result = ops::computePocket(kRect, baseParams(), toolOf(6), 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    bool reported = false;
    for (const base::Diagnostic& w : result->warnings)
        if (w.message.find("cannot reach") != std::string::npos) {
            reported = true;
            // Four corners of r^2 (1 - pi/4) each, r = 3: 7.73 mm^2 (less the tolerance margin).
            const double area = std::stod(w.message.substr(w.message.find(": ") + 2));
            EXPECT_NEAR(area, 4 * 9 * (1 - kPi / 4), 0.5) << w.message;
        }
    EXPECT_TRUE(reported);
}

TEST(PocketOp, HelixEntryRadiusAndPitchExact)
{
    auto p = baseParams();
    p.heights.finalZ = -3;
    p.stepDownMm = 0;
    p.helixDiameterMm = 5;
    p.helixPitchMm = 0.8;
    const auto tc = toolOf(6);
    auto result = ops::computePocket(kRect, p, tc, 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const toolpath::Toolpath& tp = result->toolpath;
    Vec3 pos;
    int helical = 0;
    double descent = 0;
    bool flatAfterHelix = false;
    for (const toolpath::Record& r : tp.records()) {
        if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            if (a->to.z != pos.z) {
                ++helical;
                EXPECT_NEAR(distance(pos.xy(), a->center.xy()), 2.5, 1e-9);
                EXPECT_NEAR(distance(a->to.xy(), a->center.xy()), 2.5, 1e-9);
                EXPECT_EQ(a->center.z, pos.z);
                EXPECT_FALSE(a->clockwise);  // climb: counter-clockwise like the outer wall
                EXPECT_EQ(a->feedMmPerMin, tc.rampFeedMmPerMin);
                const geom::Segment s = geom::Segment::arc(pos.xy(), a->to.xy(), a->center.xy(), true);
                EXPECT_LE(std::abs(s.sweep()), kPi + 1e-9);  // one record per half turn at most
                EXPECT_NEAR((pos.z - a->to.z) / std::abs(s.sweep()), 0.8 / (2 * kPi), 1e-9);
                descent += pos.z - a->to.z;
            } else if (helical > 0 && a->to.z == -3) {
                flatAfterHelix = true;
            }
            pos = a->to;
        } else if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            pos = l->to;
        } else if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            pos = rapid->to;
        }
    }
    EXPECT_EQ(helical, 8);  // 3 mm at 0.4 mm per half turn: 7 whole half turns and the rest
    EXPECT_NEAR(descent, 3, 1e-12);
    EXPECT_TRUE(flatAfterHelix);
}

TEST(PocketOp, RampEntryAtTheAngle)
{
    auto p = baseParams();
    p.entry = ops::EntryKind::Ramp;
    p.rampAngleDeg = 5;
    const auto tc = toolOf(6);
    auto result = ops::computePocket(kRect, p, tc, 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    Vec3 pos;
    int ramps = 0;
    for (const toolpath::Record& r : result->toolpath.records()) {
        if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            const double run = distance(l->to.xy(), pos.xy());
            if (l->to.z < pos.z && run > 1e-9 && pos.z <= p.heights.startZ) {
                ++ramps;
                EXPECT_NEAR((pos.z - l->to.z) / run, std::tan(5 * kPi / 180), 1e-9);
                EXPECT_EQ(l->feedMmPerMin, tc.rampFeedMmPerMin);
            }
            pos = l->to;
        } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            pos = a->to;
        } else if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            pos = rapid->to;
        }
    }
    EXPECT_GE(ramps, 2);  // one per level at least
}

TEST(PocketOp, ClimbAndConventionalRunTheWallsOppositeWays)
{
    for (const bool climb : {true, false}) {
        auto p = baseParams();
        p.climb = climb;
        p.entry = ops::EntryKind::Plunge;
        p.stepDownMm = 0;
        auto result = ops::computePocket(kRect, p, toolOf(6), 0);
        ASSERT_TRUE(result.ok()) << result.error().message;
        // The first cut after the plunge is the wall ring: its shoelace area gives its direction.
        const toolpath::Toolpath& tp = result->toolpath;
        std::size_t i = 0;
        while (!(std::holds_alternative<toolpath::Linear>(tp.record(i)) &&
                 std::get<toolpath::Linear>(tp.record(i)).to.z == p.heights.finalZ))
            ++i;
        const Vec2 start = std::get<toolpath::Linear>(tp.record(i)).to.xy();
        Vec2 pos = start;
        double area2 = 0;
        for (++i; i < tp.size(); ++i) {
            const auto* l = std::get_if<toolpath::Linear>(&tp.record(i));
            ASSERT_NE(l, nullptr);
            area2 += pos.cross(l->to.xy());
            pos = l->to.xy();
            if (pos == start)
                break;
        }
        EXPECT_NEAR(std::abs(area2) / 2, 34 * 24, 2);  // the tool-centre rectangle, less the safety margin
        EXPECT_EQ(area2 > 0, climb);
    }
}

TEST(PocketOp, ProgressAndCancel)
{
    std::vector<double> reports;
    ops::Progress progress;
    progress.report = [&](double f) { reports.push_back(f); };
    auto result = ops::computePocket(kRect, baseParams(), toolOf(6), 0, progress);
    ASSERT_TRUE(result.ok()) << result.error().message;
    ASSERT_FALSE(reports.empty());
    for (std::size_t i = 1; i < reports.size(); ++i)
        EXPECT_GE(reports[i], reports[i - 1]);
    EXPECT_DOUBLE_EQ(reports.back(), 1.0);

    std::atomic<bool> cancel{true};
    ops::Progress cancelled;
    cancelled.cancel = &cancel;
    auto none = ops::computePocket(kRect, baseParams(), toolOf(6), 0, cancelled);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message, "pocket \"Pocket 1\": cancelled");
}

TEST(PocketOp, HelixThatFitsNowhereRampsWithAWarning)
{
    // A slot 7.2 mm wide for a 6 mm tool: the tool centre has 1.2 mm, the 5.4 mm helix no room.
    auto p = baseParams();
    const std::vector<geom::Region> slot{rectRegion(0, 0, 40, 7.2)};
    auto result = ops::computePocket(slot, p, toolOf(6), 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    bool warned = false;
    for (const base::Diagnostic& w : result->warnings)
        warned = warned || w.message.find("ramped there instead") != std::string::npos;
    EXPECT_TRUE(warned);
    EXPECT_EQ(result->counts.helices, 0);
}

TEST(PocketOp, GoldenOffsetWithIslandAndHelix)
{
    auto p = baseParams();
    p.name = "Golden offset";
    p.heights = {10, 2, 0, -2};
    p.stepDownMm = 1;
    p.wallStockMm = 0.2;
    const std::vector<geom::Region> shape{
        {geom::test::roundedRectangle(0, 0, 36, 26, 5), {geom::test::circle({18, 13}, 4).reversed()}}};
    auto result = ops::computePocket(shape, p, toolOf(6), 2);
    ASSERT_TRUE(result.ok()) << result.error().message;
    ops::test::expectGolden("pocket", "offset_island_helix.trace", toolpath::traceOf(result->toolpath));
    ops::test::expectFeedKindsAgreeWithSections(result->toolpath);
}

TEST(PocketOp, GoldenZigZagRamp)
{
    auto p = baseParams();
    p.name = "Golden zigzag";
    p.pattern = ops::PocketPattern::ZigZag;
    p.zigZagAngleDeg = 45;
    p.entry = ops::EntryKind::Ramp;
    p.heights = {10, 2, 0, -1.5};
    p.stepDownMm = 0;
    p.finishWalls = true;
    p.wallStockMm = 0.3;
    auto result = ops::computePocket({rectRegion(0, 0, 30, 20)}, p, toolOf(5), 3);
    ASSERT_TRUE(result.ok()) << result.error().message;
    ops::test::expectGolden("pocket", "zigzag_ramp.trace", toolpath::traceOf(result->toolpath));
    ops::test::expectFeedKindsAgreeWithSections(result->toolpath);
}
