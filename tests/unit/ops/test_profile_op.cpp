#include "../geom/GeomTestUtil.h"
#include "geom/ClipperAdapter.h"
#include "ops/ProfileOp.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace camwb;
using namespace camwb::geom::test;
using geom::polygonArea;
using geom::Vec2;
using toolpath::Vec3;
constexpr double kPi = std::numbers::pi;

namespace {

ops::ToolController tenMillimetreTool()
{
    ops::ToolController tc;
    tc.tool.number = 2;
    tc.tool.name = "Flat 10";
    tc.tool.diameterMm = 10;
    tc.spindleRpm = 10000;
    tc.cuttingFeedMmPerMin = 1200;
    tc.plungeFeedMmPerMin = 300;
    return tc;
}

ops::ProfileParams params(bool climb = true)
{
    ops::ProfileParams p;
    p.name = "Outer contour";
    p.finalDepthZ = -3;
    p.safeZ = 2;
    p.clearanceZ = 15;
    p.climb = climb;
    return p;
}

const geom::Profile kPlate = roundedRectangle(0, 0, 90, 60, 8);
const std::vector<Vec2> kCornerCentres{{8, 8}, {82, 8}, {82, 52}, {8, 52}};

// Points along one cutting move from `from`, for distance checks and the loop's area.
std::vector<Vec2> samples(Vec2 from, const toolpath::Record& r, int n = 24)
{
    std::vector<Vec2> pts;
    if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
        for (int i = 0; i <= n; ++i)
            pts.push_back(from + (l->to.xy() - from) * (static_cast<double>(i) / n));
    } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
        const geom::Segment s = geom::Segment::arc(from, a->to.xy(), a->center.xy(), !a->clockwise);
        for (int i = 0; i <= n; ++i)
            pts.push_back(s.pointAt(static_cast<double>(i) / n));
    }
    return pts;
}

struct Walk {
    std::vector<Vec2> loopPoints;  // every sampled point of the cutting loop
    Vec2 start, end;
    int arcs = 0, cw = 0, ccw = 0;
};

// Walks the cutting loop (records 4 .. size-3) checking the invariants every move must keep.
Walk walkLoop(const toolpath::Toolpath& tp, const ops::ProfileParams& p, const ops::ToolController& tc)
{
    Walk w;
    const auto& plunge = std::get<toolpath::Linear>(tp.record(3));
    w.start = plunge.to.xy();
    Vec2 pos = w.start;
    for (std::size_t i = 4; i + 2 < tp.size(); ++i) {
        const toolpath::Record& r = tp.record(i);
        if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            EXPECT_EQ(l->to.z, p.finalDepthZ);
            EXPECT_EQ(l->feedMmPerMin, tc.cuttingFeedMmPerMin);
        } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            ++w.arcs;
            ++(a->clockwise ? w.cw : w.ccw);
            EXPECT_EQ(a->to.z, p.finalDepthZ);
            EXPECT_EQ(a->center.z, p.finalDepthZ);
            EXPECT_EQ(a->normal, (Vec3{0, 0, 1}));
            EXPECT_EQ(a->turns, 0);
            EXPECT_EQ(a->feedMmPerMin, tc.cuttingFeedMmPerMin);
            EXPECT_NEAR(distance(pos, a->center.xy()), distance(a->to.xy(), a->center.xy()), 1e-9);
        } else {
            ADD_FAILURE() << "record " << i << " is not a cutting move";
            continue;
        }
        const std::vector<Vec2> pts = samples(pos, r);
        w.loopPoints.insert(w.loopPoints.end(), pts.begin(), pts.end() - 1);
        pos = pts.back();
    }
    w.end = pos;
    return w;
}

}  // namespace

TEST(ProfileOp, RecordSequenceAsSpecified)
{
    const auto tc = tenMillimetreTool();
    const auto p = params();
    auto result = ops::computeOuterProfile(kPlate, p, tc, 3);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const toolpath::Toolpath& tp = result.value();
    ASSERT_GE(tp.size(), 8u);

    const auto& begin = std::get<toolpath::SectionBegin>(tp.record(0));
    EXPECT_EQ(begin.operationName, "Outer contour");
    EXPECT_EQ(begin.strategy, "profile");
    EXPECT_EQ(begin.toolNumber, 2);
    EXPECT_EQ(begin.feeds.cuttingMmPerMin, 1200);
    EXPECT_EQ(begin.feeds.plungeMmPerMin, 300);

    const auto& rapid1 = std::get<toolpath::Rapid>(tp.record(1));
    const auto& rapid2 = std::get<toolpath::Rapid>(tp.record(2));
    const auto& plunge = std::get<toolpath::Linear>(tp.record(3));
    const Vec2 start = plunge.to.xy();
    // The plunge happens in the middle of a long (74 mm) straight side.
    EXPECT_NEAR(start.x, 45, 1e-12);
    EXPECT_TRUE(std::abs(start.y + 5) < 1e-12 || std::abs(start.y - 65) < 1e-12) << start.y;
    EXPECT_EQ(rapid1.to, (Vec3{start.x, start.y, 15}));
    EXPECT_EQ(rapid2.to, (Vec3{start.x, start.y, 2}));
    EXPECT_EQ(plunge.to.z, -3);
    EXPECT_EQ(plunge.feedMmPerMin, 300);

    const auto& retract = std::get<toolpath::Rapid>(tp.record(tp.size() - 2));
    EXPECT_EQ(retract.to, (Vec3{start.x, start.y, 15}));
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

TEST(ProfileOp, LoopIsClosedAtDepthWithArcsOfRadius13OnCornerCentres)
{
    for (bool climb : {true, false}) {
        SCOPED_TRACE(climb ? "climb" : "conventional");
        const auto tc = tenMillimetreTool();
        const auto p = params(climb);
        auto result = ops::computeOuterProfile(kPlate, p, tc, 0);
        ASSERT_TRUE(result.ok()) << result.error().message;
        const toolpath::Toolpath& tp = result.value();
        const Walk w = walkLoop(tp, p, tc);
        EXPECT_NEAR(distance(w.start, w.end), 0, 1e-12);
        EXPECT_EQ(w.arcs, 4);
        // Climb around an outside boundary is clockwise, conventional counter-clockwise.
        EXPECT_EQ(w.cw, climb ? 4 : 0);
        EXPECT_EQ(w.ccw, climb ? 0 : 4);
        const double loopArea = polygonArea(w.loopPoints);
        EXPECT_EQ(loopArea < 0, climb);

        for (std::size_t i = 4; i + 2 < tp.size(); ++i)
            if (const auto* a = std::get_if<toolpath::Arc>(&tp.record(i))) {
                EXPECT_NEAR(distance(a->to.xy(), a->center.xy()), 13, 1e-9);
                bool onCorner = false;
                for (const Vec2& c : kCornerCentres)
                    onCorner = onCorner || distance(c, a->center.xy()) < 1e-12;
                EXPECT_TRUE(onCorner) << a->center.x << ", " << a->center.y;
            }
        for (const Vec2& pt : w.loopPoints)
            EXPECT_NEAR(distanceToProfile(pt, kPlate), 5, 1e-9) << pt.x << ", " << pt.y;
    }
}

TEST(ProfileOp, ClockwiseBoundaryGivesTheSameToolpath)
{
    const auto tc = tenMillimetreTool();
    auto a = ops::computeOuterProfile(kPlate, params(), tc, 0);
    auto b = ops::computeOuterProfile(kPlate.reversed(), params(), tc, 0);
    ASSERT_TRUE(a.ok());
    ASSERT_TRUE(b.ok());
    const Walk wa = walkLoop(a.value(), params(), tc);
    const Walk wb = walkLoop(b.value(), params(), tc);
    EXPECT_EQ(wb.cw, 4);
    EXPECT_NEAR(polygonArea(wa.loopPoints), polygonArea(wb.loopPoints), 1e-6);
}

TEST(ProfileOp, CircularBossIsTwoHalfCircles)
{
    const auto tc = tenMillimetreTool();
    auto result = ops::computeOuterProfile(circle({20, 10}, 15), params(), tc, 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const toolpath::Toolpath& tp = result.value();
    ASSERT_EQ(tp.size(), 4u + 2u + 2u);
    const Walk w = walkLoop(tp, params(), tc);
    EXPECT_EQ(w.cw, 2);
    EXPECT_NEAR(distance(w.start, w.end), 0, 1e-12);
    for (const Vec2& pt : w.loopPoints)
        EXPECT_NEAR(distance(pt, {20, 10}), 20, 1e-9);
    const auto& first = std::get<toolpath::Arc>(tp.record(4));
    EXPECT_GT(distance(first.to.xy(), w.start), 39.9);  // half way round, not back on the start
}

TEST(ProfileOp, TraceIsStable)
{
    auto result = ops::computeOuterProfile(rectangle(0, 0, 40, 20), params(), tenMillimetreTool(), 0);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(toolpath::traceOf(result.value()),
              "section \"Outer contour\" profile tool 2 cut 1200.0000 plunge 300.0000\n"
              "rapid 20.0000 25.0000 15.0000\n"
              "rapid 20.0000 25.0000 2.0000\n"
              "linear 20.0000 25.0000 -3.0000 f 300.0000\n"
              "linear 40.0000 25.0000 -3.0000 f 1200.0000\n"
              "arc cw 45.0000 20.0000 -3.0000 c 40.0000 20.0000 -3.0000 n 0.0000 0.0000 1.0000 turns 0 f 1200.0000\n"
              "linear 45.0000 0.0000 -3.0000 f 1200.0000\n"
              "arc cw 40.0000 -5.0000 -3.0000 c 40.0000 0.0000 -3.0000 n 0.0000 0.0000 1.0000 turns 0 f 1200.0000\n"
              "linear 0.0000 -5.0000 -3.0000 f 1200.0000\n"
              "arc cw -5.0000 0.0000 -3.0000 c 0.0000 0.0000 -3.0000 n 0.0000 0.0000 1.0000 turns 0 f 1200.0000\n"
              "linear -5.0000 20.0000 -3.0000 f 1200.0000\n"
              "arc cw 0.0000 25.0000 -3.0000 c 0.0000 20.0000 -3.0000 n 0.0000 0.0000 1.0000 turns 0 f 1200.0000\n"
              "linear 20.0000 25.0000 -3.0000 f 1200.0000\n"
              "rapid 20.0000 25.0000 15.0000\n"
              "endsection\n");
}

TEST(ProfileOp, ValidationErrors)
{
    const auto good = tenMillimetreTool();
    auto expectError = [](const geom::Profile& boundary, const ops::ProfileParams& p, const ops::ToolController& tc,
                          const std::string& fragment) {
        auto r = ops::computeOuterProfile(boundary, p, tc, 0);
        ASSERT_FALSE(r.ok()) << "expected an error about " << fragment;
        EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().message;
    };
    auto tc = good;
    tc.tool.diameterMm = 0;
    expectError(kPlate, params(), tc, "tool diameter");
    tc.tool.diameterMm = -10;
    expectError(kPlate, params(), tc, "tool diameter");
    tc = good;
    tc.cuttingFeedMmPerMin = 0;
    expectError(kPlate, params(), tc, "cutting feed");
    tc = good;
    tc.plungeFeedMmPerMin = -1;
    expectError(kPlate, params(), tc, "plunge feed");
    tc = good;
    tc.spindleRpm = 0;
    expectError(kPlate, params(), tc, "spindle speed");

    auto p = params();
    p.clearanceZ = 1;  // below safeZ 2
    expectError(kPlate, p, good, "clearance height");
    p = params();
    p.safeZ = p.finalDepthZ;
    expectError(kPlate, p, good, "safe height");
    p = params();
    p.safeZ = -5;
    p.clearanceZ = 0;
    expectError(kPlate, p, good, "safe height");
    expectError(geom::Profile{}, params(), good, "empty");

    // Geometry the tool cannot follow: a concave arc of radius 4 with a 10 mm tool.
    geom::Profile notched;
    notched.segments = {
        geom::Segment::line({0, 0}, {80, 0}),    geom::Segment::line({80, 0}, {80, 50}),
        geom::Segment::line({80, 50}, {44, 50}), geom::Segment::arc({44, 50}, {36, 50}, {40, 50}, false),
        geom::Segment::line({36, 50}, {0, 50}),  geom::Segment::line({0, 50}, {0, 0}),
    };
    expectError(notched, params(), good, "tool too large for the concave arc of radius 4");
    // clearance == safe is allowed
    p = params();
    p.clearanceZ = p.safeZ;
    EXPECT_TRUE(ops::computeOuterProfile(kPlate, p, good, 0).ok());
}
