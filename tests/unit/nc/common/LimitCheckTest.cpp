// Machine checks of an interpreted program: each finding once, on the line that caused it.
#include "nc/LimitCheck.h"

#include "kinematics/Machine.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

namespace camwb::nc {
namespace {

using namespace camwb::toolpath;

kinematics::Machine smallMill()
{
    kinematics::Machine m;
    m.name = "Mill";
    m.axes = {{"X", false, -50, 50}, {"Y", false, 0, 80}, {"Z", false, -100, 0}};
    m.spindleMinRpm = 100;
    m.spindleMaxRpm = 5000;
    m.toolStations = 10;
    m.maxCuttingFeedMmPerMin = 2000;
    return m;
}

TEST(LimitCheck, ForwardsEverythingAndWarnsOncePerFinding)
{
    const kinematics::Machine machine = smallMill();
    ToolpathRecorder recorder;
    LimitCheck check(machine, recorder);
    auto line = [&](int n) { check.setSource(SourceRef{-1, -1, n, 0}); };
    line(1), check.toolChange(ToolChange{Tool{12}});
    line(2), check.spindle(Spindle{6000, true});
    line(3), check.spindle(Spindle{7000, true});
    line(4), check.rapid(Rapid{{0, 0, 10}});
    line(5), check.linear(Linear{{120, 0, 10}, 2500});
    line(6), check.linear(Linear{{0, 0, 10}, 3000});
    EXPECT_EQ(recorder.toolpath().size(), 6u);
    EXPECT_EQ(recorder.toolpath().source(4).line, 5);

    const auto found = check.diagnostics({"p.mpf"});
    ASSERT_EQ(found.size(), 4u);
    EXPECT_EQ(formatDiagnostic(found[0]), "p.mpf:1: warning: tool 12 is not one of Mill's 10 stations");
    EXPECT_EQ(formatDiagnostic(found[1]), "p.mpf:2: warning: spindle speed 6000.000 rpm is above Mill's 5000.000 rpm");
    EXPECT_EQ(formatDiagnostic(found[2]), "p.mpf:5: warning: feed 2500.000 mm/min is above Mill's 2000.000 mm/min");
    EXPECT_EQ(formatDiagnostic(found[3]),
              "p.mpf:5: warning: the program spans 120.000 mm in X (0.000 to 120.000), more than Mill's 100.000 mm "
              "travel");
}

TEST(LimitCheck, ProgramWithinLimitsIsQuiet)
{
    const kinematics::Machine machine = smallMill();
    ToolpathRecorder recorder;
    LimitCheck check(machine, recorder);
    check.spindle(Spindle{3000, true});
    check.rapid(Rapid{{-40, 10, 5}});
    check.linear(Linear{{40, 70, -20}, 1500});
    check.feedMode(FeedModeChange{FeedMode::PerRevolution});
    check.linear(Linear{{0, 0, -20}, 3000});  // mm/rev: not compared with the mm/min limit
    EXPECT_TRUE(check.diagnostics({"p.mpf"}).empty());
}

}  // namespace
}  // namespace camwb::nc
