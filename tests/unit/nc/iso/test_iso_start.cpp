// The program start: no axis is known until a block gives it in absolute terms, so the first
// moves carry only the axes they give, and a block that needs an unknown axis is an error.
#include "IsoTestSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using toolpath::AxisMask;
using toolpath::Linear;
using toolpath::Rapid;
using toolpath::Vec3;

TEST(IsoStart, FirstMoveInZOnlyMovesZ)
{
    const IsoRun r = run("G21 G90\nG0 Z5\nG0 X10 Y20\nG1 X11 Y20 Z-1 F100\nM2\n", InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), "");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[0].axes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(rapids[0].to.z, 5);
    EXPECT_EQ(rapids[1].axes, AxisMask{});  // every axis known from here on
    EXPECT_EQ(rapids[1].to, (Vec3{10, 20, 5}));
    ASSERT_EQ(r.all<Linear>().size(), 1u);
    EXPECT_TRUE(r.all<Linear>()[0].axes.all());
    EXPECT_EQ(r.trace.substr(0, r.trace.find('\n')), "2 rapid z 5.0000 s 0.0000 t 0");
}

TEST(IsoStart, FirstMoveGivingEveryAxisIsAFullMove)
{
    const IsoRun r = run("G0 X1 Y2 Z3\nM2\n", InterpretOptions{});
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.all<Rapid>()[0].axes.all());
    EXPECT_EQ(r.trace, "1 rapid 1.0000 2.0000 3.0000 s 0.0000 t 0\n");
}

TEST(IsoStart, IncrementalMoveOnAnUnknownAxisIsAnError)
{
    const IsoRun r = run("G0 Z5\nG91 G0 Z1 X2\nG90 G0 X0 Y0\nM2\n", InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), "2:11: error: X is unknown here: no absolute X has been programmed yet, and an "
                               "incremental move needs it; nothing moves\n");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);  // the incremental block moved nothing
    EXPECT_EQ(rapids[0].to.z, 5);
    EXPECT_EQ(rapids[1].to, (Vec3{0, 0, 5}));
}

TEST(IsoStart, ArcBeforeXAndYAreKnownIsAnError)
{
    const IsoRun r = run("G0 Z5\nG2 X10 Y0 I5 J0 F100\nM2\n", InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), "2:4: error: X is unknown here: no absolute X has been programmed yet, and the arc "
                               "needs it; nothing moves\n");
    EXPECT_TRUE(r.all<toolpath::Arc>().empty());
}

TEST(IsoStart, CycleAndCompensationNeedTheirAxes)
{
    const IsoRun r = run("G0 X0 Y0\nG81 X5 Y5 Z-3 R2 F100\nG0 Z10\nG41.1 D4\nG1 X10 F100\nM2\n", InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), "2:11: error: Z is unknown here: no absolute Z has been programmed yet, and the "
                               "canned cycle needs it; nothing moves\n");
    EXPECT_TRUE(r.all<toolpath::Cycle>().empty());
    ASSERT_EQ(r.all<Linear>().size(), 1u);  // Z known by then: compensation starts
}

TEST(IsoStart, ACallerThatKnowsTheStartGivesIt)
{
    InterpretOptions options;
    options.start = Vec3{1, 2, 3};
    const IsoRun r = run("G0 Z5\nM2\n", options);
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.all<Rapid>()[0].axes.all());
    EXPECT_EQ(r.all<Rapid>()[0].to, (Vec3{1, 2, 5}));
}

}  // namespace
}  // namespace camwb::nc::iso::test
