// The post kernel's five-axis services (post/FiveAxisPlan.h) on a B/C table-table machine in
// seed 000's convention: the branch chosen over the whole operation, the error naming the CL
// record, the pole keeping C, retract-turn-re-enter, and the joint-space linearisation.
#include "post/FiveAxisPlan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace camwb::post {
namespace {

using kinematics::MachinePose;
using toolpath::Vec3;

constexpr double kPi = 3.14159265358979323846;

// B -120..+30 about +Y, C about +Z through MRZP (the origin); C endless unless `cLimit` > 0.
kinematics::Machine bcTable(double cLimit = 0)
{
    kinematics::Machine m;
    m.id = "test-bc";
    m.axes = {{"X", false, -1000, 1000}, {"Y", false, -1000, 1000}, {"Z", false, -1000, 1000}};
    m.axes.push_back({"B", true, -120, 30});
    kinematics::Axis c{"C", true, -1e300, 1e300, true};
    if (cLimit > 0)
        c = {"C", true, -cLimit, cLimit, false};
    m.axes.push_back(c);
    m.kinematics.type = kinematics::ChainType::TableTable;
    m.kinematics.joints = {{"B", true, {0, 1, 0}, {}}, {"C", true, {0, 0, 1}, {}}};
    m.kinematics.preferredJoint = 0;
    m.kinematics.preferredSign = 1;  // B > 0 first: a move-by-move choice starts there
    return m;
}

// Tool axis tilted `tiltDeg` from +Z towards the direction `azimuthDeg` in XY.
Vec3 tilted(double tiltDeg, double azimuthDeg)
{
    const double t = tiltDeg * kPi / 180, a = azimuthDeg * kPi / 180;
    return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

toolpath::Toolpath fiveAxisSection(const std::vector<std::pair<Vec3, Vec3>>& moves)
{
    toolpath::Toolpath tp;
    tp.add(toolpath::SectionBegin{});
    for (const auto& [tip, axis] : moves)
        tp.add(toolpath::ToolAxisMove{tip, axis, 500});
    tp.add(toolpath::SectionEnd{});
    return tp;
}

std::vector<const FiveAxisStep*> moves(const FiveAxisPlan& plan)
{
    std::vector<const FiveAxisStep*> result;
    for (const FiveAxisStep& step : plan.steps)
        if (step.kind == StepKind::Move)
            result.push_back(&step);
    return result;
}

TEST(FiveAxisPlan, ChoosesTheBranchThatFinishesTheOperation)
{
    // 20 deg is reachable with B > 0 (the preferred branch) and B < 0; 40 deg only with B < 0
    // (B stops at +30). Move by move the first pose would take B+20 and flip later.
    const auto tp = fiveAxisSection({{{0, 0, 0}, tilted(20, 0)},
                                     {{5, 0, 0}, tilted(30, 0)},
                                     {{10, 0, 0}, tilted(40, 0)},
                                     {{15, 0, 0}, tilted(35, 0)}});
    auto plan = planFiveAxis(tp, bcTable(), {}, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    ASSERT_EQ(plan.value().sections.size(), 1u);
    EXPECT_EQ(plan.value().sections[0].reconfigurations, 0);
    for (const FiveAxisStep* step : moves(plan.value())) {
        EXPECT_LT(step->pose.rotaryDeg[0], 0) << "record " << step->record;
        EXPECT_FALSE(step->reconfigure);
        const auto fk = kinematics::forwardKinematics(bcTable().kinematics, step->pose);
        EXPECT_NEAR(distance(fk.tip, step->tool.tip), 0, 1e-9);
        EXPECT_NEAR(distance(fk.axis, step->tool.axis), 0, 1e-9);
    }
}

TEST(FiveAxisPlan, APoseOutOfReachNamesItsRecord)
{
    // 130 deg of tilt: beyond B's -120 on either branch.
    const auto tp = fiveAxisSection({{{0, 0, 0}, tilted(10, 0)}, {{1, 0, 0}, tilted(130, 90)}});
    auto plan = planFiveAxis(tp, bcTable(), {}, 0.01);
    ASSERT_FALSE(plan);
    EXPECT_NE(plan.error().message.find("CL record 2 ToolAxisMove"), std::string::npos) << plan.error().message;
}

TEST(FiveAxisPlan, ThePoleKeepsC)
{
    const auto tp = fiveAxisSection(
        {{{0, 0, 0}, tilted(20, 140)}, {{1, 0, 0}, {0, 0, 1}}, {{2, 0, 0}, tilted(0.004, 10)}, {{3, 0, 0}, {0, 0, 1}}});
    FiveAxisOptions options;
    options.poleConeDeg = 0.01;
    auto plan = planFiveAxis(tp, bcTable(), options, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    const auto m = moves(plan.value());
    ASSERT_EQ(m.size(), 4u);
    const double c = m[0]->pose.rotaryDeg[1];
    for (std::size_t i = 1; i < m.size(); ++i) {
        EXPECT_TRUE(m[i]->pole) << i;
        EXPECT_NEAR(m[i]->pose.rotaryDeg[1], c, 1e-9) << i;
        EXPECT_NEAR(m[i]->pose.rotaryDeg[0], 0, 1e-9) << i;
    }
    EXPECT_EQ(plan.value().poleAdjusted, 1);
    EXPECT_EQ(plan.value().firstPoleAdjusted, 3u);
    EXPECT_NEAR(plan.value().maxAxisDeviationDeg, 0.004, 1e-9);
}

// Through the pole on a B that may not be positive, the tool axis goes from one side to the other:
// C must turn half a turn, and it turns on the pole (tip and axis still), not during the next
// move, where B and C together would swing the axis off the CL's plane.
TEST(FiveAxisPlan, CTurnsOnThePoleNotOnTheWayOut)
{
    kinematics::Machine machine = bcTable();
    machine.axes[3] = {"B", true, -120, 0};
    const auto tp =
        fiveAxisSection({{{-5, 0, 0}, tilted(20, 180)}, {{0, 0, 0}, {0, 0, 1}}, {{5, 0, 0}, tilted(20, 0)}});
    auto plan = planFiveAxis(tp, machine, {}, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    const auto m = moves(plan.value());
    ASSERT_EQ(m.size(), 4u);
    EXPECT_TRUE(m[1]->pole);
    EXPECT_NEAR(m[1]->pose.rotaryDeg[1], m[0]->pose.rotaryDeg[1], 1e-9);  // arrives with C kept
    // The turn: the pole's tip and axis, B still 0, C where the last move needs it.
    EXPECT_NEAR(distance(m[2]->tool.tip, Vec3{0, 0, 0}), 0, 1e-12);
    EXPECT_NEAR(m[2]->pose.rotaryDeg[0], 0, 1e-9);
    EXPECT_NEAR(std::abs(m[2]->pose.rotaryDeg[1] - m[1]->pose.rotaryDeg[1]), 180, 1e-9);
    EXPECT_NEAR(m[3]->pose.rotaryDeg[1], m[2]->pose.rotaryDeg[1], 1e-9);  // the way out turns B only
    EXPECT_LT(m[3]->pose.rotaryDeg[0], 0);
    EXPECT_EQ(m[2]->record, m[3]->record);
}

TEST(FiveAxisPlan, RetractsTurnsAndReentersWhereTheLimitsForceIt)
{
    // The tool axis goes round twice at 30 deg of tilt: C must pass its +-200 limit.
    std::vector<std::pair<Vec3, Vec3>> ring;
    for (int i = 0; i <= 48; ++i)
        ring.push_back({{std::cos(i * kPi / 12) * 20, std::sin(i * kPi / 12) * 20, 0}, tilted(30, i * 15.0)});
    const auto tp = fiveAxisSection(ring);
    FiveAxisOptions options;
    options.retractMm = 40;
    auto plan = planFiveAxis(tp, bcTable(200), options, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    EXPECT_GE(plan.value().sections[0].reconfigurations, 1);
    const auto& steps = plan.value().steps;
    bool found = false;
    for (std::size_t i = 1; i + 3 < steps.size(); ++i) {
        if (steps[i].kind != StepKind::Retract)
            continue;
        found = true;
        const FiveAxisStep& before = steps[i - 1];
        EXPECT_NEAR(distance(steps[i].tool.tip, before.tool.tip + before.tool.axis * 40), 0, 1e-9);
        EXPECT_EQ(steps[i].pose.rotaryDeg, before.pose.rotaryDeg);
        EXPECT_EQ(steps[i + 1].kind, StepKind::Turn);
        EXPECT_EQ(steps[i + 2].kind, StepKind::Approach);
        EXPECT_EQ(steps[i + 3].kind, StepKind::Move);
        EXPECT_TRUE(steps[i + 3].reconfigure);
        EXPECT_EQ(steps[i + 2].pose.rotaryDeg, steps[i + 3].pose.rotaryDeg);
        EXPECT_NEAR(distance(steps[i + 2].tool.tip, steps[i + 3].tool.tip + steps[i + 3].tool.axis * 40), 0, 1e-9);
    }
    EXPECT_TRUE(found);
    for (const FiveAxisStep& step : steps)
        EXPECT_LE(std::abs(step.pose.rotaryDeg[1]), 200 + 1e-9);

    options.retractToReconfigure = false;
    auto refused = planFiveAxis(tp, bcTable(200), options, 0.01);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("CL record"), std::string::npos) << refused.error().message;
    EXPECT_NE(refused.error().message.find("reconfigured"), std::string::npos) << refused.error().message;
}

TEST(FiveAxisPlan, TheNextSectionStartsWhereTheRotariesWentHome)
{
    // The first section turns the tool axis round once and a bit: C ends near +-380.
    toolpath::Toolpath tp;
    tp.add(toolpath::SectionBegin{});
    for (int az = 0; az <= 380; az += 20)
        tp.add(toolpath::ToolAxisMove{{0, 0, 0}, tilted(30, az), 500});
    tp.add(toolpath::SectionEnd{});
    tp.add(toolpath::SectionBegin{});
    tp.add(toolpath::ToolAxisMove{{0, 0, 0}, tilted(30, 10), 500});
    tp.add(toolpath::SectionEnd{});
    auto plan = planFiveAxis(tp, bcTable(), {}, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    ASSERT_EQ(plan.value().sections.size(), 2u);
    const auto& first = plan.value().sections[0];
    const double lastC = plan.value().steps[first.endStep - 1].pose.rotaryDeg[1];
    EXPECT_GT(std::abs(lastC), 360);
    EXPECT_EQ(first.home[0], 0);
    EXPECT_EQ(first.home[1], 360 * std::round(lastC / 360));
    // Planned from there: no turn back over a whole revolution.
    const double nextC = plan.value().steps[plan.value().sections[1].firstStep].pose.rotaryDeg[1];
    EXPECT_LT(std::abs(nextC - first.home[1]), 180) << nextC;
}

TEST(FiveAxisPlan, ArcsInAFiveAxisSectionAreToolPosesAlongTheirChords)
{
    toolpath::Toolpath tp;
    tp.add(toolpath::SectionBegin{});
    tp.add(toolpath::ToolAxisMove{{0, 0, 0}, tilted(20, 0), 500});
    tp.add(toolpath::Linear{{10, 0, 0}, 500});
    toolpath::Arc arc;
    arc.to = {20, 10, 0};
    arc.center = {10, 10, 0};
    arc.normal = {0, 0, 1};
    arc.clockwise = false;
    arc.feedMmPerMin = 500;
    tp.add(arc);
    tp.add(toolpath::SectionEnd{});
    auto plan = planFiveAxis(tp, bcTable(), {}, 0.01);
    ASSERT_TRUE(plan) << plan.error().message;
    EXPECT_EQ(plan.value().arcsLinearised, 1);
    EXPECT_EQ(plan.value().firstArcLinearised, 3u);
    int points = 0;
    for (const FiveAxisStep& step : plan.value().steps) {
        if (step.record != 3)
            continue;
        ++points;
        EXPECT_NEAR(distance(step.tool.tip, Vec3{10, 10, 0}), 10, 1e-9);
        EXPECT_EQ(step.tool.axis, (Vec3{0, 0, 1}));
        EXPECT_NEAR(step.pose.rotaryDeg[0], 0, 1e-9);  // on the pole: B0, C kept
    }
    EXPECT_GT(points, 5);
}

TEST(FiveAxisPlan, ThreeAxisSectionsAreNotPlanned)
{
    toolpath::Toolpath tp;
    tp.add(toolpath::SectionBegin{});
    tp.add(toolpath::Rapid{{0, 0, 10}});
    tp.add(toolpath::Linear{{10, 0, 10}, 300});
    tp.add(toolpath::SectionEnd{});
    auto plan = planFiveAxis(tp, bcTable(), {}, 0.01);
    ASSERT_TRUE(plan);
    EXPECT_TRUE(plan.value().steps.empty());
}

// Dense samples of the tip along each piece, as the control moves every axis linearly.
double worstDeviation(const kinematics::KinematicChain& chain, const MachinePose& start,
                      const std::vector<MachinePose>& pieces, const Vec3& a, const Vec3& b)
{
    double worst = 0;
    MachinePose from = start;
    for (const MachinePose& to : pieces) {
        for (int k = 0; k <= 64; ++k) {
            const double t = k / 64.0;
            MachinePose p;
            p.linear = from.linear + (to.linear - from.linear) * t;
            for (int j = 0; j < 2; ++j)
                p.rotaryDeg[j] = from.rotaryDeg[j] + (to.rotaryDeg[j] - from.rotaryDeg[j]) * t;
            const Vec3 tip = kinematics::forwardKinematics(chain, p).tip;
            const Vec3 ab = b - a;
            const double s = std::clamp((tip - a).dot(ab) / ab.dot(ab), 0.0, 1.0);
            worst = std::max(worst, distance(tip, a + ab * s));
        }
        from = to;
    }
    return worst;
}

TEST(FiveAxisPlan, MachineCoordinatesAreLinearisedWithinTheTolerance)
{
    const auto chain = bcTable().kinematics;
    const Vec3 a{60, 0, 10}, b{60, 20, 10};
    MachinePose from, to;
    from.rotaryDeg = {-30, 0};
    to.rotaryDeg = {-40, 60};
    from.linear = kinematics::linearAxesFor(chain, a, from.rotaryDeg);
    to.linear = kinematics::linearAxesFor(chain, b, to.rotaryDeg);
    // One block would swing the tip far off the line ...
    EXPECT_GT(worstDeviation(chain, from, {to}, a, b), 1.0);
    // ... the pieces keep it within 0.01 mm and end exactly at the CL point.
    const auto pieces = lineariseJointMove(chain, from, to, a, b, 0.01);
    ASSERT_GT(pieces.size(), 4u);
    EXPECT_LE(worstDeviation(chain, from, pieces, a, b), 0.0101);
    EXPECT_EQ(pieces.back().linear, to.linear);
    EXPECT_EQ(pieces.back().rotaryDeg, to.rotaryDeg);
    // A move of the linear axes alone is one block.
    MachinePose shifted = from;
    shifted.linear = from.linear + Vec3{5, 0, 0};
    EXPECT_EQ(lineariseJointMove(chain, from, shifted, a, a + Vec3{5, 0, 0}, 0.01).size(), 1u);
}

TEST(FiveAxisPlan, CombinedFeedGivesTheTipItsTime)
{
    MachinePose from, to;
    to.linear = {3, 4, 0};   // 5 mm of linear axes
    to.rotaryDeg = {0, 12};  // and 12 degrees: 13 "units" in all
    bool capped = true;
    // The tip moves 10 mm at 600 mm/min (1 s): 13 units in 1 s is F780.
    EXPECT_NEAR(combinedFeed(from, to, 10, 600, 0, &capped), 780, 1e-9);
    EXPECT_FALSE(capped);
    EXPECT_NEAR(combinedFeed(from, to, 10, 600, 700, &capped), 700, 1e-9);
    EXPECT_TRUE(capped);
    MachinePose turn;
    turn.rotaryDeg = {0, 90};  // the tip stands: the CL feed as degrees per minute
    EXPECT_NEAR(combinedFeed(from, turn, 0, 600, 0), 600, 1e-9);
}

TEST(FiveAxisPlan, InverseTimeFeedIsTheTipsTime)
{
    MachinePose from, to;
    to.linear = {3, 4, 0};
    to.rotaryDeg = {0, 12};
    bool capped = true;
    // 10 mm at 600 mm/min: 1/60 min, F60 in inverse time.
    EXPECT_NEAR(inverseTimeFeed(from, to, 10, 600, 0, &capped), 60, 1e-9);
    EXPECT_FALSE(capped);
    // All axes together (13 units) at most 390/min: the block takes 1/30 min.
    EXPECT_NEAR(inverseTimeFeed(from, to, 10, 600, 390, &capped), 30, 1e-9);
    EXPECT_TRUE(capped);
    MachinePose turn;
    turn.rotaryDeg = {0, 90};  // the tip stands: 90 degrees at 600 degrees/min
    EXPECT_NEAR(inverseTimeFeed(from, turn, 0, 600, 0), 600.0 / 90, 1e-9);
}

}  // namespace
}  // namespace camwb::post
