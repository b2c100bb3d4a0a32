// Diagnostics with exact lines and columns, carrying on after a bad line, the cap on kept
// diagnostics, and inputs that must neither crash nor hang.
#include "IsoTestSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

TEST(IsoDiagnostics, LineAndColumn)
{
    const IsoRun r = run("G0 E5\nG0 X[1+2\nG0 (abc\nG0 X1 )\nG0 X1 X2\nG0 G1 X1\nG0 (a (b) c)\nG0 X\nG0 X1 $\n"
                         "G0 X[1]]\nG0 X1 [2]\nG1.55 X1\nM3.5\nG0 X1 M3 M4\nG5 X1\n"
                         "G0 X1e5\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:4: error: unknown word E (LinuxCNC has no E word)\n"
                               "2:5: error: unbalanced brackets: '[' without ']'\n"
                               "3:4: error: comment not closed: missing ')'\n"
                               "4:7: error: ')' without '(' before it\n"
                               "5:7: error: word X given twice in one block\n"
                               "6:4: error: two G codes of the same modal group: G0 and G1\n"
                               "7:7: error: comments cannot nest: '(' inside a comment\n"
                               "8:4: error: missing value after X\n"
                               "9:7: error: unexpected character '$'\n"
                               "10:8: error: ']' outside a word: an expression belongs after a letter or '='\n"
                               "11:7: error: '[' outside a word: an expression belongs after a letter or '='\n"
                               "12:1: error: G number must be positive with at most one decimal\n"
                               "13:1: error: M number must be a positive integer\n"
                               "14:10: error: two M codes of the same modal group: M3 and M4\n"
                               "15:1: error: G5 is not supported by this interpreter\n"
                               "16:6: error: unknown word E (LinuxCNC has no E word)\n");
    EXPECT_TRUE(r.all<Rapid>().empty());
    EXPECT_TRUE(r.result.completed);
    EXPECT_TRUE(r.result.hasErrors());
}

TEST(IsoDiagnostics, CarriesOnAfterABadLine)
{
    const IsoRun r = run("G0 X1\nG0 X[\nG0 X2\nM2\n");
    EXPECT_EQ(r.all<Rapid>().size(), 2u);
    EXPECT_EQ(r.result.diagnostics.size(), 1u);
}

TEST(IsoDiagnostics, FileNameOnEveryDiagnostic)
{
    InterpretOptions options;
    options.fileName = "part.ngc";
    const IsoRun r = run("G0 E1\nM2\n", options);
    ASSERT_EQ(r.result.diagnostics.size(), 1u);
    EXPECT_EQ(r.result.diagnostics[0].file, "part.ngc");
    EXPECT_EQ(formatDiagnostic(r.result.diagnostics[0]),
              "part.ngc:1:4: error: unknown word E (LinuxCNC has no E word)");
    EXPECT_EQ(r.result.files, std::vector<std::string>{"part.ngc"});
}

TEST(IsoDiagnostics, KeepsAtMostTheLimit)
{
    InterpretOptions options;
    options.maxDiagnostics = 2;
    const IsoRun r = run("E\nE\nE\nE\nE\nM2\n", options);
    EXPECT_EQ(r.result.diagnostics.size(), 2u);
    EXPECT_EQ(r.result.diagnosticsDropped, 3u);
}

TEST(IsoDiagnostics, HostileInputsEndQuickly)
{
    std::string deep(100000, '[');
    EXPECT_TRUE(run("G0 X" + deep + "\nM2\n").result.hasErrors());
    std::string minus(100000, '-');
    EXPECT_TRUE(run("G0 X" + minus + "1\nM2\n").result.hasErrors());
    std::string hashes(100000, '#');
    EXPECT_TRUE(run("G0 X" + hashes + "1\nM2\n").result.hasErrors());
    std::string digits(100000, '7');
    EXPECT_TRUE(run("G0 X" + digits + "\nM2\n").result.hasErrors());
    std::string binary;
    for (int i = 0; i < 4096; ++i)
        binary += static_cast<char>((i * 7919) & 0xff);
    EXPECT_TRUE(run(binary).result.hasErrors());
    EXPECT_TRUE(run(std::string("G0 X1\0Y2\nM2\n", 12)).result.hasErrors());
    EXPECT_FALSE(run("").result.hasErrors());
    InterpretOptions few;
    few.maxBlocks = 10000;
    EXPECT_TRUE(run("o1 while [1]\no1 endwhile\n", few).result.hasErrors());  // stops at maxBlocks
}

TEST(IsoDiagnostics, MalformedNumbersAreErrorsAndTheBlockDoesNotMove)
{
    // rs274: "bad number format (trailing characters) parsing '1.2.3'".
    const IsoRun r = run("G0 X0 Y0\nG0 X1.2.3 Y20\nG0 X1..2 Y30\nG0 XX5 Y40\nG0 X8 Y8\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:5: error: malformed number 1.2.3 after X\n"
                               "3:5: error: malformed number 1..2 after X\n"
                               "4:4: error: unknown word XX (a letter and a number expected)\n");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[1].to.x, 8);
}

TEST(IsoDiagnostics, M61NeedsAWholeToolNumber)
{
    // M61 sets the tool in the spindle without a change: Q must name one, as T does.
    const IsoRun r = run("M61 Q99999999999\nM61 Q2.5\nM61 Q-1\nM61 Q3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:5: error: M61 needs Q to be a tool number (a whole number >= 0)\n"
                               "2:5: error: M61 needs Q to be a tool number (a whole number >= 0)\n"
                               "3:5: error: M61 needs Q to be a tool number (a whole number >= 0)\n");
}

}  // namespace
}  // namespace camwb::nc::iso::test
