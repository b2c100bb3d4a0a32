// The setup sheet's HTML writer (Qt-free): names from the job are escaped wherever they appear,
// durations read as an operator reads them, the pictures carry their sizes, and a sheet made
// without the simulator says so instead of showing empty counts.
#include "sheet/SheetHtml.h"

#include <gtest/gtest.h>

namespace camwb::sheet {
namespace {

document::SetupSheet sheetWithNames()
{
    document::SetupSheet sheet;
    sheet.jobName = "Bracket <rev \"B\"> & co";
    sheet.ncFile = "bracket.mpf";
    document::SheetTool tool;
    tool.controller.tool.number = 3;
    tool.controller.tool.name = "D6 <long>";
    tool.controller.tool.holder = "ER32 & collet";
    tool.stickOutMm = 17.5;
    tool.operations = {"Pocket <1>"};
    sheet.tools.push_back(tool);
    document::SheetOperation op;
    op.name = "Pocket <1>";
    op.kind = "pocket";
    op.toolNumber = 3;
    op.seconds = 75.25;
    sheet.operations.push_back(op);
    return sheet;
}

TEST(SheetHtml, EscapesTheJobsNames)
{
    const std::string html = sheetHtml(sheetWithNames(), {});
    EXPECT_NE(html.find("<title>Setup sheet: Bracket &lt;rev &quot;B&quot;&gt; &amp; co</title>"), std::string::npos);
    EXPECT_NE(html.find("<td>D6 &lt;long&gt;</td>"), std::string::npos);
    EXPECT_NE(html.find("<td>ER32 &amp; collet</td>"), std::string::npos);
    EXPECT_NE(html.find("<h3>1. Pocket &lt;1&gt; (T3, 1 min 15.3 s)</h3>"), std::string::npos);
    EXPECT_EQ(html.find("<1>"), std::string::npos);
    EXPECT_EQ(html.find("<long>"), std::string::npos);
}

TEST(SheetHtml, PicturesCarryTheirSizes)
{
    SheetImages images;
    images.part = {"sheet-images/part.png", 720, 480};
    images.operations = {{"sheet-images/op-1.png", 480, 320}};
    const std::string html = sheetHtml(sheetWithNames(), images);
    EXPECT_NE(html.find("<img src=\"sheet-images/part.png\" width=\"720\" height=\"480\""), std::string::npos);
    EXPECT_NE(html.find("<img src=\"sheet-images/op-1.png\" width=\"480\" height=\"320\""), std::string::npos);
}

TEST(SheetHtml, SaysWhenTheSimulatorDidNotRun)
{
    document::SetupSheet sheet = sheetWithNames();
    EXPECT_NE(sheetHtml(sheet, {}).find("The simulator was not run"), std::string::npos);
    sheet.verification.run = true;
    sheet.verification.gouges = 2;
    sheet.verification.firstFindings = {"Pocket <1>: gouge"};
    const std::string html = sheetHtml(sheet, {});
    EXPECT_NE(html.find("Simulated: ERRORS FOUND."), std::string::npos);
    EXPECT_NE(html.find("<tr><td>Gouges into the model</td><td>2</td></tr>"), std::string::npos);
    EXPECT_NE(html.find("<li>Pocket &lt;1&gt;: gouge</li>"), std::string::npos);
}

TEST(SheetHtml, Durations)
{
    EXPECT_EQ(formatDuration(0), "0.0 s");
    EXPECT_EQ(formatDuration(59.94), "59.9 s");
    EXPECT_EQ(formatDuration(60), "1 min 0.0 s");
    EXPECT_EQ(formatDuration(465.4), "7 min 45.4 s");
    EXPECT_EQ(formatDuration(59.97), "1 min 0.0 s");
    EXPECT_EQ(formatDuration(119.97), "2 min 0.0 s");
}

}  // namespace
}  // namespace camwb::sheet
