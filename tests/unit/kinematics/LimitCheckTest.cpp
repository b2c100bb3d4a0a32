// The one machine limit check, as posting (CL records), `nc trace --machine` and the inspector use
// it: each kind of finding once at its first record, with the count; records pass on unchanged.
#include "kinematics/LimitCheck.h"

#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace camwb::kinematics
