// Reading lines: case, blanks anywhere, numbers in every spelling, comments, '%', '/' and N.
#include "IsoTestSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

TEST(IsoScanner, CaseAndBlanksAnywhere)
{
    const IsoRun r = run("g1x 1 0 . 5y-2f100\nG 0 1 X  11\n");
    EXPECT_EQ(r.diagnostics(), "2:0: warning: the program ends without M2, M30 or a closing '%'\n");
    const auto moves = r.all<Linear>();
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0].to, (Vec3{10.5, -2, 0}));
    EXPECT_EQ(moves[0].feedMmPerMin, 100);
    EXPECT_EQ(moves[1].to, (Vec3{11, -2, 0}));
}

TEST(IsoScanner, NumberSpellings)
{
    const IsoRun r = run("G0 X.5 Y-.25 Z+1.\nX1.123456789012345678901234 Y007 Z-0\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0].to, (Vec3{0.5, -0.25, 1}));
    EXPECT_DOUBLE_EQ(moves[1].to.x, 1.1234567890123457);
    EXPECT_EQ(moves[1].to.y, 7);
    EXPECT_EQ(moves[1].to.z, 0);
    EXPECT_EQ(0.1 + 0.2 == 0.30000000000000004, true);  // the double rules the parser must match
    const IsoRun exact = run("G0 X0.1 Y0.30000000000000004 Z123456.789\nM2\n");
    EXPECT_EQ(exact.all<Rapid>()[0].to, (Vec3{0.1, 0.30000000000000004, 123456.789}));
}

TEST(IsoScanner, CommentsBecomeRecordsSemicolonCommentsDoNot)
{
    const IsoRun r = run("(first) G0 X1 (second)\nG0 X2 ; X3 (not a record)\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto comments = r.all<Comment>();
    ASSERT_EQ(comments.size(), 2u);
    EXPECT_EQ(comments[0].text, "first");
    EXPECT_EQ(comments[1].text, "second");
    EXPECT_EQ(r.all<Rapid>().back().to.x, 2);
    // Comments come before the block's motion, with the block's line.
    EXPECT_TRUE(std::holds_alternative<Comment>(r.path.record(0)));
    EXPECT_EQ(r.path.source(0).line, 1);
}

TEST(IsoScanner, PercentDelimitsTheProgram)
{
    const IsoRun r = run("\n%\nG0 X1\n%\nG0 X2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_TRUE(r.result.completed);
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_EQ(r.path.source(0).line, 3);
}

TEST(IsoScanner, BlockDeleteRunsTheBlockAndNumbersAreIgnored)
{
    const IsoRun r = run("N10 G0 X1\n/N20 X2\n  / X3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 3u);
    EXPECT_EQ(moves[2].to.x, 3);
}

TEST(IsoScanner, CrLfLines)
{
    const IsoRun r = run("G0 X1\r\nG1 Y2 F50\r\nM2\r\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(r.all<Linear>().at(0).to, (Vec3{1, 2, 0}));
}

TEST(IsoScanner, SourceLinesOnEveryRecord)
{
    const IsoRun r = run("G21\n\nG0 X1\nS100 M3\nG1 X2 F10\nM2\n");
    ASSERT_EQ(r.path.size(), 4u);  // rapid, spindle, linear, spindle stop at M2
    EXPECT_EQ(r.path.source(0).line, 3);
    EXPECT_EQ(r.path.source(1).line, 4);
    EXPECT_EQ(r.path.source(2).line, 5);
    EXPECT_EQ(r.path.source(3).line, 6);
    EXPECT_EQ(r.path.source(3).file, 0);
}

}  // namespace
}  // namespace camwb::nc::iso::test

namespace camwb::nc::iso::test {
namespace {

// The eight-bytes-at-a-time digit reader against strtod, on numbers of every length and position
// (as feeds, which have no travel limit).
TEST(IsoScanner, NumbersMatchStrtod)
{
    std::string program = "G1 X0 F1\n";
    std::vector<double> expected{1};
    unsigned seed = 12345;
    const auto next = [&seed] { return seed = seed * 1103515245u + 12345u; };
    for (int i = 0; i < 3000; ++i) {
        const std::string digits = std::to_string(next()) + std::to_string(next());
        std::string number = digits.substr(0, 1 + next() % 12);
        if (next() % 3)
            number += "." + digits.substr(0, next() % 12);
        if (next() % 5 == 0)
            number = "." + std::to_string(next() % 1000);
        program += "X" + std::to_string(i % 2) + " F" + number + (next() % 2 ? " Y1\n" : "\n");
        expected.push_back(std::strtod(number.c_str(), nullptr));
    }
    program += "M2\n";
    const IsoRun r = run(program);
    ASSERT_TRUE(r.result.diagnostics.empty()) << r.result.diagnostics[0].message;
    const auto moves = r.all<toolpath::Linear>();
    ASSERT_EQ(moves.size(), expected.size());
    for (std::size_t i = 0; i < moves.size(); ++i)
        ASSERT_EQ(moves[i].feedMmPerMin, expected[i]) << i;
}

}  // namespace
}  // namespace camwb::nc::iso::test
