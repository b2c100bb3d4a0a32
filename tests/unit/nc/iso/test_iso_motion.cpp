// Modal state and straight moves: units, distance modes, feeds, spindle, tools, coolant, dwell,
// work offsets, compensation, stops and the end of program.
#include "IsoTestSupport.h"
#include "nc/ToolTable.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

TEST(IsoMotion, InchScaledToMillimetres)
{
    const IsoRun r = run("G20 G0 X1 Y2\nG1 Z-0.5 F10\nG21 G1 X1\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(r.all<Rapid>().at(0).to, (Vec3{25.4, 50.8, 0}));
    const auto lines = r.all<Linear>();
    EXPECT_EQ(lines.at(0).to, (Vec3{25.4, 50.8, -12.7}));
    EXPECT_DOUBLE_EQ(lines.at(0).feedMmPerMin, 254);
    EXPECT_EQ(lines.at(1).to, (Vec3{1, 50.8, -12.7}));
    EXPECT_DOUBLE_EQ(lines.at(1).feedMmPerMin, 254);  // the feed stays what it was
}

TEST(IsoMotion, IncrementalMoves)
{
    const IsoRun r = run("G0 X10 Y10\nG91 X1 Y-1\nZ-2\nG90 X0\nM2\n");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 4u);
    EXPECT_EQ(moves[1].to, (Vec3{11, 9, 0}));
    EXPECT_EQ(moves[2].to, (Vec3{11, 9, -2}));
    EXPECT_EQ(moves[3].to, (Vec3{0, 9, -2}));
}

TEST(IsoMotion, FeedModes)
{
    const IsoRun r = run("G93 G1 X10 F2\nG95 G1 X20 F0.1\nG94 G1 X30 F300\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto modes = r.all<FeedModeChange>();
    ASSERT_EQ(modes.size(), 3u);
    EXPECT_EQ(modes[0].mode, FeedMode::InverseTime);
    EXPECT_EQ(modes[1].mode, FeedMode::PerRevolution);
    EXPECT_EQ(modes[2].mode, FeedMode::PerMinute);
    const auto lines = r.all<Linear>();
    EXPECT_EQ(lines[0].feedMmPerMin, 2);
    EXPECT_EQ(lines[1].feedMmPerMin, 0.1);
    EXPECT_EQ(lines[2].feedMmPerMin, 300);
}

TEST(IsoMotion, InverseTimeNeedsFOnEveryFeedBlock)
{
    const IsoRun r = run("G93 G1 X10 F2\nX20\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:0: error: G1 under G93 (inverse time) needs an F word in the block\n");
}

TEST(IsoMotion, SpindleToolsCoolant)
{
    const IsoRun r = run("S1000 M3\nM4\nS2000\nT3 M6\nM3\nM8\nM7\nM9\nM5\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto spindles = r.all<Spindle>();
    ASSERT_EQ(spindles.size(), 6u);
    EXPECT_EQ(spindles[0].rpm, 1000);
    EXPECT_TRUE(spindles[0].clockwise);
    EXPECT_FALSE(spindles[1].clockwise);
    EXPECT_EQ(spindles[2].rpm, 2000);
    EXPECT_EQ(spindles[3].rpm, 0);  // M6 stops the spindle
    EXPECT_EQ(spindles[4].rpm, 2000);
    EXPECT_TRUE(spindles[4].clockwise);
    EXPECT_EQ(spindles[5].rpm, 0);
    ASSERT_EQ(r.all<ToolChange>().size(), 1u);
    EXPECT_EQ(r.all<ToolChange>()[0].tool.number, 3);
    const auto coolant = r.all<Coolant>();
    ASSERT_EQ(coolant.size(), 3u);
    EXPECT_EQ(coolant[0].mode, CoolantMode::Flood);
    EXPECT_EQ(coolant[1].mode, CoolantMode::Mist);
    EXPECT_EQ(coolant[2].mode, CoolantMode::Off);
}

TEST(IsoMotion, DwellWorkOffsetsCompensationStops)
{
    const IsoRun r = run("G4 P0.5\nG55\nG59\nG59.1\nG59.3\nG54\nG41 D1\nG40\nG42\nG40\nM0\nM1\nM30\n");
    EXPECT_EQ(r.diagnostics(), "");
    ASSERT_EQ(r.all<Dwell>().size(), 1u);
    EXPECT_EQ(r.all<Dwell>()[0].seconds, 0.5);
    const auto offsets = r.all<WorkOffset>();
    ASSERT_EQ(offsets.size(), 5u);
    EXPECT_EQ(offsets[0].index, 2);
    EXPECT_EQ(offsets[1].index, 6);
    EXPECT_EQ(offsets[2].index, 7);
    EXPECT_EQ(offsets[3].index, 9);
    EXPECT_EQ(offsets[4].index, 1);
    const auto comp = r.all<CutterComp>();
    ASSERT_EQ(comp.size(), 4u);
    EXPECT_EQ(comp[0].side, CutterCompSide::Left);
    EXPECT_EQ(comp[1].side, CutterCompSide::Off);
    EXPECT_EQ(comp[2].side, CutterCompSide::Right);
    const auto stops = r.all<ProgramStop>();
    ASSERT_EQ(stops.size(), 2u);
    EXPECT_FALSE(stops[0].optional);
    EXPECT_TRUE(stops[1].optional);
    EXPECT_TRUE(r.result.completed);
}

TEST(IsoMotion, ProgramEndResetsAndStops)
{
    const IsoRun r = run("G56 S500 M3 M8\nG95\nM2\nG0 X99\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_TRUE(r.all<Rapid>().empty());  // nothing runs after M2
    EXPECT_EQ(r.all<Spindle>().back().rpm, 0);
    EXPECT_EQ(r.all<Coolant>().back().mode, CoolantMode::Off);
    EXPECT_EQ(r.all<WorkOffset>().back().index, 1);
    EXPECT_EQ(r.all<FeedModeChange>().back().mode, FeedMode::PerMinute);
    EXPECT_EQ(r.path.source(r.path.size() - 1).line, 3);
}

TEST(IsoMotion, AxisWordsNeedAMotionMode)
{
    const IsoRun r = run("X1\nG0 X2\nG80\nX3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:0: error: axis words without a motion mode (G80 is active): add G0, G1, G2 or G3\n"
                               "4:0: warning: axis words under G80: moving with G0 as Fanuc-style controls do "
                               "(LinuxCNC wants the G word again)\n");
    ASSERT_EQ(r.all<Rapid>().size(), 2u);
    EXPECT_EQ(r.all<Rapid>()[1].to.x, 3);
}

// G53 Z0 is the top of the machine's Z travel, not work Z0: the trace cannot place it, so the axes
// it gives are unknown (and said so to the sinks) until a block gives them; the warning comes once.
TEST(IsoMotion, MachineCoordinatesLeaveTheirAxesUnknown)
{
    const IsoRun r = run("G0 X5 Y6 Z7\nG91 G53 X1\nG53 Z0\nG90 G0 Y8\nG0 X2 Z3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:5: warning: G53: a move in machine coordinates is not traced (the work offset is "
                               "the control's); the axes it gives are unknown until a block gives them\n");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    EXPECT_EQ(rapids[1].axes, AxisMask{AxisMask::kY});  // not moved from X5 Z7, where the tool is not
    EXPECT_TRUE(rapids[2].axes.all());
    EXPECT_EQ(rapids[2].to, (Vec3{2, 8, 3}));
    const auto unknown = r.all<UnknownAxes>();
    ASSERT_EQ(unknown.size(), 2u);
    EXPECT_EQ(unknown[0].axes, AxisMask{AxisMask::kX});
    EXPECT_EQ(unknown[1].axes, AxisMask{AxisMask::kZ});
}

TEST(IsoMotion, ZeroFeedIsAnError)
{
    const IsoRun r = run("G1 X1\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:0: error: G1 with feed rate 0: set F first\n");
}

TEST(IsoMotion, RotaryAxesWarnAndDoNotMove)
{
    const IsoRun r = run("G0 X1 A90\nB10\nM2\n");
    EXPECT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_EQ(r.result.diagnostics.size(), 1u);
    EXPECT_EQ(r.result.diagnostics[0].severity, Severity::Warning);
}

// G28 Z20: up to the intermediate point in work coordinates, then to the stored position, which is
// in machine coordinates (#5163 = 3 is machine Z3, not work Z3): Z unknown after it, X and Y kept.
// Without axis words every axis goes home.
TEST(IsoMotion, ReferenceReturnGoesThroughItsPointToAnUnknownHome)
{
    const IsoRun r = run("#5161=1 #5162=2 #5163=3\nG0 X10 Y10 Z10\nG28 Z20\nG0 X4\nG30\nM2\n");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 3u);
    EXPECT_EQ(moves[1].to, (Vec3{10, 10, 20}));
    EXPECT_EQ(moves[2].axes, (AxisMask{AxisMask::kX | AxisMask::kY}));
    const auto unknown = r.all<UnknownAxes>();
    ASSERT_EQ(unknown.size(), 2u);
    EXPECT_EQ(unknown[0].axes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(unknown[1].axes, (AxisMask{AxisMask::kX | AxisMask::kY}));  // Z was unknown already
    EXPECT_NE(r.diagnostics().find("3:0: warning: G28 goes to the stored position #5161.. in machine coordinates: "
                                   "not traced; the axes it moves are unknown until a block gives them"),
              std::string::npos)
        << r.diagnostics();
}

}  // namespace
}  // namespace camwb::nc::iso::test

namespace camwb::nc::iso::test {
namespace {

TEST(IsoMotion, NewSpeedWithTheSameDirection)
{
    const IsoRun r = run("M3 S3200\nM3 S1800\nS1800\nM3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto spindles = r.all<toolpath::Spindle>();
    ASSERT_EQ(spindles.size(), 3u);  // 3200, 1800, the stop at M2
    EXPECT_EQ(spindles[0].rpm, 3200);
    EXPECT_EQ(spindles[1].rpm, 1800);
    EXPECT_EQ(spindles[2].rpm, 0);
}

TEST(IsoMotion, CompensationRadiusFromTheToolTableOrG41Point1)
{
    // G41 D<tool>, G42 with the tool in the spindle, G41.1 D<diameter> (LinuxCNC).
    ToolTable table;
    table.set({3, 3, 6.0, 0.0, {}});
    table.set({4, 4, 10.0, 0.0, {}});
    InterpretOptions options = fromOrigin();
    options.toolTable = &table;
    const IsoRun r = run("G0 X-10 Y0\nG41 D3\nG1 X0 Y0 F100\nG1 X10 Y0\nG40\nG1 X20 Y-10\n"
                         "T4 M6\nG42\nG1 X30 Y-10\nG1 X40 Y-10\nG40\nG1 X50 Y0\n"
                         "G41.1 D2\nG1 X60 Y0\nG1 X70 Y0\nG40\nG1 X80 Y10\nM2\n",
                         options);
    EXPECT_EQ(r.diagnostics(), "");
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 9u);
    EXPECT_NEAR(lines[0].to.y, 3, 1e-12);    // square to the entry move, left of +X
    EXPECT_NEAR(lines[3].to.y, -15, 1e-12);  // tool 4 in the spindle, right of +X
    EXPECT_NEAR(lines[6].to.y, 1, 1e-12);    // G41.1 D2
}

}  // namespace
}  // namespace camwb::nc::iso::test
