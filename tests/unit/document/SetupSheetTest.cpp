// The setup sheet's facts: the stick-out each tool needs (hand-computed from its deepest tip
// below the clearance box), the work offset's name, and the sheet of the example job.
#include "document/SetupSheet.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "post/PostRegistry.h"
#include "sim/Moves.h"
#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <cmath>

namespace camwb::document {
namespace {

toolpath::ToolChange toolChange(int number)
{
    toolpath::Tool tool;
    tool.number = number;
    tool.diameterMm = 6;
    return toolpath::ToolChange{tool};
}

TEST(SetupSheet, StickOutIsTheDeepestTipBelowTheClearanceBoxPlusTheMargin)
{
    toolpath::Toolpath program;
    // T1 cuts 3 mm below the box's bottom, whose top is Z 12: 12 + 3 + 2 = 17 mm.
    program.add(toolChange(1));
    program.add(toolpath::Rapid{{5, 5, 20}});
    program.add(toolpath::Linear{{5, 5, -3}, 100});
    program.add(toolpath::Linear{{20, 5, -3}, 100});
    program.add(toolpath::Rapid{{20, 5, 20}});
    // T2 stays above the box: only the margin.
    program.add(toolChange(2));
    program.add(toolpath::Rapid{{5, 5, 20}});
    program.add(toolpath::Linear{{5, 5, 15}, 100});
    // T4 tilted 45° towards +X, tip at X 40 Z 6: the box's highest corner along the axis
    // (1, 0, 1)/√2 is (40, y, 12), so the tip is (40 + 12 - 40 - 6)/√2 = 6/√2 below it.
    program.add(toolChange(4));
    const base::Vec3 axis{1 / std::sqrt(2.0), 0, 1 / std::sqrt(2.0)};
    program.add(toolpath::ToolAxisMove{{60, 15, 30}, axis, 500});
    program.add(toolpath::ToolAxisMove{{40, 15, 6}, axis, 500});
    const sim::MoveList moves = sim::buildMoves(program);
    const base::Box3 clear{{0, 0, 0}, {40, 30, 12}, false};

    ASSERT_TRUE(requiredStickOut(moves, 1, clear, 2));
    EXPECT_NEAR(*requiredStickOut(moves, 1, clear, 2), 17.0, 1e-9);
    EXPECT_NEAR(*requiredStickOut(moves, 1, clear, 0.5), 15.5, 1e-9);
    EXPECT_NEAR(*requiredStickOut(moves, 2, clear, 2), 2.0, 1e-9);
    EXPECT_FALSE(requiredStickOut(moves, 3, clear, 2));  // never moved
    ASSERT_TRUE(requiredStickOut(moves, 4, clear, 2));
    EXPECT_NEAR(*requiredStickOut(moves, 4, clear, 2), 6 / std::sqrt(2.0) + 2, 1e-9);
}

TEST(SetupSheet, WorkOffsetNames)
{
    // As the bundled posts write them: the operator sets the offset the NC calls.
    EXPECT_EQ(workOffsetName(1, "sinumerik828d-emco"), "G54");
    EXPECT_EQ(workOffsetName(4, "sinumerik840d"), "G57");
    EXPECT_EQ(workOffsetName(5, "sinumerik828d-emco"), "G505");
    EXPECT_EQ(workOffsetName(99, "sinumerik840d"), "G599");
    EXPECT_EQ(workOffsetName(2, "heidenhain-itnc530"), "preset 2");
    EXPECT_EQ(workOffsetName(6, "linuxcnc"), "G59");
    EXPECT_EQ(workOffsetName(7, "linuxcnc"), "G59.1");
    EXPECT_EQ(workOffsetName(10, "linuxcnc"), "offset 10");
}

TEST(SetupSheet, ExampleJobToolsOperationsAndTimes)
{
    const std::string path = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.camwb";
    auto job = loadJob(path);
    ASSERT_TRUE(job) << job.error().toString();
    auto model = loadJobModel(job.value());
    ASSERT_TRUE(model) << model.error().toString();
    auto program = computeProgram(job.value(), model.value());
    ASSERT_TRUE(program) << program.error().toString();
    SheetOptions options;
    options.simulate = false;
    options.postDirs = post::defaultPostDirs();
    auto sheet = collectSetupSheet(job.value(), path, model.value(), program.value(), options);
    ASSERT_TRUE(sheet) << sheet.error().toString();

    EXPECT_EQ(sheet->ncFile, "example-block.mpf");
    EXPECT_FALSE(sheet->verification.run);
    ASSERT_EQ(sheet->tools.size(), 3u);
    // T1's contour ends at Z 10 under the stock top at Z 16: 6 + 2 mm.
    ASSERT_TRUE(sheet->tools[0].stickOutMm);
    EXPECT_NEAR(*sheet->tools[0].stickOutMm, 8.0, 1e-6);
    EXPECT_EQ(sheet->tools[1].operations.size(), 2u);
    ASSERT_EQ(sheet->operations.size(), 4u);
    double sum = 0;
    for (const SheetOperation& op : sheet->operations) {
        EXPECT_GT(op.seconds, 0) << op.name;
        sum += op.seconds;
    }
    // Every move but the work offset's belongs to an operation.
    EXPECT_NEAR(sum, sheet->cycleSeconds, 1e-6);
    EXPECT_FALSE(sheet->tools[0].tooShort);

    // A T1 of 7 mm cannot stick out the 8 mm its contour needs.
    job.value().tools[0].tool.lengthMm = 7;
    auto shortTool = collectSetupSheet(job.value(), path, model.value(), program.value(), options);
    ASSERT_TRUE(shortTool);
    EXPECT_TRUE(shortTool->tools[0].tooShort);
    EXPECT_FALSE(shortTool->tools[1].tooShort);

    // A disabled operation is listed as not posted, takes no time and is not a use of its tool.
    job.value().operations[1].enabled = false;
    auto withoutPocket = computeProgram(job.value(), model.value());
    ASSERT_TRUE(withoutPocket);
    auto disabled = collectSetupSheet(job.value(), path, model.value(), withoutPocket.value(), options);
    ASSERT_TRUE(disabled);
    ASSERT_EQ(disabled->operations.size(), 4u);
    EXPECT_NE(disabled->operations[1].kind.find("disabled: not posted"), std::string::npos);
    EXPECT_EQ(disabled->operations[1].seconds, 0);
    EXPECT_EQ(disabled->tools[1].operations.size(), 1u);
}

}  // namespace
}  // namespace camwb::document
