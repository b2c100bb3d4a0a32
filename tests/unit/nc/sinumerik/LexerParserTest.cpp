// Lexer and block parser: columns, block numbers and labels, case, comments, printed line wraps,
// line ends, and the seed-004 SINUMERIK listings.
#include "TestSupport.h"

#include "nc/sinumerik/Lexer.h"
#include "nc/sinumerik/Program.h"

namespace camwb::nc::sinumerik::test {
namespace {

TEST(SinumerikLexer, TokensWithColumns)
{
    std::vector<Token> tokens;
    lexLine("N10 G1 X10.5 Y=-R1*2 ; feed <>", 7, tokens);
    ASSERT_EQ(tokens.size(), 10u);
    EXPECT_EQ(tokens[0].text, "N10");
    EXPECT_EQ(tokens[2].text, "X10.5");
    EXPECT_EQ(tokens[2].column, 8);
    EXPECT_EQ(tokens[3].text, "Y");
    EXPECT_EQ(tokens[4].kind, Tok::Assign);
    EXPECT_EQ(tokens[5].kind, Tok::Minus);
    EXPECT_EQ(tokens[9].kind, Tok::Comment);
    EXPECT_EQ(tokens[9].text, " feed <>");
    EXPECT_EQ(tokens[9].line, 7);
    tokens.clear();
    lexLine("IF R1<>2 AND R2>=.5", 1, tokens);
    EXPECT_EQ(tokens[2].kind, Tok::Ne);
    EXPECT_EQ(tokens[6].kind, Tok::Ge);
    EXPECT_DOUBLE_EQ(tokens[7].number, 0.5);
}

TEST(SinumerikLexer, LineEnds)
{
    LineSplitter lines("a\r\nb\rc\n\nd");
    std::vector<std::string> out;
    std::string_view line;
    while (lines.next(line))
        out.emplace_back(line);
    EXPECT_EQ(out, (std::vector<std::string>{"a", "b", "c", "", "d"}));
}

TEST(SinumerikParser, BlocksLabelsAndFlow)
{
    const Program p =
        parseProgram("T.MPF", "N10 G0 X1\nSTART: N20 G1 X2 F1\n; note\nIF R1>0\nELSE\nENDIF\nGOTOB START\n");
    EXPECT_TRUE(p.diagnostics.empty());
    ASSERT_EQ(p.blocks.size(), 7u);
    EXPECT_EQ(p.labels.at("START"), std::vector<std::int32_t>{1});
    EXPECT_EQ(p.blockNumbers.size(), 2u);
    EXPECT_EQ(p.blocks[3].kind, BlockKind::If);
    EXPECT_EQ(p.blocks[3].jump, 4);
    EXPECT_EQ(p.blocks[4].jump, 5);
    EXPECT_EQ(p.blocks[2].kind, BlockKind::Empty);
    EXPECT_EQ(p.texts[static_cast<std::size_t>(p.blocks[2].comment)], " note");
}

TEST(SinumerikParser, PrintedLineWrapsJoinWithAWarning)
{
    const Program p = parseProgram("T.MPF", "R1=1+\n+2*(3+\n\n+4)\nR2=5 AND\n(6)\nG0 X1\n");
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blocks[0].line, 1);
    ASSERT_EQ(p.diagnostics.size(), 3u);
    EXPECT_EQ(p.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(p.diagnostics[0].line, 2);
    const NcRun r = run("R1=1+\n+2*(3+\n\n+4)\nG0 X=R1\n");
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.x, 15);
}

TEST(SinumerikParser, CaseInsensitiveAndGluedWords)
{
    const NcRun r = run("n10 g1x10y20z-5f100\nif r1==0\ng0 x=cos(0)\nendif\nm30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<toolpath::Linear>().size(), 1u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Linear>()[0].to.y, 20);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Linear>()[0].to.z, -5);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.x, 1);
}

TEST(SinumerikParser, CutListingsWarnOnly)
{
    const NcRun r = run("G0 X1\n...\nG1 X2 F10 ...\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(r.warnings(), 2);
}

// seed-004 Tab. 12: the two columns (planar and helical arcs of the thesis job), each after the
// position the job reaches before them.
TEST(SinumerikParser, Seed004Table12Arcs)
{
    const NcRun planar = run("G0 X18.851 Y4.539 Z12.5\nG1 F200\n"
                             "N230 G2 X46.211 Y66.477 I26.149 J25.461\nN240 X81.477 Y28.789 I-1.211 J-36.477\n"
                             "N250 X43.789 Y-6.477 I-36.477 J1.211\nN260 X18.851 Y4.539 I1.211 J36.477\n");
    EXPECT_EQ(planar.errors(), 0) << planar.diagnostics();
    EXPECT_EQ(planar.all<toolpath::Arc>().size(), 4u);
    const NcRun helical = run("G0 X49 Y30 Z15\nG1 F200\n"
                              "N1060 G2 X41.000 Y30.000 Z14.583 I-4.000 J0.000\nN1070 X49.000 Y30.000 Z14.167 I4.000 "
                              "J0.000\nN1080 X41.000 Y30.000 Z13.750 I-4.000 J0.000\nN1090 X49.000 Y30.000 Z13.333 "
                              "I4.000 J0.000\n");
    EXPECT_EQ(helical.errors(), 0) << helical.diagnostics();
    EXPECT_EQ(helical.all<toolpath::Arc>().size(), 4u);
    // The form the 828D refused (no Y in a helical block) is fine here: Y is modal.
    const NcRun derived = run("G0 X49 Y30 Z15\nG1 F200\nN1060 G2 X41.000 Z14.583 I-4.000 J0.000\n"
                              "N1070 X49.000 Z14.167 I4.000 J0.000\n");
    EXPECT_EQ(derived.errors(), 0) << derived.diagnostics();
}

TEST(SinumerikParser, Seed004Table12AsPrinted)
{
    // As printed: a heading line and two blocks per line separated by a tab. Not a program: the
    // heading and the second block of each line are errors, not crashes.
    const NcRun r = run("Kruhová interpolace v rovině\tKruhová interpolace v prostoru\n"
                        "N230 G2 X46.211 Y66.477 I26.149 J25.461\tN1060 G2 X41.000 Y30.000 Z14.583 I-4.000 J0.000\n");
    EXPECT_GT(r.errors(), 0);
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
