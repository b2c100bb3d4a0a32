// The one machine limit check, as posting (CL records), `nc trace --machine` and the inspector use
// it: each kind of finding once at its first record, with the count; records pass on unchanged.
#include "kinematics/LimitCheck.h"

#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <limits>

namespace camwb::kinematics {
namespace {

using namespace camwb::toolpath;

Machine smallMill()
{
    Machine m;
    m.id = "mill";
    m.name = "Mill";
    m.axes = {{"X", false, -50, 50}, {"Y", false, 0, 80}, {"Z", false, -100, 0}};
    m.spindleMinRpm = 100;
    m.spindleMaxRpm = 5000;
    m.toolStations = 10;
    m.maxToolDiameterMm = 20;
    m.maxToolLengthMm = 100;
    m.maxCuttingFeedMmPerMin = 2000;
    m.coolants = {"flood"};
    return m;
}

std::vector<std::string> texts(const std::vector<base::Diagnostic>& diagnostics)
{
    std::vector<std::string> out;
    for (const base::Diagnostic& d : diagnostics)
        out.push_back(base::formatDiagnostic(d));
    return out;
}

// A lathe has X and Z only: moves in its XZ plane (Y not given, or 0 as arcs give it) pass,
// a move to another Y is one it cannot make.
TEST(LimitCheck, ALatheFlagsAMoveOffItsXZPlane)
{
    Machine lathe;
    lathe.id = "lathe";
    lathe.name = "Lathe";
    lathe.axes = {{"X", false, 0, 1000}, {"Z", false, 0, 10000}};
    ToolpathRecorder recorder;
    LimitCheck check(lathe, recorder);
    auto line = [&](int n) { check.setSource(SourceRef{-1, -1, n, 0}); };
    line(1), check.rapid(Rapid{{200, 0, 0}, AxisMask{AxisMask::kX}});
    line(2), check.rapid(Rapid{{200, 0, 150}, AxisMask{AxisMask::kZ}});
    line(3), check.linear(Linear{{180, 0, 150}, 0.2});
    EXPECT_TRUE(check.ncDiagnostics({"p.mpf"}).empty());
    line(4), check.linear(Linear{{180, 5, 150}, 0.2});
    EXPECT_EQ(texts(check.ncDiagnostics({"p.mpf"})),
              (std::vector<std::string>{
                  "p.mpf:4: warning: a move goes to Y5 but the Lathe turns in X and Z only (a lathe, no Y axis)"}));
}

TEST(LimitCheck, ForwardsEverythingAndFlagsEachKindOnceAtItsFirstLine)
{
    const Machine machine = smallMill();
    ToolpathRecorder recorder;
    LimitCheck check(machine, recorder);
    auto line = [&](int n) { check.setSource(SourceRef{-1, -1, n, 0}); };
    line(1), check.toolChange(ToolChange{Tool{12}});
    line(2), check.spindle(Spindle{6000, true});
    line(3), check.spindle(Spindle{7000, true});
    line(4), check.rapid(Rapid{{0, 0, -10}});
    line(5), check.linear(Linear{{120, 0, -10}, 2500});
    line(6), check.linear(Linear{{0, 0, -10}, 3000});
    EXPECT_EQ(recorder.toolpath().size(), 6u);
    EXPECT_EQ(recorder.toolpath().source(4).line, 5);

    EXPECT_EQ(texts(check.ncDiagnostics({"p.mpf"})),
              (std::vector<std::string>{
                  "p.mpf:1: warning: tool T12 has no station: the Mill has stations 1..10",
                  "p.mpf:2: warning: spindle speed 6000 rpm is above the Mill's maximum of 5000 rpm (2 times in all)",
                  "p.mpf:5: warning: feed 2500 mm/min is above the Mill's maximum cutting feed of 2000 mm/min (2 times "
                  "in all)",
                  "p.mpf:5: warning: the program spans 120 mm in X (0 to 120); the Mill travels 100 mm"}));
}

TEST(LimitCheck, NamesTheClRecordWhenCheckingAToolpath)
{
    const Machine machine = smallMill();
    Toolpath path;
    path.add(ToolChange{Tool{3, "", "flat", 25, 0, 20, 120}});
    path.add(Coolant{CoolantMode::Mist});
    path.add(Spindle{50, true});
    path.add(Rapid{{0, 10, -5}});
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    play(path, check);
    EXPECT_EQ(texts(check.clDiagnostics()),
              (std::vector<std::string>{
                  "warning: tool T3 is 25 mm in diameter; the Mill takes at most 20 mm (CL record 0)",
                  "warning: tool T3 is 120 mm long; the Mill takes at most 100 mm (CL record 0)",
                  "warning: coolant mist is not available on the Mill (CL record 1)",
                  "warning: spindle speed 50 rpm is below the Mill's minimum of 100 rpm (CL record 2)"}));
}

// Posting and reading NC back used to disagree: one refused T0, the other accepted it. T0 empties
// the spindle on the controls we serve (LinuxCNC, SINUMERIK, Heidenhain TOOL CALL 0), so the change
// itself is fine; cutting with no tool after it is not.
TEST(LimitCheck, ToolZeroEmptiesTheSpindleAndCuttingAfterItIsFlagged)
{
    const Machine machine = smallMill();
    NullSink nowhere;
    LimitCheck unload(machine, nowhere);
    unload.toolChange(ToolChange{Tool{5}});
    unload.linear(Linear{{0, 10, -5}, 100});
    unload.toolChange(ToolChange{Tool{0}});
    unload.rapid(Rapid{{0, 10, 0}});
    EXPECT_TRUE(unload.clDiagnostics().empty());

    LimitCheck cutting(machine, nowhere);
    cutting.toolChange(ToolChange{Tool{0}});
    cutting.rapid(Rapid{{0, 10, 0}});
    cutting.linear(Linear{{0, 20, 0}, 100});
    EXPECT_EQ(texts(cutting.clDiagnostics()),
              std::vector<std::string>{"warning: a cutting move with no tool in the spindle (after T0) (CL record 2)"});
}

// The travel check sees an arc's bulge, not only its end points: a half circle from X-40 to X40
// through Y-40 makes a program that reaches Y80 span 120 mm in Y.
TEST(LimitCheck, ArcsCountWithTheirExtremes)
{
    const Machine machine = smallMill();
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    check.rapid(Rapid{{-40, 0, -5}});
    check.rapid(Rapid{{-40, 80, -5}});
    check.rapid(Rapid{{-40, 0, -5}});
    Arc half;
    half.to = {40, 0, -5};
    half.center = {0, 0, -5};
    half.clockwise = false;  // counter-clockwise from -X passes through -Y
    half.feedMmPerMin = 500;
    check.arc(half);
    EXPECT_EQ(texts(check.clDiagnostics()),
              std::vector<std::string>{
                  "warning: the program spans 120 mm in Y (-40 to 80); the Mill travels 80 mm (CL record 3)"});
}

// After a move to where the program does not say (an untraced M140 MB MAX or SUPA), the same arc
// has no known start: it spans nothing from the old place, only its end counts.
TEST(LimitCheck, AnArcFromUnknownAxesCountsByItsEnd)
{
    const Machine machine = smallMill();
    ToolpathRecorder recorder;
    LimitCheck check(machine, recorder);
    check.rapid(Rapid{{-40, 0, -5}});
    check.rapid(Rapid{{-40, 80, -5}});
    check.rapid(Rapid{{-40, 0, -5}});
    check.unknownAxes(UnknownAxes{AxisMask{AxisMask::kX | AxisMask::kY}});
    Arc half;
    half.to = {40, 0, -5};
    half.center = {0, 0, -5};
    half.feedMmPerMin = 500;
    check.arc(half);
    EXPECT_TRUE(check.findings().empty()) << check.findings()[0].message;
    ASSERT_EQ(recorder.toolpath().size(), 5u);  // passed on
    EXPECT_TRUE(std::holds_alternative<UnknownAxes>(recorder.toolpath().record(3)));
}

TEST(LimitCheck, ProgramWithinLimitsIsQuiet)
{
    const Machine machine = smallMill();
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    check.toolChange(ToolChange{Tool{10, "", "flat", 20, 0, 30, 100}});
    check.coolant(Coolant{CoolantMode::Flood});
    check.spindle(Spindle{3000, true});
    check.rapid(Rapid{{-40, 10, 5}});
    check.linear(Linear{{40, 70, -20}, 1500});
    check.feedMode(FeedModeChange{FeedMode::PerRevolution});
    check.linear(Linear{{0, 0, -20}, 3000});  // mm/rev: not compared with the mm/min limit
    EXPECT_TRUE(check.ncDiagnostics({"p.mpf"}).empty());
    EXPECT_TRUE(check.findings().empty());
}

// The minimum cutting feed is checked as the maximum is: per minute only, once at the first
// record with the count. A feed of 0 is no feed (the interpreters report that), not a slow one.
TEST(LimitCheck, FeedBelowTheMinimumIsFlaggedLikeTheMaximum)
{
    Machine machine = smallMill();
    machine.minCuttingFeedMmPerMin = 2;
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    auto line = [&](int n) { check.setSource(SourceRef{-1, -1, n, 0}); };
    line(1), check.rapid(Rapid{{0, 10, 0}});
    line(2), check.linear(Linear{{0, 20, 0}, 2});  // at the minimum: fine
    line(3), check.linear(Linear{{0, 30, 0}, 1.5});
    Arc arc;
    arc.to = {0, 50, 0};
    arc.center = {0, 40, 0};
    arc.feedMmPerMin = 1;
    line(4), check.arc(arc);
    line(5), check.linear(Linear{{0, 60, 0}, 0});
    line(6), check.feedMode(FeedModeChange{FeedMode::PerRevolution});
    line(7), check.linear(Linear{{0, 70, 0}, 0.1});  // mm/rev: not compared with the mm/min limit
    EXPECT_EQ(texts(check.ncDiagnostics({"p.h"})),
              std::vector<std::string>{"p.h:3: warning: feed 1.5 mm/min is below the Mill's minimum cutting feed of 2 "
                                       "mm/min (2 times in all)"});
}

Machine mcvl1000()
{
    auto machine = findMachine("mas-mcvl1000", defaultMachineDirs());
    EXPECT_TRUE(machine.ok()) << machine.error().toString();
    return machine.ok() ? machine.value() : Machine{};
}

// The MAS MCVL 1000 has rotary axes B (limited) and C (endless) besides X/Y/Z: they change
// nothing in the checks of X, Y and Z, and a program within its limits is quiet.
TEST(LimitCheck, RotaryAxesLeaveTheLinearChecksAsTheyWere)
{
    const Machine machine = mcvl1000();
    ASSERT_EQ(machine.axes.size(), 5u);
    NullSink nowhere;
    LimitCheck quiet(machine, nowhere);
    quiet.toolChange(ToolChange{Tool{1, "", "flat", 10, 0, 30, 80}});
    quiet.coolant(Coolant{CoolantMode::Flood});
    quiet.spindle(Spindle{7500, true});
    quiet.rapid(Rapid{{0, 0, 100}});
    quiet.linear(Linear{{1016, 610, -560}, 12000});
    quiet.toolAxisMove(ToolAxisMove{{0, 0, 100}, {0, 0, 1}, 2});
    EXPECT_EQ(texts(quiet.clDiagnostics()), std::vector<std::string>{});

    LimitCheck check(machine, nowhere);
    check.toolChange(ToolChange{Tool{99}});  // a manual change: no stations to check
    check.spindle(Spindle{10, true});
    check.rapid(Rapid{{0, 0, 0}});
    check.linear(Linear{{1100, 0, 0}, 1.5});
    check.linear(Linear{{1100, 700, 0}, 13000});
    check.rapid(Rapid{{1100, 700, 700}});
    EXPECT_EQ(
        texts(check.clDiagnostics()),
        (std::vector<std::string>{
            "warning: spindle speed 10 rpm is below the MAS MCVL 1000's minimum of 20 rpm (CL record 1)",
            "warning: feed 1.5 mm/min is below the MAS MCVL 1000's minimum cutting feed of 2 mm/min (CL record 3)",
            "warning: feed 13000 mm/min is above the MAS MCVL 1000's maximum cutting feed of 12000 mm/min (CL record "
            "4)",
            "warning: the program spans 1100 mm in X (0 to 1100); the MAS MCVL 1000 travels 1016 mm (CL record 3)",
            "warning: the program spans 700 mm in Y (0 to 700); the MAS MCVL 1000 travels 610 mm (CL record 4)",
            "warning: the program spans 700 mm in Z (0 to 700); the MAS MCVL 1000 travels 660 mm (CL record 5)"}));
}

// Axes are found by name, whatever their order among the rotary ones; a rotary axis, endless or
// limited, is no linear travel.
TEST(LimitCheck, LinearAxesAreFoundAmongRotaryOnes)
{
    Machine machine = smallMill();
    const double inf = std::numeric_limits<double>::infinity();
    machine.axes = {{"C", true, -inf, inf, true}, {"Y", false, 0, 80}, {"B", true, -120, 30}, {"X", false, -50, 50}};
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    check.rapid(Rapid{{-40, 0, -500}});
    check.rapid(Rapid{{70, 100, 500}});  // Z has no axis here: not checked
    EXPECT_EQ(texts(check.clDiagnostics()),
              (std::vector<std::string>{
                  "warning: the program spans 110 mm in X (-40 to 70); the Mill travels 100 mm (CL record 1)",
                  "warning: the program spans 100 mm in Y (0 to 100); the Mill travels 80 mm (CL record 1)"}));
}

// A five-axis move that gives its rotary positions (NC read back, a post's pose): each against its
// axis' range, an endless C never; through the machine's chain, the linear spans are the machine's.
TEST(LimitCheck, RotaryPositionsAgainstTheirRangesAndTheChain)
{
    const Machine machine = mcvl1000();
    NullSink nowhere;
    LimitCheck check(machine, nowhere);
    auto move = [](Vec3 tip, double b, double c, unsigned char known = RotaryAxes::kB | RotaryAxes::kC) {
        ToolAxisMove m{tip, {0, 0, 1}, 100};
        m.machine.bDeg = b;
        m.machine.cDeg = c;
        m.machine.known = known;
        return m;
    };
    check.toolAxisMove(move({0, 0, 0}, -30, 1000));  // C endless: fine
    check.toolAxisMove(move({0, 0, 0}, 35, 0));      // B above +30
    check.toolAxisMove(move({0, 0, 0}, -125, 0));    // below -120: the same finding again
    ToolAxisMove withA = move({0, 0, 0}, 0, 0, RotaryAxes::kA);
    withA.machine.aDeg = 10;
    check.toolAxisMove(withA);  // the machine has no A
    EXPECT_EQ(
        texts(check.clDiagnostics()),
        (std::vector<std::string>{
            "warning: B35 is outside the MAS MCVL 1000's B range -120 .. 30 degrees (CL record 1; 2 records in all)",
            "warning: a move turns A but the MAS MCVL 1000 has no rotary axis A (CL record 3)"}));

    // The tip stays at X 400 while B turns -90: about MRZP the machine's X goes to 0 and its Z to
    // 400, so the span in Z is 800 > 660 where the tip's own span is 0.
    LimitCheck spans(machine, nowhere);
    spans.toolAxisMove(move({400, 0, 0}, -90, 0));
    spans.toolAxisMove(move({400, 0, 0}, 90 - 180, 180));  // the same tilt on the other branch
    spans.toolAxisMove(move({-400, 0, 0}, -90, 0));
    const auto diagnostics = texts(spans.clDiagnostics());
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0], "warning: the program spans 800 mm in Z (-400 to 400); the MAS MCVL 1000 travels 660 mm "
                              "(CL record 1)");
}

// 3+2: a tilted plane needs a machine whose chain can tilt the tool so; the moves in it count in
// the machine's axes through the pose that does.
TEST(LimitCheck, TiltedWorkingPlanes)
{
    NullSink nowhere;
    const Machine mill = smallMill();  // the check keeps a reference: not a temporary
    LimitCheck flat(mill, nowhere);
    flat.workingPlane(WorkingPlane{{0, 0, 0}, {1, 0, 0}, {0, -0.6, 0.8}});
    flat.rapid(Rapid{{0, 0, 0}});
    EXPECT_EQ(texts(flat.clDiagnostics()),
              (std::vector<std::string>{"warning: a tilted working plane (3+2), but the Mill has no five-axis chain in "
                                        "its machine file to tilt the tool (CL record 0)"}));

    const Machine machine = mcvl1000();
    LimitCheck tilted(machine, nowhere);
    // The tool along -X: within B -120..+30 only the branch B -90 remains; about MRZP it turns
    // the workpiece's X into the machine's Z.
    tilted.workingPlane(WorkingPlane{{0, 0, 0}, {0, 0, 1}, {-1, 0, 0}});
    tilted.rapid(Rapid{{0, 0, 400}});                                     // 400 along the tool axis: the workpiece's -X
    tilted.rapid(Rapid{{0, 0, -400}});                                    // and +X: the machine's Z, 800 apart
    tilted.workingPlane(WorkingPlane{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}});  // upside down: no pose
    const auto findings = texts(tilted.clDiagnostics());
    ASSERT_EQ(findings.size(), 2u);
    EXPECT_NE(findings[0].find("working plane with tool axis (0, 0, -1): no solution within the rotary limits"),
              std::string::npos)
        << findings[0];
    EXPECT_EQ(findings[1], "warning: the program spans 800 mm in Z (-400 to 400); the MAS MCVL 1000 travels 660 mm "
                           "(CL record 2)");
}

}  // namespace
}  // namespace camwb::kinematics
