// Swarf milling on an analytic drafted boss (a cone narrowing upward, 15 degrees draft): the tip on
// the bottom circle moved off by the tool radius along the normal, the axis on the rulings, the
// chord and angle tolerances between consecutive points, climb direction, entry and exit along the
// tool axis, passes, and the errors.
#include "ops/SwarfOp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace camwb::ops {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDraft = 15 * kPi / 180;
constexpr double kBaseRadius = 10, kHeight = 5;

geom::RulingPoint coneAt(double t)
{
    const double c = std::cos(t), s = std::sin(t);
    return {{kBaseRadius * c, kBaseRadius * s, 0},
            {-std::sin(kDraft) * c, -std::sin(kDraft) * s, std::cos(kDraft)},
            {std::cos(kDraft) * c, std::cos(kDraft) * s, std::sin(kDraft)},
            kHeight / std::cos(kDraft)};
}

SwarfDrive coneDrive() { return {0, 2 * kPi, true, coneAt}; }

ToolController endMill()
{
    ToolController tc;
    tc.tool.number = 2;
    tc.tool.diameterMm = 6;
    tc.tool.fluteLengthMm = 16;
    tc.spindleRpm = 4500;
    tc.cuttingFeedMmPerMin = 500;
    tc.plungeFeedMmPerMin = 120;
    return tc;
}

SwarfParams params()
{
    SwarfParams p;
    p.name = "Cone";
    p.heights.clearanceZ = 30;
    p.heights.safeZ = 12;
    return p;
}

std::vector<toolpath::ToolAxisMove> moves(const OpResult& r)
{
    std::vector<toolpath::ToolAxisMove> out;
    for (const toolpath::Record& record : r.toolpath.records())
        if (const auto* m = std::get_if<toolpath::ToolAxisMove>(&record))
            out.push_back(*m);
    return out;
}

// The cone parameter of a pose: the direction its axis leans in.
double paramOf(const toolpath::ToolAxisMove& m) { return std::atan2(-m.axis.y, -m.axis.x); }

std::vector<toolpath::ToolAxisMove> cuts(const OpResult& r)
{
    std::vector<toolpath::ToolAxisMove> out;
    for (const toolpath::ToolAxisMove& m : moves(r))
        if (m.feedMmPerMin == 500)
            out.push_back(m);
    return out;
}

TEST(SwarfOp, TipOnTheDriveEdgeOffByTheRadiusAxisOnTheRulings)
{
    auto r = computeSwarf(coneDrive(), params(), endMill(), 3);
    ASSERT_TRUE(r.ok()) << r.error().toString();
    const std::vector<toolpath::ToolAxisMove> cut = cuts(r.value());
    ASSERT_GT(cut.size(), 16u);
    for (const toolpath::ToolAxisMove& m : cut) {
        const geom::RulingPoint exact = coneAt(paramOf(m));
        EXPECT_NEAR(distance(m.tip, exact.point + exact.normal * 3), 0, 1e-9);
        EXPECT_NEAR(distance(m.axis, exact.ruling), 0, 1e-6);
        EXPECT_NEAR(m.axis.length(), 1, 1e-12);
    }
    // Round the whole loop: back at the start.
    EXPECT_NEAR(distance(cut.back().tip, moves(r.value())[2].tip), 0, 1e-9);
}

TEST(SwarfOp, ConsecutivePointsKeepTheChordAndAngleTolerances)
{
    for (const auto& [chord, angle] : {std::pair{0.01, 1.0}, {0.001, 1.0}, {0.1, 0.5}, {0.05, 5.0}}) {
        SwarfParams p = params();
        p.chordToleranceMm = chord;
        p.angleToleranceDeg = angle;
        auto r = computeSwarf(coneDrive(), p, endMill(), 0);
        ASSERT_TRUE(r.ok()) << r.error().toString();
        const std::vector<toolpath::ToolAxisMove> cut = cuts(r.value());
        std::vector<toolpath::ToolAxisMove> all = moves(r.value());
        // The plunge ends on the first pose; the cut runs from there.
        const toolpath::ToolAxisMove start = all[2];
        double worstChord = 0, worstAngle = 0;
        toolpath::ToolAxisMove a = start;
        for (const toolpath::ToolAxisMove& b : cut) {
            worstAngle = std::max(worstAngle, std::acos(std::min(1.0, a.axis.dot(b.axis))) * 180 / kPi);
            double ta = paramOf(a), tb = paramOf(b);
            if (tb > ta)
                tb -= 2 * kPi;  // clockwise (climb round a boss): the parameter falls
            for (int k = 1; k < 20; ++k) {
                const double t = ta + (tb - ta) * k / 20;
                const geom::RulingPoint e = coneAt(t);
                const base::Vec3 tip = e.point + e.normal * 3;
                for (double h : {0.0, kHeight / std::cos(kDraft)}) {
                    const base::Vec3 p0 = a.tip + a.axis * h, p1 = b.tip + b.axis * h, q = tip + e.ruling * h;
                    const base::Vec3 d = p1 - p0;
                    const double f = std::clamp((q - p0).dot(d) / d.dot(d), 0.0, 1.0);
                    worstChord = std::max(worstChord, distance(q, p0 + d * f));
                }
            }
            a = b;
        }
        EXPECT_LE(worstChord, chord * 1.0001) << chord << " " << angle;
        EXPECT_LE(worstAngle, angle + 1e-9) << chord << " " << angle;
        // One of the tolerances is what limits the step (bisection halves it at most).
        EXPECT_TRUE(worstChord > chord / 8 || worstAngle > angle / 2) << chord << " " << angle;
    }
}

TEST(SwarfOp, ClimbGoesClockwiseRoundABossConventionalTheOtherWay)
{
    for (bool climb : {true, false}) {
        SwarfParams p = params();
        p.climb = climb;
        auto r = computeSwarf(coneDrive(), p, endMill(), 0);
        ASSERT_TRUE(r.ok());
        const std::vector<toolpath::ToolAxisMove> cut = cuts(r.value());
        const double turn = cut[0].tip.cross(cut[1].tip).z;
        EXPECT_EQ(turn < 0, climb);
    }
}

TEST(SwarfOp, EntersAndLeavesAlongTheToolAxis)
{
    auto r = computeSwarf(coneDrive(), params(), endMill(), 7);
    ASSERT_TRUE(r.ok());
    const toolpath::Toolpath& path = r->toolpath;
    const auto* begin = std::get_if<toolpath::SectionBegin>(&path.record(0));
    ASSERT_NE(begin, nullptr);
    EXPECT_EQ(begin->strategy, "swarf");
    EXPECT_EQ(begin->toolNumber, 2);
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionEnd>(path.record(path.size() - 1)));
    EXPECT_EQ(path.source(0).operationIndex, 7);
    const std::vector<toolpath::ToolAxisMove> m = moves(r.value());
    ASSERT_GE(m.size(), 5u);
    const toolpath::ToolAxisMove& first = m[2];
    EXPECT_EQ(m[0].feedMmPerMin, 0);
    EXPECT_NEAR(m[0].tip.z, 30, 1e-9);
    EXPECT_EQ(m[1].feedMmPerMin, 0);
    EXPECT_NEAR(m[1].tip.z, 12, 1e-9);
    EXPECT_EQ(first.feedMmPerMin, 120);
    for (int i : {0, 1}) {
        EXPECT_NEAR(distance(m[i].axis, first.axis), 0, 1e-12);
        EXPECT_NEAR((m[i].tip - first.tip).cross(first.axis).length(), 0, 1e-9);  // on the axis line
    }
    const toolpath::ToolAxisMove& last = m.back();
    EXPECT_EQ(last.feedMmPerMin, 0);
    EXPECT_NEAR(last.tip.z, 30, 1e-9);
    EXPECT_NEAR((last.tip - m[m.size() - 2].tip).cross(last.axis).length(), 0, 1e-9);
    EXPECT_EQ(r->counts.rapids, 3);
}

TEST(SwarfOp, PassesStepInToTheFaceAndTheAxialOffsetLiftsTheTip)
{
    SwarfParams p = params();
    p.radialPasses = 3;
    p.radialStepoverMm = 0.5;
    p.radialStockMm = 0.2;
    p.axialOffsetMm = 1;
    auto r = computeSwarf(coneDrive(), p, endMill(), 0);
    ASSERT_TRUE(r.ok()) << r.error().toString();
    const std::vector<toolpath::ToolAxisMove> m = moves(r.value());
    std::vector<double> offsets;
    for (const toolpath::ToolAxisMove& move : m) {
        if (move.feedMmPerMin == 0)
            continue;
        const geom::RulingPoint e = coneAt(paramOf(move));
        const base::Vec3 d = move.tip - e.point - e.ruling * 1;  // the axial offset along the ruling
        EXPECT_NEAR(d.cross(e.normal).length(), 0, 1e-9);
        const double offset = d.dot(e.normal);
        if (offsets.empty() || std::abs(offsets.back() - offset) > 1e-9)
            offsets.push_back(offset);
    }
    ASSERT_EQ(offsets.size(), 3u);
    EXPECT_NEAR(offsets[0], 3 + 0.2 + 1, 1e-9);
    EXPECT_NEAR(offsets[1], 3 + 0.2 + 0.5, 1e-9);
    EXPECT_NEAR(offsets[2], 3 + 0.2, 1e-9);
    EXPECT_EQ(r->counts.rapids, 3);  // a closed drive steps in at feed, no retract between passes
}

TEST(SwarfOp, ErrorsNameTheOperation)
{
    auto message = [](SwarfParams p, ToolController tc = endMill()) {
        auto r = computeSwarf(coneDrive(), p, tc, 0);
        return r.ok() ? std::string("ok") : r.error().message;
    };
    SwarfParams p = params();
    ToolController shortFlutes = endMill();
    shortFlutes.tool.fluteLengthMm = 4;
    EXPECT_EQ(message(p, shortFlutes),
              "swarf \"Cone\": the face reaches 5.1764 mm up the tool from its tip, beyond its 4 mm flute length");
    p.axialOffsetMm = 1.5;  // lifted, the flutes cover it
    EXPECT_EQ(message(p, shortFlutes), "ok");
    p = params();
    p.angleToleranceDeg = 0;
    EXPECT_EQ(message(p), "swarf \"Cone\": angle tolerance must be above 0 and at most 45 degrees, got 0 degrees");
    p = params();
    p.chordToleranceMm = -1;
    EXPECT_EQ(message(p), "swarf \"Cone\": chord tolerance must be positive, got -1 mm");
    p = params();
    p.radialPasses = 0;
    EXPECT_EQ(message(p), "swarf \"Cone\": radial passes must be at least 1, got 0");
    p = params();
    p.heights.safeZ = -5;
    EXPECT_NE(message(p).find("the safe height -5 mm is below the tip at"), std::string::npos) << message(p);
    // A drive whose rulings point down: nowhere to go up along the axis.
    SwarfDrive down = coneDrive();
    down.at = [](double t) {
        geom::RulingPoint r = coneAt(t);
        r.ruling = r.ruling * -1;
        return r;
    };
    auto r = computeSwarf(down, params(), endMill(), 0);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("points down or nearly level"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace camwb::ops
