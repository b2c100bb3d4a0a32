// LinuxCNC's tool table format as `camwb-cli nc trace --tool-table` reads it: the tools, and an
// error with file, line and column for every kind of malformed line.
#include "nc/ToolTable.h"

#include <gtest/gtest.h>

namespace camwb::nc::test {
namespace {

TEST(ToolTable, ReadsLinuxCncLines)
{
    const auto table = parseToolTable("; a comment line\n"
                                      "T1 P1 D6.0 Z+25.5 ;flat end mill 6 mm\n"
                                      "\n"
                                      "t2 p5 x0 y0 z30 d10 i0 j0 q0\r\n"
                                      "T12 P12 D.5\n",
                                      "tools.tbl");
    ASSERT_TRUE(table) << table.error().toString();
    ASSERT_EQ(table->tools().size(), 3u);
    const ToolTableEntry* one = table->find(1);
    ASSERT_NE(one, nullptr);
    EXPECT_EQ(one->pocket, 1);
    EXPECT_EQ(one->diameterMm, 6);
    EXPECT_EQ(one->lengthMm, 25.5);
    EXPECT_EQ(one->comment, "flat end mill 6 mm");
    EXPECT_EQ(table->radiusOf(2), 5);
    EXPECT_EQ(table->radiusOf(12), 0.25);
    EXPECT_FALSE(table->radiusOf(3));
}

TEST(ToolTable, MalformedLinesAreErrorsWithTheirPlace)
{
    struct Bad {
        const char* text;
        int line, column;
        const char* message;
    };
    const Bad cases[] = {
        {"T1 P1 D6\nT2 P2 Dx\n", 2, 8, "malformed number after D"},
        {"T1 P1 D6..5\n", 1, 8, "malformed number after D"},
        {"T1 P1 K6\n", 1, 7, "unknown word 'K' (a tool table line holds T P X Y Z A B C U V W D I J Q)"},
        {"P1 D6\n", 1, 1, "tool table line without a tool number T"},
        {"T1 D6\nT1 D8\n", 2, 1, "tool 1 is already given on line 1"},
        {"T1.5 D6\n", 1, 2, "T must be a whole number >= 0"},
        {"T1 D-6\n", 1, 5, "negative diameter (compensation on the other side) is not supported"},
        {"T1 D6 D7\n", 1, 7, "D given twice on one line"},
        {"T1 D6X\n", 1, 5, "malformed number after D"},
    };
    for (const Bad& bad : cases) {
        const auto table = parseToolTable(bad.text, "tools.tbl");
        ASSERT_FALSE(table) << bad.text;
        EXPECT_EQ(table.error().file, "tools.tbl");
        EXPECT_EQ(table.error().line, bad.line) << bad.text;
        EXPECT_EQ(table.error().column, bad.column) << bad.text;
        EXPECT_EQ(table.error().message, bad.message) << bad.text;
    }
}

TEST(ToolTable, AMissingFileIsAnError) { EXPECT_FALSE(readToolTable("/nonexistent/tools.tbl")); }

}  // namespace
}  // namespace camwb::nc::test
