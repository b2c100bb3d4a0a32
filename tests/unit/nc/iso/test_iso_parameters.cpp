// Parameters and expressions: numbered, named local and global, assignments taking effect after
// the line, operator precedence, functions in degrees, and the errors.
#include "IsoTestSupport.h"

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

double xOf(const std::string& expression)
{
    const IsoRun r = run("G0 X" + expression + "\nM2\n");
    EXPECT_EQ(r.diagnostics(), "") << expression;
    const auto moves = r.all<Rapid>();
    return moves.empty() ? -12345 : moves[0].to.x;
}

TEST(IsoParameters, AssignmentsTakeEffectAfterTheLine)
{
    const IsoRun r = run("#1=5 #2=[#1+1]\nG0 X#1 Y#2\n#3 = 7 G0 Z#3\nG0 Z#3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto moves = r.all<Rapid>();
    ASSERT_EQ(moves.size(), 3u);
    EXPECT_EQ(moves[0].to, (Vec3{5, 1, 0}));  // #2 read #1 before the line set it
    EXPECT_EQ(moves[1].to.z, 0);
    EXPECT_EQ(moves[2].to.z, 7);
}

TEST(IsoParameters, NamedLocalAndGlobal)
{
    const IsoRun r = run("#<depth> = -3\n#<_Safe Height>=2\nG0 Z#<DEPTH> X#<_safeheight>\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(r.all<Rapid>().at(0).to, (Vec3{2, 0, -3}));
}

TEST(IsoParameters, IndirectAndComputedNumbers)
{
    const IsoRun r = run("#1=2 #2=30\n##1=4 #[10+5]=1.5\nG0 X#2 Y#15\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_EQ(r.all<Rapid>().at(0).to, (Vec3{4, 1.5, 0}));
}

TEST(IsoParameters, Precedence)
{
    EXPECT_EQ(xOf("[1+2*3]"), 7);
    EXPECT_EQ(xOf("[2**3**2]"), 64);  // left to right within a level
    EXPECT_EQ(xOf("[2*3**2]"), 18);
    EXPECT_EQ(xOf("[10-4-3]"), 3);
    EXPECT_EQ(xOf("[12/3/2]"), 2);
    EXPECT_EQ(xOf("[7 MOD 3]"), 1);
    EXPECT_EQ(xOf("[-7 MOD 3]"), 2);
    EXPECT_EQ(xOf("[1+1 EQ 2]"), 1);
    EXPECT_EQ(xOf("[2 GT 3 OR 1 LT 2]"), 1);
    EXPECT_EQ(xOf("[1 AND 0]"), 0);
    EXPECT_EQ(xOf("[1 XOR 1]"), 0);
    EXPECT_EQ(xOf("[3 NE 3]"), 0);
    EXPECT_EQ(xOf("[3 GE 3]"), 1);
    EXPECT_EQ(xOf("[3 LE 2]"), 0);
    EXPECT_EQ(xOf("-[1+1]"), -2);
    EXPECT_EQ(xOf("[ 1 + [ 2 ] ]"), 3);
}

TEST(IsoParameters, FunctionsInDegrees)
{
    EXPECT_NEAR(xOf("[SIN[30]]"), 0.5, 1e-12);
    EXPECT_NEAR(xOf("COS[60]"), 0.5, 1e-12);
    EXPECT_NEAR(xOf("[TAN[45]]"), 1, 1e-12);
    EXPECT_NEAR(xOf("[ATAN[1]/[1]]"), 45, 1e-12);
    EXPECT_NEAR(xOf("[ATAN[1]/[-1]]"), 135, 1e-12);
    EXPECT_NEAR(xOf("[ASIN[1]]"), 90, 1e-12);
    EXPECT_NEAR(xOf("[ACOS[0]]"), 90, 1e-12);
    EXPECT_EQ(xOf("[SQRT[16]]"), 4);
    EXPECT_EQ(xOf("[ABS[-3]]"), 3);
    EXPECT_EQ(xOf("[ROUND[2.5]]"), 3);
    EXPECT_EQ(xOf("[ROUND[-2.5]]"), -3);
    EXPECT_EQ(xOf("[FIX[-2.5]]"), -3);
    EXPECT_EQ(xOf("[FUP[2.1]]"), 3);
    EXPECT_EQ(xOf("[EXP[0]]"), 1);
    EXPECT_EQ(xOf("[LN[1]]"), 0);
    EXPECT_EQ(xOf("[EXISTS[#<nothing>]]"), 0);
}

TEST(IsoParameters, Errors)
{
    const IsoRun r = run("G0 X[1/0]\nG0 X#<nowhere>\n#6000=1\nG0 X[SQRT[-1]]\nG0 X[1 MOD 0]\nG0 X[LN[0]]\n"
                         "G0 X[ASIN[2]]\n#1 X5\nG0 X[(-2)**0.5]\nG0 X[10**400]\nG0 X[[-2]**0.5]\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:7: error: division by zero\n"
                               "2:5: error: parameter #<nowhere> is not defined\n"
                               "3:2: error: parameter number out of range (0..5399)\n"
                               "4:6: error: SQRT of a negative value\n"
                               "5:8: error: division by zero\n"
                               "6:6: error: LN of a value that is not positive\n"
                               "7:6: error: ASIN of a value outside -1..1\n"
                               "8:4: error: expected '=' after the parameter\n"
                               "9:6: error: expected a value\n"
                               "10:8: error: the result is not a finite number\n"
                               "11:10: error: negative number to a non-integer power\n");
    EXPECT_TRUE(r.all<Rapid>().empty());
}

}  // namespace
}  // namespace camwb::nc::iso::test
