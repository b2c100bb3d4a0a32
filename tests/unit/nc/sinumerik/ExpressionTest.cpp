// Expressions: operators and their SINUMERIK priorities, functions in degrees, ROUNDUP, R
// parameters, DEF variables and arrays, errors for division by zero and square roots of negatives.
#include "TestSupport.h"

#include <cmath>

namespace camwb::nc::sinumerik::test {
namespace {

// The X of the only rapid of `assignments` followed by G0 X=R99.
double value(const std::string& expression)
{
    const NcRun r = run("R99=" + expression + "\nG0 X=R99\n");
    EXPECT_EQ(r.errors(), 0) << expression << '\n' << r.diagnostics();
    const auto rapids = r.all<toolpath::Rapid>();
    return rapids.empty() ? std::nan("") : rapids.back().to.x;
}

TEST(SinumerikExpression, ArithmeticAndPriorities)
{
    EXPECT_DOUBLE_EQ(value("1+2*3"), 7);
    EXPECT_DOUBLE_EQ(value("(1+2)*3"), 9);
    EXPECT_DOUBLE_EQ(value("10-4-3"), 3);
    EXPECT_DOUBLE_EQ(value("8/4/2"), 1);
    EXPECT_DOUBLE_EQ(value("-2*3"), -6);
    EXPECT_DOUBLE_EQ(value("-(2+3)"), -5);
    EXPECT_DOUBLE_EQ(value("7 MOD 3"), 1);
    EXPECT_DOUBLE_EQ(value("7 DIV 2"), 3);
    EXPECT_DOUBLE_EQ(value("2*-3"), -6);
    EXPECT_DOUBLE_EQ(value("1.5EX2"), 150);
}

TEST(SinumerikExpression, FunctionsInDegrees)
{
    EXPECT_NEAR(value("SIN(30)"), 0.5, 1e-12);
    EXPECT_NEAR(value("cos(60)"), 0.5, 1e-12);
    EXPECT_NEAR(value("TAN(45)"), 1, 1e-12);
    EXPECT_NEAR(value("ASIN(0.5)"), 30, 1e-12);
    EXPECT_NEAR(value("ACOS(0.5)"), 60, 1e-12);
    EXPECT_NEAR(value("ATAN2(1,1)"), 45, 1e-12);
    EXPECT_NEAR(value("ATAN2(1,-1)"), 135, 1e-12);
    EXPECT_DOUBLE_EQ(value("SQRT(16)"), 4);
    EXPECT_DOUBLE_EQ(value("ABS(-3)"), 3);
    EXPECT_DOUBLE_EQ(value("POT(3)"), 9);
    EXPECT_DOUBLE_EQ(value("ROUND(2.5)"), 3);
    EXPECT_DOUBLE_EQ(value("TRUNC(-2.7)"), -2);
    EXPECT_DOUBLE_EQ(value("MINVAL(2,3)+MAXVAL(2,3)"), 5);
}

TEST(SinumerikExpression, RoundUpIsTheCeilingAsInTheManualsExamples)
{
    EXPECT_DOUBLE_EQ(value("ROUNDUP(3.1)"), 4);
    EXPECT_DOUBLE_EQ(value("ROUNDUP(3.6)"), 4);
    EXPECT_DOUBLE_EQ(value("ROUNDUP(-3.1)"), -3);
    EXPECT_DOUBLE_EQ(value("ROUNDUP(-3.6)"), -3);
    EXPECT_DOUBLE_EQ(value("ROUNDUP(3.0)"), 3);
}

TEST(SinumerikExpression, ComparisonsAndLogicAreOneOrZero)
{
    EXPECT_DOUBLE_EQ(value("2==2"), 1);
    EXPECT_DOUBLE_EQ(value("2<>2"), 0);
    EXPECT_DOUBLE_EQ(value("1<2"), 1);
    EXPECT_DOUBLE_EQ(value("2<=2"), 1);
    EXPECT_DOUBLE_EQ(value("3>=4"), 0);
    EXPECT_DOUBLE_EQ(value("(1<2) AND (3>2)"), 1);
    EXPECT_DOUBLE_EQ(value("(1>2) OR (3>2)"), 1);
    EXPECT_DOUBLE_EQ(value("NOT (1>2)"), 1);
    EXPECT_DOUBLE_EQ(value("(1<2) XOR (3>2)"), 0);
    // Comparisons bind loosest: 1+1 == 2 compares the sums.
    EXPECT_DOUBLE_EQ(value("1+1==2"), 1);
}

TEST(SinumerikExpression, RParametersAreGlobalAndCaseInsensitive)
{
    const NcRun r = run("r1=2 R2=r1*3\nR[R1+1]=R[2]+1\ng0 x=R2 y=r3\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<toolpath::Rapid>().size(), 1u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.x, 6);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.y, 7);
}

TEST(SinumerikExpression, DefVariablesIntRoundsAndArrays)
{
    const NcRun r = run("DEF REAL LEN=1.5, SUM\nDEF INT CNT=2.6\nDEF REAL V[3]\nDEF BOOL OK=5\nV[2]=LEN*CNT\n"
                        "SUM=V[2]+OK\nG0 X=SUM Y=CNT Z=V[0]\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<toolpath::Rapid>().size(), 1u);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.x, 5.5);  // 1.5 * 3 + 1
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.y, 3);
    EXPECT_DOUBLE_EQ(r.all<toolpath::Rapid>()[0].to.z, 0);
}

TEST(SinumerikExpression, AddressLettersAreNoVariableNames)
{
    const NcRun r = run("DEF REAL A=1\nDEF INT N\n");
    ASSERT_EQ(r.errors(), 2) << r.diagnostics();
    EXPECT_EQ(r.result.diagnostics[0].column, 10);
}

TEST(SinumerikExpression, RuntimeErrorsAreReportedWithTheirColumn)
{
    const NcRun r = run("R1=0\nR2=10/R1\nR3=SQRT(-R2-1)\nR4=ACOS(2)\nDEF REAL V[2]\nV[5]=1\nG0 X=R2\n");
    const Diagnostic* div = r.find("division by zero");
    ASSERT_NE(div, nullptr) << r.diagnostics();
    EXPECT_EQ(div->line, 2);
    EXPECT_EQ(div->column, 6);
    const Diagnostic* sqrt = r.find("square root of a negative");
    ASSERT_NE(sqrt, nullptr);
    EXPECT_EQ(sqrt->line, 3);
    EXPECT_NE(r.find("ACOS"), nullptr);
    EXPECT_NE(r.find("array index out of range"), nullptr);
    EXPECT_EQ(r.all<toolpath::Rapid>().size(), 1u);  // the program goes on
}

TEST(SinumerikExpression, DeepNestingAndLongChainsAreErrorsNotCrashes)
{
    EXPECT_GT(run("R1=" + std::string(5000, '(') + "1" + std::string(5000, ')') + "\n").errors(), 0);
    EXPECT_GT(run("R1=" + std::string(100000, '-') + "1\n").errors(), 0);
    std::string chain = "R1=1";
    for (int i = 0; i < 50000; ++i)
        chain += "+1";
    EXPECT_GT(run(chain + "\n").errors(), 0);
    EXPECT_EQ(run("R1=((((((((((((((((((((1))))))))))))))))))))+2\n").errors(), 0);
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
