// Block numbers per dialect: analysis of single lines, find by number, renumber with its options
// and GOTO targets, removal.
#include "nc/tools/BlockNumbers.h"

#include <gtest/gtest.h>

#include <string>

using namespace camwb::nc;

TEST(BlockNumbers, AnalyzesSinumerikLines)
{
    LineInfo a = analyzeLine("N10 G1 X10", Dialect::Sinumerik);
    EXPECT_EQ(a.kind, LineKind::Block);
    ASSERT_TRUE(a.number);
    EXPECT_EQ(*a.number, 10);
    EXPECT_EQ(a.numberBegin, 0u);
    EXPECT_EQ(a.numberEnd, 3u);
    EXPECT_EQ(a.removeEnd, 4u);

    LineInfo skip = analyzeLine("/1 N20 G0 Z5", Dialect::Sinumerik);
    ASSERT_TRUE(skip.number);
    EXPECT_EQ(*skip.number, 20);
    EXPECT_EQ(skip.insertAt, 3u);

    EXPECT_EQ(analyzeLine("; only a comment", Dialect::Sinumerik).kind, LineKind::CommentOnly);
    EXPECT_EQ(analyzeLine("   ", Dialect::Sinumerik).kind, LineKind::Empty);
    EXPECT_EQ(analyzeLine("%_N_PART_MPF", Dialect::Sinumerik).kind, LineKind::Header);
    EXPECT_EQ(*analyzeLine(":100 G0 X0", Dialect::Sinumerik).number, 100);
    EXPECT_FALSE(analyzeLine("NOT_A_NUMBER=1", Dialect::Sinumerik).number);
    EXPECT_FALSE(analyzeLine("G1 X10 N20", Dialect::Sinumerik).number);  // only at the block start
    EXPECT_EQ(*analyzeLine("n5g0x1", Dialect::Iso).number, 5);
}

TEST(BlockNumbers, AnalyzesIsoAndHeidenhainLines)
{
    EXPECT_EQ(analyzeLine("(a comment) (another)", Dialect::Iso).kind, LineKind::CommentOnly);
    EXPECT_EQ(analyzeLine("O1234", Dialect::Iso).kind, LineKind::Header);
    EXPECT_EQ(analyzeLine("o100 sub", Dialect::Iso).kind, LineKind::Header);
    EXPECT_EQ(analyzeLine("(x) G0 X1", Dialect::Iso).kind, LineKind::Block);

    LineInfo begin = analyzeLine("0 BEGIN PGM TEST MM", Dialect::Heidenhain);
    ASSERT_TRUE(begin.number);
    EXPECT_EQ(*begin.number, 0);
    EXPECT_EQ(analyzeLine("12 ; comment", Dialect::Heidenhain).kind, LineKind::CommentOnly);
    EXPECT_EQ(analyzeLine("  Q200=2 ;SET-UP CLEARANCE ~", Dialect::Heidenhain, true).kind, LineKind::Header);
    EXPECT_FALSE(analyzeLine("L X+10 R0 FMAX", Dialect::Heidenhain).number);
}

TEST(BlockNumbers, FindsBlocks)
{
    const std::string sin = "; header\nN10 G0 X0\nN20 G1 X5 ; N30 in a comment\nN30 M30\n";
    EXPECT_EQ(findBlock(sin, Dialect::Sinumerik, 20), 3);
    EXPECT_EQ(findBlock(sin, Dialect::Sinumerik, 30), 4);
    EXPECT_FALSE(findBlock(sin, Dialect::Sinumerik, 40));
    const std::string hh = "0 BEGIN PGM A MM\n1 CYCL DEF 200 ~\n  2 ~\n  Q201=-5\n2 L Z+100 R0 FMAX\n3 END PGM A MM\n";
    EXPECT_EQ(findBlock(hh, Dialect::Heidenhain, 2), 5);  // the continuation "2 ~" is no block
    EXPECT_EQ(findBlock(hh, Dialect::Heidenhain, 0), 1);
}

TEST(BlockNumbers, RenumbersSinumerik)
{
    const std::string in = "%_N_A_MPF\r\n; start\r\nN5 G0 X0\r\n\r\nG1 X10 F100 ; N99 stays\r\n"
                           "MSG(\"N7 in a string\")\r\nM30";
    RenumberOptions options;
    options.start = 100;
    options.step = 5;
    const RenumberResult r = renumberBlocks(in, options);
    EXPECT_EQ(r.text, "%_N_A_MPF\r\n; start\r\nN100 G0 X0\r\n\r\nN105 G1 X10 F100 ; N99 stays\r\n"
                      "N110 MSG(\"N7 in a string\")\r\nN115 M30");
    EXPECT_EQ(r.report.linesNumbered, 4);

    options.numberCommentLines = true;
    options.numberEmptyLines = true;
    EXPECT_EQ(renumberBlocks("; a\n\nG0 X0\n", options).text, "N100 ; a\nN105\nN110 G0 X0\n");
}

TEST(BlockNumbers, KeepsExistingOrOnlyRenumbersNumbered)
{
    RenumberOptions keep;
    keep.replaceExisting = false;
    EXPECT_EQ(renumberBlocks("N7 G0\nG1 X1\n  G1 X2\n", keep).text, "N7 G0\nN10 G1 X1\n  N20 G1 X2\n");
    RenumberOptions only;
    only.onlyNumbered = true;
    only.start = 1;
    only.step = 1;
    EXPECT_EQ(renumberBlocks("N7 G0\nG1 X1\n/N9 G1 X2\n", only).text, "N1 G0\nG1 X1\n/N2 G1 X2\n");
}

TEST(BlockNumbers, RemapsGotoTargetsAndLeavesLabels)
{
    const std::string in = "N10 R1=0\n"
                           "N20 LOOP1: R1=R1+1\n"
                           "N30 IF R1<5 GOTOB N20\n"
                           "N40 GOTOF N60 ; GOTOF N40 in a comment\n"
                           "N50 GOTOF LOOP1\n"
                           "N60 GOTOF N999\n"
                           "N70 M30\n";
    RenumberOptions options;
    options.start = 1;
    options.step = 1;
    const RenumberResult r = renumberBlocks(in, options);
    EXPECT_EQ(r.text, "N1 R1=0\n"
                      "N2 LOOP1: R1=R1+1\n"
                      "N3 IF R1<5 GOTOB N2\n"
                      "N4 GOTOF N6 ; GOTOF N40 in a comment\n"
                      "N5 GOTOF LOOP1\n"
                      "N6 GOTOF N999\n"
                      "N7 M30\n");
    EXPECT_EQ(r.report.targetsRemapped, 2);
    ASSERT_EQ(r.report.notes.size(), 1u);
    EXPECT_EQ(r.report.notes[0].line, 6);
    EXPECT_NE(r.report.notes[0].message.find("N999"), std::string::npos);
}

TEST(BlockNumbers, RemapsBackwardJumpsToTheNearestBlock)
{
    const std::string in = "N10 G0\nN20 G1\nN10 G1\nN30 GOTOB N10\n";
    RenumberOptions options;
    const RenumberResult r = renumberBlocks(in, options);
    EXPECT_EQ(r.text, "N10 G0\nN20 G1\nN30 G1\nN40 GOTOB N30\n");
}

TEST(BlockNumbers, RemapsIsoMacroGoto)
{
    const std::string in = "O1000\nN1 #1=0\nN2 #1=#1+1\nIF[#1LT3]GOTO2\nGOTO 9\nN9 M30\n";
    RenumberOptions options;
    options.dialect = Dialect::Iso;
    const RenumberResult r = renumberBlocks(in, options);
    EXPECT_EQ(r.text, "O1000\nN10 #1=0\nN20 #1=#1+1\nN30 IF[#1LT3]GOTO20\nN40 GOTO 50\nN50 M30\n");
    EXPECT_EQ(r.report.targetsRemapped, 2);
}

TEST(BlockNumbers, RenumbersHeidenhainFromZero)
{
    const std::string in = "10 BEGIN PGM P MM\n"
                           "20 ; tool\n"
                           "TOOL CALL 1 Z S2000\n"
                           "30 CYCL DEF 200 DRILLING ~\n"
                           "  Q200=2 ;SET-UP CLEARANCE ~\n"
                           "  Q201=-20 ;DEPTH\n"
                           "40 END PGM P MM\n";
    RenumberOptions options;
    options.dialect = Dialect::Heidenhain;
    const RenumberResult r = renumberBlocks(in, options);
    EXPECT_EQ(r.text, "0 BEGIN PGM P MM\n"
                      "1 ; tool\n"
                      "2 TOOL CALL 1 Z S2000\n"
                      "3 CYCL DEF 200 DRILLING ~\n"
                      "  Q200=2 ;SET-UP CLEARANCE ~\n"
                      "  Q201=-20 ;DEPTH\n"
                      "4 END PGM P MM\n");
    EXPECT_FALSE(r.report.notes.empty());  // start 10 step 10 ignored, and said so

    const RenumberResult removed = removeBlockNumbers(in, Dialect::Heidenhain);
    EXPECT_EQ(removed.text, in);
    EXPECT_EQ(removed.report.notes.size(), 1u);
}

TEST(BlockNumbers, RemovesNumbersButKeepsJumpTargets)
{
    const std::string in = "N10 G0 X0\n/N20 G1 X1\nN30 GOTOB N10\nN40 M30 ; N50\n";
    const RenumberResult r = removeBlockNumbers(in, Dialect::Sinumerik);
    EXPECT_EQ(r.text, "N10 G0 X0\n/G1 X1\nGOTOB N10\nM30 ; N50\n");
    EXPECT_EQ(r.report.numbersRemoved, 3);
    EXPECT_EQ(r.report.notes.size(), 1u);
}

TEST(BlockNumbers, RenumbersAMillionLinesQuickly)
{
    std::string big;
    big.reserve(20'000'000);
    for (int i = 0; i < 1'000'000; ++i)
        big += "G1 X" + std::to_string(i % 100) + " Y1\n";
    RenumberOptions options;
    options.dialect = Dialect::Iso;
    const RenumberResult r = renumberBlocks(big, options);
    EXPECT_EQ(r.report.linesNumbered, 1'000'000);
    EXPECT_EQ(findBlock(r.text, Dialect::Iso, 10'000'000), 1'000'000);
}
