// The program start: no axis is known until a block gives it in absolute terms, so the first
// moves carry only the axes they give, and a block that needs an unknown axis is an error.
#include "TestSupport.h"

namespace camwb::nc::sinumerik::test {
namespace {

using toolpath::AxisMask;
using toolpath::Linear;
using toolpath::Rapid;
using toolpath::Vec3;

TEST(SinumerikStart, FirstMoveInZOnlyMovesZ)
{
    const NcRun r = run("G17 G90 G54\nG0 Z5\nG0 X10 Y20\nG1 X11 Z-1 F100\nM30\n", {}, InterpretOptions{});
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[0].axes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(rapids[0].to.z, 5);
    EXPECT_TRUE(rapids[1].axes.all());
    EXPECT_EQ(rapids[1].to, (Vec3{10, 20, 5}));
    ASSERT_EQ(r.all<Linear>().size(), 1u);
    EXPECT_TRUE(r.all<Linear>()[0].axes.all());
    EXPECT_EQ(r.trace().substr(0, r.trace().find('\n')), "2 rapid z 5.0000 s 0.0000 t 0");
}

TEST(SinumerikStart, FirstMoveGivingEveryAxisIsAFullMove)
{
    const NcRun r = run("G0 X1 Y2 Z3\nM30\n", {}, InterpretOptions{});
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.all<Rapid>()[0].axes.all());
    EXPECT_EQ(r.trace(), "1 rapid 1.0000 2.0000 3.0000 s 0.0000 t 0\n");
}

// DIAMON/DIAMOF say the program is for a lathe: its tool works in the XZ plane through the
// spindle axis, so Y is 0 and a G18 arc needs nothing unknown.
TEST(SinumerikStart, TurningProgramHasItsToolAtYZero)
{
    const NcRun r = run("G18 G90 DIAMON\nG0 X62 Z2\nG1 X50 Z0 F100\nG2 X60 Z-5 CR=5\nM30\n", {}, InterpretOptions{});
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<toolpath::Arc>().size(), 1u);
    EXPECT_EQ(r.all<toolpath::Arc>()[0].to, (Vec3{30, 0, -5}));
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.all<Rapid>()[0].axes.all());  // X and Z given, Y on the spindle axis
    EXPECT_EQ(r.all<Rapid>()[0].to, (Vec3{31, 0, 2}));
}

TEST(SinumerikStart, IncrementalMoveOnAnUnknownAxisIsAnError)
{
    const NcRun r = run("G0 Z5\nG0 Z=IC(1) X=IC(2)\nG91 Y3\nG90 X0 Y0\nM30\n", {}, InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), "MAIN.MPF:2:12: error: X is unknown here: no absolute X has been programmed yet, "
                               "and an incremental move needs it; nothing moves\n"
                               "MAIN.MPF:3:5: error: Y is unknown here: no absolute Y has been programmed yet, "
                               "and an incremental move needs it; nothing moves\n");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);  // the incremental blocks moved nothing
    EXPECT_EQ(rapids[1].to, (Vec3{0, 0, 5}));
}

TEST(SinumerikStart, ArcAndCycleBeforeXAndYAreKnownAreErrors)
{
    const NcRun r = run("G0 Z5\nG2 X10 Y0 I5 J0 F100\nCYCLE81(10, 0, 2, -5)\nM30\n", {}, InterpretOptions{});
    EXPECT_EQ(r.errors(), 2) << r.diagnostics();
    const Diagnostic* arc = r.find("and the arc needs it");
    ASSERT_NE(arc, nullptr) << r.diagnostics();
    EXPECT_EQ(arc->line, 2);
    EXPECT_EQ(arc->message.substr(0, 20), "X is unknown here: n");
    const Diagnostic* cycle = r.find("the drilling cycle");
    ASSERT_NE(cycle, nullptr) << r.diagnostics();
    EXPECT_EQ(cycle->line, 3);
    EXPECT_TRUE(r.all<toolpath::Arc>().empty());
    EXPECT_TRUE(r.all<toolpath::Cycle>().empty());
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
