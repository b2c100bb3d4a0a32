// G2/G3: centre words in the three planes, absolute centres, R both ways, helices, P turns,
// full circles, inch arcs, and the radius checks.
#include "IsoTestSupport.h"

#include "../../../support/DecimalCommaLocale.h"

#include <gtest/gtest.h>

#include <cmath>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

void expectNear(const Vec3& a, const Vec3& b)
{
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(IsoArcs, CentreWordsInAllPlanes)
{
    const IsoRun r = run("G0 X10 Y0 Z0\nG3 X0 Y10 I-10 J0 F500\nG0 X0 Y0 Z-3\nG18 G2 Z7 I0 K5\nG19 G3 Y10 Z-3 J5 K-5\n"
                         "M2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 3u);
    expectNear(arcs[0].center, {0, 0, 0});
    expectNear(arcs[0].normal, {0, 0, 1});
    EXPECT_FALSE(arcs[0].clockwise);
    EXPECT_EQ(arcs[0].feedMmPerMin, 500);
    // G18: Z and X, K and I; clockwise seen from +Y.
    expectNear(arcs[1].to, {0, 0, 7});
    expectNear(arcs[1].center, {0, 0, 2});
    expectNear(arcs[1].normal, {0, 1, 0});
    EXPECT_TRUE(arcs[1].clockwise);
    // G19: Y and Z, J and K.
    expectNear(arcs[2].to, {0, 10, -3});
    expectNear(arcs[2].center, {0, 5, 2});
    expectNear(arcs[2].normal, {1, 0, 0});
    EXPECT_FALSE(arcs[2].clockwise);
}

TEST(IsoArcs, FullCircleHelixAndTurns)
{
    const IsoRun r = run("G0 X-10 Y0 Z0\nG3 I10 J0 F100\nG2 Z-1 I10 J0\nG2 Z-4 I10 P3\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 3u);
    expectNear(arcs[0].to, {-10, 0, 0});  // start = end: one whole circle
    EXPECT_EQ(arcs[0].turns, 0);
    expectNear(arcs[1].to, {-10, 0, -1});
    expectNear(arcs[1].center, {0, 0, 0});  // the centre at the start's height
    expectNear(arcs[2].center, {0, 0, -1});
    EXPECT_EQ(arcs[2].turns, 2);  // P3: three revolutions, two more than one
    EXPECT_NE(r.trace.find("3 helix cw -10.0000 0.0000 -1.0000"), std::string::npos) << r.trace;
}

TEST(IsoArcs, RadiusWordsBothSides)
{
    const IsoRun r = run("G2 X2 Y0 R1 F100\nG0 X0\nG2 X2 R[SQRT[2]]\nG0 X0\nG2 X2 R-[SQRT[2]]\nG0 X0\n"
                         "G3 X2 R[SQRT[2]]\nG0 X0\nG18 G2 X2 Z0 R[SQRT[2]]\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 5u);
    expectNear(arcs[0].center, {1, 0, 0});
    expectNear(arcs[1].center, {1, -1, 0});  // clockwise, at most 180 degrees: centre right of the chord
    expectNear(arcs[2].center, {1, 1, 0});   // negative R: the long way round
    expectNear(arcs[3].center, {1, 1, 0});   // counter-clockwise: left of the chord
    expectNear(arcs[4].center, {1, 0, 1});   // G18, seen from +Y: Z to the right, X up
}

TEST(IsoArcs, AbsoluteCentresWithG901)
{
    const IsoRun r = run("G0 X10 Y5\nG90.1 G3 X0 Y15 I0 J5 F100\nG91.1 G2 X10 Y5 I0 J-10\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    expectNear(arcs[0].center, {0, 5, 0});
    expectNear(arcs[1].center, {0, 5, 0});
}

TEST(IsoArcs, IncrementalAndInchArcs)
{
    const IsoRun r = run("G20 G0 X1\nG91 G3 X-1 Y1 I-1 J0 F10\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].to, {0, 25.4, 0});
    expectNear(arcs[0].center, {0, 0, 0});
    EXPECT_DOUBLE_EQ(arcs[0].feedMmPerMin, 254);
}

TEST(IsoArcs, RadiusMismatchIsAnErrorAtTheCentreWord)
{
    const IsoRun r = run("G0 X10\nG2 X0 Y10.1 I-10 J0 F100\nG2 X10 Y0.005 I0 J-10\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:13: error: G2 radius differs at start (10.0000) and end (10.1000) by more than "
                               "0.0100 mm\n");
    EXPECT_EQ(r.all<Arc>().size(), 2u);  // traced as written, so the plot shows where it goes wrong
}

TEST(IsoArcs, MessagesKeepTheDecimalPointInADecimalCommaLocale)
{
    // The GUI runs in the user's locale (Qt sets it); a message must read the same there.
    const std::string program = "G0 X10\nG2 X0 Y10.1 I-10 J0 F100\nG2 X10 Y0 R4\nM2\n";
    const std::string inC = run(program).diagnostics();
    EXPECT_NE(inC.find("(10.1000) by more than 0.0100 mm"), std::string::npos) << inC;
    camwb::test::DecimalCommaLocale comma;
    if (!comma.active())
        GTEST_SKIP() << comma.missing();
    EXPECT_EQ(run(program).diagnostics(), inC) << comma.name();
}

TEST(IsoArcs, ToleranceFromTheOptions)
{
    InterpretOptions options = fromOrigin();
    options.arcRadiusToleranceMm = 0.2;
    EXPECT_EQ(run("G0 X10\nG2 X0 Y10.1 I-10 J0 F100\nM2\n", options).diagnostics(), "");
}

TEST(IsoArcs, RadiusTooSmallForTheChord)
{
    const IsoRun r = run("G2 X10 Y0 R4 F100\nG2 X0 Y0 R4\nG2 X0 Y0 I1 R1\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:11: error: G2 radius 4.0000 is too small for the chord 10.0000 (at most 2R)\n"
                               "2:10: error: G2 with R cannot make a full circle: its start and end coincide\n"
                               "3:13: error: G2 with both R and centre words\n");
    EXPECT_TRUE(r.all<Arc>().empty());
}

TEST(IsoArcs, MissingCentreAndZeroRadius)
{
    const IsoRun r = run("G2 X10 F100\nG2 X10 I0 J0\nM2\n");
    EXPECT_EQ(r.diagnostics(), "1:0: error: G2 needs I or J (centre) or R in this plane\n"
                               "2:8: error: G2 with zero radius: the centre is the start point\n");
}

}  // namespace
}  // namespace camwb::nc::iso::test
