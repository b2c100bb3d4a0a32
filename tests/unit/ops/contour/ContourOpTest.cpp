// The contour operation's basic record sequence (everything the first outer profile did, ported
// from test_profile_op.cpp), several contours, progress and cancelling, and every input error.
#include "ContourTestUtil.h"
#include "geom/ClipperAdapter.h"

#include <atomic>

using namespace camwb;
using namespace camwb::ops::test;
using geom::distanceToProfile;
using geom::test::circle;
using geom::test::rectangle;
using geom::test::roundedRectangle;

namespace {

const Profile kPlate = roundedRectangle(0, 0, 90, 60, 8);
const std::vector<Vec2> kCornerCentres{{8, 8}, {82, 8}, {82, 52}, {8, 52}};

toolpath::Toolpath compute(const Profile& p, const ops::ContourParams& params, const ops::ToolController& tc = tool(),
                           int opIndex = 0)
{
    auto r = ops::computeContour({p}, params, tc, opIndex);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return r.ok() ? r.value().toolpath : toolpath::Toolpath{};
}

// The loop of a single-level contour: records 4 .. size-3.
struct Loop {
    std::vector<Vec2> points;
    Vec2 start, end;
    int arcs = 0, cw = 0, ccw = 0;
};

Loop loopOf(const toolpath::Toolpath& tp, double z)
{
    Loop loop;
    const std::vector<Move> moves = walk(tp);
    loop.start = std::get<toolpath::Linear>(tp.record(3)).to.xy();
    for (const Move& m : moves) {
        if (m.record < 4 || m.record + 2 >= tp.size())
            continue;
        EXPECT_EQ(m.to.z, z);
        EXPECT_EQ(m.feed, 1200);
        if (m.arc) {
            const auto& a = std::get<toolpath::Arc>(tp.record(m.record));
            ++loop.arcs;
            ++(a.clockwise ? loop.cw : loop.ccw);
            EXPECT_EQ(a.center.z, z);
            EXPECT_EQ(a.turns, 0);
        }
        for (std::size_t k = 0; k + 1 < m.points.size(); ++k)
            loop.points.push_back(m.points[k].xy());
        loop.end = m.to.xy();
    }
    return loop;
}

}  // namespace

TEST(ContourOp, RecordSequenceAsTheFirstProfile)
{
    const toolpath::Toolpath tp = compute(kPlate, params(), tool(), 3);
    ASSERT_GE(tp.size(), 8u);
    const auto& begin = std::get<toolpath::SectionBegin>(tp.record(0));
    EXPECT_EQ(begin.operationName, "Outer contour");
    EXPECT_EQ(begin.strategy, "contour");
    EXPECT_EQ(begin.toolNumber, 2);
    EXPECT_EQ(begin.feeds.cuttingMmPerMin, 1200);
    EXPECT_EQ(begin.feeds.plungeMmPerMin, 300);
    EXPECT_EQ(begin.feeds.entryMmPerMin, 600);

    const Vec2 start = std::get<toolpath::Linear>(tp.record(3)).to.xy();
    // The plunge happens in the middle of a long (74 mm) straight side.
    EXPECT_NEAR(start.x, 45, 1e-12);
    EXPECT_TRUE(std::abs(start.y + 5) < 1e-12 || std::abs(start.y - 65) < 1e-12) << start.y;
    EXPECT_EQ(std::get<toolpath::Rapid>(tp.record(1)).to, (Vec3{start.x, start.y, 15}));
    EXPECT_EQ(std::get<toolpath::Rapid>(tp.record(2)).to, (Vec3{start.x, start.y, 2}));
    EXPECT_EQ(std::get<toolpath::Linear>(tp.record(3)).to.z, -3);
    EXPECT_EQ(std::get<toolpath::Linear>(tp.record(3)).feedMmPerMin, 300);
    EXPECT_EQ(std::get<toolpath::Rapid>(tp.record(tp.size() - 2)).to, (Vec3{start.x, start.y, 15}));
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionEnd>(tp.record(tp.size() - 1)));
    for (std::size_t i = 0; i < tp.size(); ++i) {
        EXPECT_EQ(tp.source(i).operationIndex, 3);
        EXPECT_EQ(tp.source(i).recordIndex, static_cast<int>(i));
        EXPECT_FALSE(std::holds_alternative<toolpath::ToolChange>(tp.record(i)));
        EXPECT_FALSE(std::holds_alternative<toolpath::Spindle>(tp.record(i)));
    }
    // Split long side: half line, arc, line, arc, line, arc, line, arc, half line.
    EXPECT_EQ(tp.size(), 4u + 9u + 2u);
}

TEST(ContourOp, LoopIsClosedAtDepthWithArcsOfRadius13OnCornerCentres)
{
    for (bool climb : {true, false}) {
        SCOPED_TRACE(climb ? "climb" : "conventional");
        const toolpath::Toolpath tp = compute(kPlate, params(ops::ContourSide::Outside, climb));
        const Loop loop = loopOf(tp, -3);
        EXPECT_NEAR(distance(loop.start, loop.end), 0, 1e-12);
        EXPECT_EQ(loop.arcs, 4);
        // Climb around an outside boundary is clockwise, conventional counter-clockwise.
        EXPECT_EQ(loop.cw, climb ? 4 : 0);
        EXPECT_EQ(loop.ccw, climb ? 0 : 4);
        EXPECT_EQ(geom::polygonArea(loop.points) < 0, climb);
        for (std::size_t i = 4; i + 2 < tp.size(); ++i)
            if (const auto* a = std::get_if<toolpath::Arc>(&tp.record(i))) {
                EXPECT_NEAR(distance(a->to.xy(), a->center.xy()), 13, 1e-9);
                bool onCorner = false;
                for (const Vec2& c : kCornerCentres)
                    onCorner = onCorner || distance(c, a->center.xy()) < 1e-12;
                EXPECT_TRUE(onCorner) << a->center.x << ", " << a->center.y;
            }
        for (const Vec2& pt : loop.points)
            EXPECT_NEAR(distanceToProfile(pt, kPlate), 5, 1e-9);
    }
}

TEST(ContourOp, ClockwiseBoundaryGivesTheSameToolpath)
{
    const Loop a = loopOf(compute(kPlate, params()), -3);
    const Loop b = loopOf(compute(kPlate.reversed(), params()), -3);
    EXPECT_EQ(b.cw, 4);
    EXPECT_NEAR(geom::polygonArea(a.points), geom::polygonArea(b.points), 1e-6);
}

TEST(ContourOp, CircularBossIsTwoHalfCircles)
{
    const toolpath::Toolpath tp = compute(circle({20, 10}, 15), params());
    ASSERT_EQ(tp.size(), 4u + 2u + 2u);
    const Loop loop = loopOf(tp, -3);
    EXPECT_EQ(loop.cw, 2);
    EXPECT_NEAR(distance(loop.start, loop.end), 0, 1e-12);
    for (const Vec2& pt : loop.points)
        EXPECT_NEAR(distance(pt, {20, 10}), 20, 1e-9);
    EXPECT_GT(distance(std::get<toolpath::Arc>(tp.record(4)).to.xy(), loop.start), 39.9);  // half way round
}

TEST(ContourOp, SeveralContoursInOrderOfNearestStart)
{
    // Input order: far, near the first, middle. Cut: first, then the nearest, then the last.
    const std::vector<Profile> loops{rectangle(0, 0, 20, 10), rectangle(200, 0, 20, 10), rectangle(60, 0, 20, 10)};
    auto r = ops::computeContour(loops, params(), tool(), 1);
    ASSERT_TRUE(r.ok()) << r.error().message;
    std::vector<double> plungeX;
    const toolpath::Toolpath& tp = r.value().toolpath;
    for (std::size_t i = 0; i < tp.size(); ++i)
        if (const auto* l = std::get_if<toolpath::Linear>(&tp.record(i)); l && l->feedMmPerMin == 300)
            plungeX.push_back(l->to.x);
    ASSERT_EQ(plungeX.size(), 3u);
    EXPECT_NEAR(plungeX[0], 10, 1e-9);
    EXPECT_NEAR(plungeX[1], 70, 1e-9);
    EXPECT_NEAR(plungeX[2], 210, 1e-9);
    // Between contours the tool goes back up to the clearance height.
    int clearanceRapids = 0;
    for (const toolpath::Record& rec : tp.records())
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&rec); rapid && rapid->to.z == 15)
            ++clearanceRapids;
    EXPECT_EQ(clearanceRapids, 6);
    EXPECT_EQ(r.value().counts.arcs, 12);
    EXPECT_EQ(r.value().counts.lines, 3 * (5 + 1));
}

TEST(ContourOp, ProgressAndCancel)
{
    auto p = params();
    p.stepDownMm = 1;
    std::vector<double> reported;
    ops::Progress progress;
    progress.report = [&](double f) { reported.push_back(f); };
    ASSERT_TRUE(ops::computeContour({kPlate, rectangle(200, 0, 10, 10)}, p, tool(), 0, progress).ok());
    ASSERT_FALSE(reported.empty());
    EXPECT_DOUBLE_EQ(reported.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_GE(reported.size(), 6u);  // 2 loops x 3 levels

    std::atomic<bool> cancel{true};
    progress.cancel = &cancel;
    auto r = ops::computeContour({kPlate}, p, tool(), 0, progress);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "contour \"Outer contour\": cancelled");
}

TEST(ContourOp, InputErrors)
{
    auto expectError = [](std::vector<Profile> loops, const ops::ContourParams& p, const ops::ToolController& tc,
                          const std::string& fragment) {
        auto r = ops::computeContour(loops, p, tc, 0);
        ASSERT_FALSE(r.ok()) << "expected an error about " << fragment;
        EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().message;
        EXPECT_EQ(r.error().message.rfind("contour \"Outer contour\": ", 0), 0u) << r.error().message;
    };
    const auto good = tool();
    auto tc = good;
    tc.tool.diameterMm = 0;
    expectError({kPlate}, params(), tc, "tool diameter must be positive");
    tc = good;
    tc.cuttingFeedMmPerMin = 0;
    expectError({kPlate}, params(), tc, "cutting feed");
    tc = good;
    tc.plungeFeedMmPerMin = -1;
    expectError({kPlate}, params(), tc, "plunge feed");
    tc = good;
    tc.spindleRpm = 0;
    expectError({kPlate}, params(), tc, "spindle speed");
    tc = good;
    tc.tool.fluteLengthMm = 2;
    expectError({kPlate}, params(), tc, "beyond the cutting length");

    auto p = params();
    p.heights.clearanceZ = 1;
    expectError({kPlate}, p, good, "clearance height");
    p = params();
    p.heights.safeZ = p.heights.startZ;
    expectError({kPlate}, p, good, "safe height");
    p = params();
    p.heights.finalZ = 1;
    p.heights.safeZ = 2;
    expectError({kPlate}, p, good, "is below the final depth");

    expectError({}, params(), good, "nothing to cut");
    expectError({kPlate, Profile{}}, params(), good, "contour 2 is empty");
    Profile gap = kPlate;
    gap.segments[2].start.x += 0.5;
    expectError({gap}, params(), good, "contour 1 is not continuous");
    Profile chain{{Segment::line({0, 0}, {50, 0})}, false};
    expectError({chain}, params(ops::ContourSide::Outside), good, "side outside needs a closed loop");
    expectError({chain}, params(ops::ContourSide::Inside), good, "side inside needs a closed loop");
    expectError({kPlate}, params(ops::ContourSide::Left), good, "side left is for open edge chains");
    expectError({kPlate}, params(ops::ContourSide::Right), good, "side right is for open edge chains");

    // Geometry the tool cannot follow: a concave arc of radius 4 with a 10 mm tool, a pocket
    // narrower than the tool.
    Profile notched;
    notched.segments = {
        Segment::line({0, 0}, {80, 0}),    Segment::line({80, 0}, {80, 50}),
        Segment::line({80, 50}, {44, 50}), Segment::arc({44, 50}, {36, 50}, {40, 50}, false),
        Segment::line({36, 50}, {0, 50}),  Segment::line({0, 50}, {0, 0}),
    };
    expectError({notched}, params(), good, "tool too large for the concave arc of radius 4");
    expectError({rectangle(0, 0, 8, 40)}, params(ops::ContourSide::Inside), good, "tool too large");

    p = params();
    p.stepDownMm = -1;
    expectError({kPlate}, p, good, "step-down must not be negative");
    p = params();
    p.axialStockMm = 3;
    expectError({kPlate}, p, good, "leaves nothing");
    p = params();
    p.radialStockMm = -0.5;
    expectError({kPlate}, p, good, "stock to leave must not be negative");
    p = params();
    p.radialPasses = 0;
    expectError({kPlate}, p, good, "radial passes must be at least 1");
    p.radialPasses = 3;
    expectError({kPlate}, p, good, "radial stepover must be positive");
    p = params();
    p.leadIn = ops::LeadKind::Arc;
    expectError({kPlate}, p, good, "lead radius/length must be positive");
    // Slips of the keyboard: refused with the least value, not computed until the memory is gone
    // (a step-down of 1e-9 mm overflowed the level count into a single full-depth level).
    p.leadRadiusMm = 1e9;
    expectError({kPlate}, p, good, "lead radius/length 1000000000 mm is more than 100 tool diameters (1000 mm)");
    for (const double slip : {1e-9, 1e-5}) {
        p = params();
        p.stepDownMm = slip;
        expectError({kPlate}, p, good, " levels over ");
        expectError({kPlate}, p, good, "more than the 10000 an operation may make; use at least ");
    }
    p = params();
    p.entry = ops::EntryKind::Helix;
    p.helixPitchMm = 1e-7;
    expectError({kPlate}, p, good, "helix pitch 0.0000001 mm makes ");
    for (double angle : {0.0, -3.0, 90.5}) {
        p = params();
        p.entry = ops::EntryKind::Ramp;
        p.rampAngleDeg = angle;
        expectError({kPlate}, p, good, "ramp angle must be above 0 and at most 90 degrees");
    }
    p = params();
    p.entry = ops::EntryKind::Helix;
    p.helixPitchMm = 0;
    expectError({kPlate}, p, good, "helix pitch must be positive");
    p.helixPitchMm = 1;
    p.helixDiameterMm = -1;
    expectError({kPlate}, p, good, "helix diameter must not be negative");
    // In a 30 mm hole the 10 mm tool's centre runs on a circle of 20 mm: no 22 mm helix.
    p = params(ops::ContourSide::Inside);
    p.entry = ops::EntryKind::Helix;
    p.helixDiameterMm = 22;
    expectError({circle({0, 0}, 15)}, p, good, "a helix of diameter 22 mm does not fit beside contour 1");
    p.helixDiameterMm = 19.9;
    EXPECT_TRUE(ops::computeContour({circle({0, 0}, 15)}, p, good, 0).ok());
    // A lead arc of 20 mm does not fit inside that hole either.
    p = params(ops::ContourSide::Inside);
    p.leadIn = ops::LeadKind::Arc;
    p.leadRadiusMm = 20;
    expectError({circle({0, 0}, 15)}, p, good, "the lead-in of contour 1");

    p = params();
    p.tabCount = -1;
    expectError({kPlate}, p, good, "tab count must not be negative");
    p.tabCount = 2;
    p.tabWidthMm = 0;
    expectError({kPlate}, p, good, "tab width must be positive");
    p.tabWidthMm = 5;
    p.tabHeightMm = 0;
    expectError({kPlate}, p, good, "tab height must be positive");
    p.tabHeightMm = 3;
    expectError({kPlate}, p, good, "tab height 3 mm reaches the start depth");
    p.tabHeightMm = 1;
    p.tabCount = 30;
    expectError({kPlate}, p, good, "30 tabs of 5 mm (plus the tool diameter) do not fit on contour 1");

    p = params(ops::ContourSide::On);
    p.compensation = ops::CompensationOutput::Control;
    expectError({kPlate}, p, good, "cutter compensation needs a side");
    p = params();
    p.compensation = ops::CompensationOutput::Control;
    p.leadIn = ops::LeadKind::Arc;
    p.leadRadiusMm = 4;
    expectError({kPlate}, p, good, "lead arc radius 4 mm must be larger than the tool radius 5 mm");
    p = params();
    p.toleranceMm = 0;
    expectError({kPlate}, p, good, "tolerance must be positive");

    // clearance == safe is allowed
    p = params();
    p.heights.clearanceZ = p.heights.safeZ;
    EXPECT_TRUE(ops::computeContour({kPlate}, p, good, 0).ok());
}
