// Canned cycles as Cycle records, one per hole: G98/G99, every kind, sticky words, L repeats
// under G91, and the refusals.
#include "IsoTestSupport.h"

#include "toolpath/CycleExpansion.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace camwb::nc::iso::test {
namespace {

using namespace camwb::toolpath;

TEST(IsoCycles, DrillWithG98ReturnsToTheStartHeight)
{
    const IsoRun r = run("G0 X0 Y0 Z50\nG98 G81 X10 Y10 Z-10 R2 F120\nX20\nG80\nG0 X0\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 2u);
    for (const Cycle& c : cycles) {
        EXPECT_EQ(c.kind, CycleKind::Drill);
        EXPECT_EQ(c.clearanceZ, 50);
        EXPECT_EQ(c.retractZ, 2);
        EXPECT_EQ(c.topZ, 2);
        EXPECT_EQ(c.bottomZ, -10);
        EXPECT_EQ(c.feedMmPerMin, 120);
        EXPECT_TRUE(c.returnToClearance);
        ASSERT_EQ(c.holes.size(), 1u);
    }
    EXPECT_EQ(cycles[0].holes[0], (Vec3{10, 10, 2}));
    EXPECT_EQ(cycles[1].holes[0], (Vec3{20, 10, 2}));
    EXPECT_EQ(r.all<Rapid>().back().to, (Vec3{0, 10, 50}));  // the cycle left the tool at Z50
    EXPECT_EQ(cycleReturnZ(cycles[0]), 50);
}

TEST(IsoCycles, G99ReturnsToR)
{
    const IsoRun r = run("G0 Z25\nG99 G82 X30 Y10 Z-4 R2 P0.5 F100\nX40\nG80\nG0 X0\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 2u);
    EXPECT_EQ(cycles[1].kind, CycleKind::DrillDwell);
    EXPECT_EQ(cycles[1].dwellSeconds, 0.5);
    EXPECT_EQ(cycles[1].clearanceZ, 25);  // the height before the cycle, for every hole
    EXPECT_FALSE(cycles[1].returnToClearance);
    EXPECT_EQ(r.all<Rapid>().back().to, (Vec3{0, 10, 2}));
}

TEST(IsoCycles, EveryKind)
{
    const IsoRun r = run("G0 Z20\nS500 M3\nG83 X1 Z-30 R3 Q6 F100\nG73 X2 Q4\nG84 X3 Z-12 R4 P0.2\nG85 X4 Z-15 R2\n"
                         "G89 X5 P1\nG86 X6 P0\nG80\nM2\n");
    EXPECT_EQ(r.diagnostics(), "8:0: warning: G86 (spindle stop, rapid out) is traced as a bore cycle with dwell\n");
    const auto c = r.all<Cycle>();
    ASSERT_EQ(c.size(), 6u);
    EXPECT_EQ(c[0].kind, CycleKind::Peck);
    EXPECT_EQ(c[0].peckMm, 6);
    EXPECT_EQ(c[0].bottomZ, -30);
    EXPECT_EQ(c[1].kind, CycleKind::ChipBreak);
    EXPECT_EQ(c[1].peckMm, 4);
    EXPECT_EQ(c[1].bottomZ, -30);  // Z and R kept from the cycle before
    EXPECT_EQ(c[1].retractZ, 3);
    EXPECT_EQ(c[2].kind, CycleKind::Tap);
    EXPECT_EQ(c[2].dwellSeconds, 0.2);
    EXPECT_EQ(c[3].kind, CycleKind::Bore);
    EXPECT_EQ(c[3].dwellSeconds, 0);
    EXPECT_EQ(c[4].kind, CycleKind::Bore);
    EXPECT_EQ(c[4].dwellSeconds, 1);
    EXPECT_EQ(c[5].kind, CycleKind::Bore);
}

TEST(IsoCycles, RepeatsUnderG91)
{
    const IsoRun r = run("G0 X0 Y0 Z10\nG91 G81 X10 Y5 Z-5 R-8 L3 F100\nG90 G80\nM2\n");
    EXPECT_EQ(r.diagnostics(), "");
    const auto c = r.all<Cycle>();
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0].retractZ, 2);  // R from the start Z
    EXPECT_EQ(c[0].bottomZ, -3);  // Z from R
    EXPECT_EQ(c[0].holes[0], (Vec3{10, 5, 2}));
    EXPECT_EQ(c[1].holes[0], (Vec3{20, 10, 2}));
    EXPECT_EQ(c[2].holes[0], (Vec3{30, 15, 2}));
    EXPECT_EQ(c[2].clearanceZ, 10);
}

TEST(IsoCycles, RepeatsUnderG90DrillTheSameHole)
{
    const IsoRun r = run("G0 Z10\nG81 X1 Y1 Z-1 R1 L2 F10\nG80\nM2\n");
    const auto c = r.all<Cycle>();
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].holes[0], c[1].holes[0]);
}

TEST(IsoCycles, InchCycles)
{
    const IsoRun r = run("G20 G0 Z1\nG81 X1 Y1 Z-0.5 R0.1 F10\nG80\nM2\n");
    const auto c = r.all<Cycle>();
    ASSERT_EQ(c.size(), 1u);
    EXPECT_DOUBLE_EQ(c[0].bottomZ, -12.7);
    EXPECT_DOUBLE_EQ(c[0].retractZ, 2.54);
    EXPECT_DOUBLE_EQ(c[0].feedMmPerMin, 254);
}

TEST(IsoCycles, Refusals)
{
    const IsoRun r = run("G0 Z10\nG81 X1 Y1 Z-1 F10\nG83 X1 Y1 Z-1 R2\nG81 X1 Y1 Z5 R2\nG18 G81 X1 Z-1 R2\n"
                         "G17 G41 G81 X1 Z-1 R2\nG40 G93 G81 X1 F1\nM2\n");
    EXPECT_EQ(r.diagnostics(), "2:0: error: G81 needs R (given once, then kept)\n"
                               "3:0: error: G83 needs Q > 0 (peck depth)\n"
                               "4:14: error: G81 R plane is below the bottom Z\n"
                               "5:0: error: G81 outside G17: only cycles along Z are traced\n"
                               "6:0: error: canned cycle with cutter compensation on (LinuxCNC refuses it)\n"
                               "7:0: error: G81 under G93 (inverse time): LinuxCNC refuses it\n");
    EXPECT_TRUE(r.all<Cycle>().empty());
}

TEST(IsoCycles, ExpansionFollowsLinuxCnc)
{
    // The hole at R, so expandCycleHole pecks from the R plane as LinuxCNC does.
    const IsoRun r = run("G0 Z20\nG83 X0 Y0 Z-10 R2 Q5 F100\nG80\nM2\n");
    const auto c = r.all<Cycle>();
    ASSERT_EQ(c.size(), 1u);
    const auto moves = expandCycleHole(c[0], c[0].holes[0], Vec3{0, 0, 20}, SpindleState{});
    std::vector<double> feedDepths;
    for (const Record& m : moves)
        if (const Linear* l = std::get_if<Linear>(&m))
            feedDepths.push_back(l->to.z);
    ASSERT_FALSE(feedDepths.empty());
    EXPECT_EQ(feedDepths.back(), -10);
    EXPECT_NE(std::find(feedDepths.begin(), feedDepths.end(), -3.0), feedDepths.end());  // R - Q
}

}  // namespace
}  // namespace camwb::nc::iso::test
