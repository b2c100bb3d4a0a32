#include "ops/OpCommon.h"

#include <gtest/gtest.h>

using namespace camwb;

TEST(StepDownLevels, EqualStepsNoDeeperThanTheStepDown)
{
    const std::vector<double> levels = ops::stepDownLevels(15, 5, 3);  // 10 mm in 4 steps of 2.5
    ASSERT_EQ(levels.size(), 4u);
    EXPECT_DOUBLE_EQ(levels[0], 12.5);
    EXPECT_DOUBLE_EQ(levels[1], 10);
    EXPECT_DOUBLE_EQ(levels[2], 7.5);
    EXPECT_DOUBLE_EQ(levels[3], 5);
}

TEST(StepDownLevels, ExactDivisionHasNoSliverLevel)
{
    EXPECT_EQ(ops::stepDownLevels(6, 0, 2).size(), 3u);
    EXPECT_EQ(ops::stepDownLevels(0.3, 0, 0.1).size(), 3u);
}

TEST(StepDownLevels, NoStepDownOrAStepDeeperThanTheCutIsOneLevel)
{
    EXPECT_EQ(ops::stepDownLevels(15, 5, 0), std::vector<double>{5});
    EXPECT_EQ(ops::stepDownLevels(15, 5, 12), std::vector<double>{5});
}

TEST(OpChecks, NameTheOperationAndTheValue)
{
    ops::ToolController tc;
    tc.tool.diameterMm = 6;
    tc.cuttingFeedMmPerMin = 500;
    tc.plungeFeedMmPerMin = 100;
    tc.spindleRpm = 0;
    auto status = ops::checkToolController("pocket \"P\"", tc);
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error().message, "pocket \"P\": spindle speed must be positive, got 0 rpm");

    ops::Heights h{10, 2, 5, 0};  // safe below start
    EXPECT_NE(ops::checkHeights("x", h).error().message.find("safe height 2"), std::string::npos);
    h = {10, 8, 5, 0};
    EXPECT_TRUE(ops::checkHeights("x", h));

    toolpath::Tool tool;
    tool.fluteLengthMm = 4;
    EXPECT_FALSE(ops::checkCuttingLength("x", h, tool));  // 5 mm deep
    tool.fluteLengthMm = 5;
    EXPECT_TRUE(ops::checkCuttingLength("x", h, tool));
}

TEST(CountMotions, TellsArcsFromHelices)
{
    toolpath::Toolpath tp;
    tp.add(toolpath::Rapid{{0, 0, 5}});
    tp.add(toolpath::Linear{{10, 0, 0}, 100});
    tp.add(toolpath::Arc{{0, 0, 0}, {5, 0, 0}, {0, 0, 1}, false, 0, 100});
    tp.add(toolpath::Arc{{10, 0, -1}, {5, 0, 0}, {0, 0, 1}, false, 0, 100});
    const ops::MotionCounts c = ops::countMotions(tp);
    EXPECT_EQ(c.rapids, 1);
    EXPECT_EQ(c.lines, 1);
    EXPECT_EQ(c.arcs, 1);
    EXPECT_EQ(c.helices, 1);
}
