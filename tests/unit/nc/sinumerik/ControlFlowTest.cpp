// Control flow: IF/ELSE/ENDIF, WHILE, REPEAT/UNTIL, FOR, LOOP, GOTOF/GOTOB/GOTO with labels and
// block numbers, conditional jumps, nesting, and subprogram calls (PROC parameters, P repetitions,
// global R parameters, M17/RET, recursion limit).
#include "TestSupport.h"

namespace camwb::nc::sinumerik::test {
namespace {

std::vector<double> xs(const NcRun& r)
{
    std::vector<double> out;
    for (const auto& m : r.all<toolpath::Rapid>())
        out.push_back(m.to.x);
    return out;
}

TEST(SinumerikControlFlow, IfElse)
{
    const NcRun r = run("R1=2\nIF R1>1\nG0 X1\nELSE\nG0 X2\nENDIF\nIF(R1==5)\nG0 X3\nELSE\nG0 X4\nENDIF\n"
                        "IF R1<0\nG0 X5\nENDIF\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(xs(r), (std::vector<double>{1, 4}));
}

TEST(SinumerikControlFlow, WhileRepeatForLoop)
{
    const NcRun r = run("R1=0\nWHILE R1<3\nG0 X=R1\nR1=R1+1\nENDWHILE\n"
                        "REPEAT\nG0 X=10+R1\nR1=R1-1\nUNTIL R1<=1\n"
                        "FOR R2=1 TO 3\nG0 X=20+R2\nENDFOR\n"
                        "DEF INT CNT\nFOR CNT=5 TO 4\nG0 X=99\nENDFOR\n"
                        "LOOP\nR1=R1+1\nIF R1>2 GOTOF OUT\nG0 X=30+R1\nENDLOOP\nOUT:\nG0 X40\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(xs(r), (std::vector<double>{0, 1, 2, 13, 12, 21, 22, 23, 32, 40}));
    EXPECT_TRUE(r.result.completed);
}

TEST(SinumerikControlFlow, NestedLoops)
{
    const NcRun r = run("FOR R1=1 TO 2\nR2=0\nWHILE R2<2\nR2=R2+1\nIF R2==2\nG0 X=R1*10+R2\nENDIF\nENDWHILE\nENDFOR\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(xs(r), (std::vector<double>{12, 22}));
}

TEST(SinumerikControlFlow, GotoLabelsAndBlockNumbers)
{
    const NcRun r = run("N10 R1=0\nBACK: G0 X=R1\nN20 R1=R1+1\nIF R1<3 GOTOB BACK\nGOTOF N50\nG0 X99\nN50 G0 X50\n"
                        "GOTO END1\nG0 X98\nEND1: M30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(xs(r), (std::vector<double>{0, 1, 2, 50}));
}

TEST(SinumerikControlFlow, RepeatedLabelsJumpToTheNearestInTheDirection)
{
    const NcRun r = run("L: G0 X1\nL: G0 X2\nR1=R1+1\nIF R1<3 GOTOB L\nGOTOF L\nG0 X9\nL: G0 X3\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(xs(r), (std::vector<double>{1, 2, 2, 2, 3}));
    std::string many;
    for (int i = 0; i < 100000; ++i)
        many += "L:\n";
    InterpretOptions options;
    options.maxBlocks = 300000;
    const NcRun big = run(many + "R1=R1+1\nIF R1<50000 GOTOB L\nG0 X5\n", {}, options);
    EXPECT_EQ(big.errors(), 0) << big.diagnostics();
    EXPECT_EQ(xs(big), (std::vector<double>{5}));
}

TEST(SinumerikControlFlow, UnmatchedStructuresAndLabelsAreErrors)
{
    const NcRun r = run("IF R1==0\nG0 X1\nWHILE R1<1\nR1=1\nENDIF\nENDWHILE\nENDFOR\nGOTOF NOWHERE\nGOTOC NOWHERE2\n");
    EXPECT_NE(r.find("WHILE without ENDWHILE"), nullptr) << r.diagnostics();
    EXPECT_NE(r.find("ENDFOR without FOR"), nullptr);
    EXPECT_NE(r.find("undefined label NOWHERE"), nullptr);
    EXPECT_EQ(r.find("NOWHERE2"), nullptr);  // GOTOC: no alarm
    EXPECT_EQ(r.find("ENDWHILE without WHILE")->line, 6);
}

TEST(SinumerikControlFlow, SubprogramsWithParametersRepetitionsAndGlobals)
{
    const std::map<std::string, std::string> subs{
        {"SIDE", "PROC SIDE(REAL LEN, INT N)\nG91 G0 X=LEN\nG90\nR10=R10+N\nM17\n"},
        {"L12", "G0 Y=R10\nRET\n"},
    };
    const NcRun r = run("R10=0\nG0 X0 Y0 Z0\nSIDE(5, 2)\nSIDE(1.5, 1) \nL12 P3\nM30\n", subs);
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto rapids = r.all<toolpath::Rapid>();
    ASSERT_EQ(rapids.size(), 6u);
    EXPECT_DOUBLE_EQ(rapids[1].to.x, 5);
    EXPECT_DOUBLE_EQ(rapids[2].to.x, 6.5);
    EXPECT_DOUBLE_EQ(rapids[3].to.y, 3);  // R10 is global: 2 + 1
    EXPECT_EQ(r.result.files.size(), 3u);
    EXPECT_EQ(r.result.files[1], "SIDE.SPF");
    EXPECT_EQ(r.path.source(1).file, 1);  // the first rapid of SIDE
    EXPECT_EQ(r.path.source(1).line, 2);
}

TEST(SinumerikControlFlow, ModalSubprogramCallAndEnds)
{
    const std::map<std::string, std::string> subs{
        {"HOLE", "PROC HOLE\nG1 Z-1 F50\nG0 Z1\nM30\n"},
        {"L7", "G0 Y7\nM17\n"},
    };
    const NcRun r = run("G0 X0 Y0 Z1\nMCALL HOLE\nX10\nX20\nMCALL\nX30\nL7\nM2\nG0 X99\n", subs);
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_EQ(r.all<toolpath::Linear>().size(), 2u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>().back().to.y, 7);
    EXPECT_TRUE(r.result.completed);
}

TEST(SinumerikControlFlow, SetAlarmStops)
{
    const NcRun r = run("G0 X1\nIF R1==0\nSETAL(61000)\nENDIF\nG0 X2\n");
    const Diagnostic* d = r.find("alarm 61000");
    ASSERT_NE(d, nullptr) << r.diagnostics();
    EXPECT_EQ(d->line, 3);
    EXPECT_EQ(r.all<toolpath::Rapid>().size(), 1u);
    EXPECT_FALSE(r.result.completed);
}

// A cycle names the cause of its alarm with MSG before SETAL: the error carries that text, and
// MSG() (no text) clears it again.
TEST(SinumerikControlFlow, SetAlarmReportsTheMessage)
{
    const NcRun r = run("MSG(\"R9 must be > 0\")\nIF R9<=0\nSETAL(65001)\nM0\nENDIF\nG0 X2\n");
    ASSERT_EQ(r.errors(), 1) << r.diagnostics();
    const Diagnostic* d = r.find("alarm 65001 (SETAL): stopped: R9 must be > 0");
    ASSERT_NE(d, nullptr) << r.diagnostics();
    EXPECT_EQ(d->line, 3);
    EXPECT_TRUE(r.all<toolpath::Rapid>().empty());
    EXPECT_TRUE(r.all<toolpath::ProgramStop>().empty());  // stopped at SETAL, M0 not reached
    EXPECT_FALSE(r.result.completed);

    const NcRun cleared = run("MSG(\"old\")\nMSG()\nSETAL(65002)\n");
    const Diagnostic* e = cleared.find("alarm 65002");
    ASSERT_NE(e, nullptr) << cleared.diagnostics();
    EXPECT_EQ(e->message.find("old"), std::string::npos) << e->message;
}

TEST(SinumerikControlFlow, RecursionStopsAtSixteenLevels)
{
    const NcRun r = run("DEEP\nM30\n", {{"DEEP", "PROC DEEP\nR1=R1+1\nDEEP\nM17\n"}});
    const Diagnostic* d = r.find("nested deeper than 16");
    ASSERT_NE(d, nullptr) << r.diagnostics();
    EXPECT_TRUE(r.result.completed);
    EXPECT_EQ(r.errors(), 1);
}

TEST(SinumerikControlFlow, UndefinedSubprogramAndProcNameMismatch)
{
    const NcRun r = run("N10 NOSUCH\nOTHER\nM30\n", {{"OTHER", "PROC WRONG\nM17\n"}});
    const Diagnostic* undefined = r.find("undefined subprogram NOSUCH");
    ASSERT_NE(undefined, nullptr) << r.diagnostics();
    EXPECT_EQ(undefined->line, 1);
    EXPECT_EQ(undefined->column, 5);
    const Diagnostic* mismatch = r.find("PROC WRONG does not match the program name OTHER");
    ASSERT_NE(mismatch, nullptr);
    EXPECT_EQ(mismatch->file, "OTHER.SPF");
}

TEST(SinumerikControlFlow, RunawayLoopNamesItsLine)
{
    InterpretOptions options;
    options.maxBlocks = 1000;
    const NcRun r = run("R1=0\nN20 WHILE R1>=0\nR1=R1+1\nENDWHILE\nM30\n", {}, options);
    ASSERT_EQ(r.errors(), 1) << r.diagnostics();
    EXPECT_EQ(r.result.diagnostics[0].line, 2);
    EXPECT_NE(r.result.diagnostics[0].message.find("WHILE loop of line 2"), std::string::npos);
    EXPECT_FALSE(r.result.completed);
    const NcRun g = run("LBL: R1=R1+1\nGOTOB LBL\n", {}, options);
    EXPECT_NE(g.find("GOTOB loop of line 1"), nullptr) << g.diagnostics();
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
