// O-word subroutines, loops and conditions, and the runaway limit.
#include "IsoTestSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

std::vector<double> xs(const IsoRun& r)
{
    std::vector<double> out;
    for (const Rapid& m : r.all<Rapid>())
        out.push_back(m.to.x);
    return out;
}

TEST(IsoControlFlow, SubroutineWithArgumentsAndReturnValue)
{
    const IsoRun r = run("o100 sub\nG0 X#1 Y#2\no100 endsub [#1+#2]\n#1=9\no100 call [3] [4]\nG0 X#1 Y#<_value>\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0].to, (Vec3{3, 4, 0}));
    EXPECT_EQ(r.path.source(0).line, 2);
    EXPECT_EQ(moves[1].to, (Vec3{9, 7, 0}));  // #1 restored after the call
}

TEST(IsoControlFlow, CallBeforeDefinitionAndNamedSubroutine)
{
    const IsoRun r = run("o<hole> call [5]\nM2\no<hole> sub\nG0 X#1\no<hole> return\nG0 X99\no<hole> endsub\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(xs(r), std::vector<double>{5});
}

TEST(IsoControlFlow, WhileDoRepeat)
{
    const IsoRun r = run("#1=0\no101 while [#1 LT 3]\nG0 X#1\n#1=[#1+1]\no101 endwhile\n"
                         "o102 do\nG0 X[10+#1]\n#1=[#1-1]\no102 while [#1 GT 0]\n"
                         "o103 repeat [2]\nG0 X20\no103 endrepeat\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(xs(r), (std::vector<double>{0, 1, 2, 13, 12, 11, 20, 20}));
}

TEST(IsoControlFlow, IfElseIfElse)
{
    const IsoRun r = run("#1=2\no1 if [#1 EQ 1]\nG0 X1\no1 elseif [#1 EQ 2]\nG0 X2\no1 elseif [1]\nG0 X3\no1 else\n"
                         "G0 X4\no1 endif\no2 if [0]\nG0 X5\no2 else\nG0 X6\no2 endif\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(xs(r), (std::vector<double>{2, 6}));
}

TEST(IsoControlFlow, BreakAndContinue)
{
    const IsoRun r = run("#1=0\no1 while [1]\n#1=[#1+1]\no2 if [#1 EQ 2]\no1 continue\no2 endif\no3 if [#1 GT 3]\n"
                         "o1 break\no3 endif\nG0 X#1\no1 endwhile\nG0 X100\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(xs(r), (std::vector<double>{1, 3, 100}));
}

TEST(IsoControlFlow, RunawayLoopStopsWithTheLine)
{
    InterpretOptions options;
    options.maxBlocks = 1000;
    const IsoRun r = run("G0 X1\no1 while [1]\nG91 X1\no1 endwhile\n", options);
    EXPECT_EQ(r.diagnostics(), "2:0: error: runaway program: more than 1000 blocks executed (an endless loop or "
                               "recursion?)\n");
    EXPECT_FALSE(r.result.completed);
}

TEST(IsoControlFlow, EndlessRecursionStops)
{
    const IsoRun r = run("o1 sub\no1 call\no1 endsub\no1 call\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:1: error: subroutine calls nested more than 100 deep (endless recursion?)\n");
    EXPECT_FALSE(r.result.completed);
}

TEST(IsoControlFlow, Mismatches)
{
    const IsoRun r = run("o1 endwhile\no2 call\no3 else\no4 if [1]\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:1: error: o1 endwhile without while\n"
                               "2:1: error: subroutine o2 is not defined\n"
                               "3:1: error: o3 else without if\n");
    const IsoRun unclosed = run("o5 while [0]\nG0 X1\n");
    EXPECT_EQ(unclosed.diagnostics(), "1:1: error: no matching end for o5 before the end of the program\n");
}

}  // namespace
}  // namespace camwb::nc::iso::test

namespace camwb::nc::iso::test {
namespace {

InterpretOptions withFiles()
{
    InterpretOptions options;
    options.fileName = "main.ngc";
    options.resolveProgram = [](std::string_view name) -> std::optional<ProgramSource> {
        if (name == "hole")
            return ProgramSource{"subs/hole.ngc", "%\n(drill one hole)\no<hole> sub\nG0 X#1 Y#2\nG1 Z-1 F100\n"
                                                  "G0 Z1 E\no<hole> endsub\n%\n"};
        return std::nullopt;
    };
    return options;
}

TEST(IsoControlFlow, SubroutineFromItsOwnFile)
{
    const IsoRun r = run("G0 Z1\no<hole> call [5] [6]\no<hole> call [7] [8]\no<nothing> call\nM2\n", withFiles());
    EXPECT_EQ(r.result.files, (std::vector<std::string>{"main.ngc", "subs/hole.ngc"}));
    ASSERT_EQ(r.result.diagnostics.size(), 3u);  // the file's error twice, then the missing subroutine
    EXPECT_EQ(formatDiagnostic(r.result.diagnostics[0]), "subs/hole.ngc:6:7: error: missing value after E");
    EXPECT_EQ(formatDiagnostic(r.result.diagnostics[2]), "main.ngc:4:1: error: subroutine onothing is not defined");
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    EXPECT_EQ(rapids[1].to, (Vec3{5, 6, 1}));
    EXPECT_EQ(rapids[2].to, (Vec3{7, 8, -1}));
    EXPECT_NE(r.trace.find("hole.ngc:4 rapid 5.0000 6.0000 1.0000"), std::string::npos) << r.trace;
    EXPECT_NE(r.trace.find("hole.ngc:5 linear 7.0000 8.0000 -1.0000"), std::string::npos) << r.trace;
}

}  // namespace
}  // namespace camwb::nc::iso::test
