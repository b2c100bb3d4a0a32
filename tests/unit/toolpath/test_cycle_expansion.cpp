// Canned cycles expanded into the moves a control makes, as posts without native cycles write them
// and the backplot draws them.
#include "toolpath/CycleExpansion.h"
#include "toolpath/Toolpath.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

using namespace camwb::toolpath;

namespace {

std::string expanded(const Cycle& cycle, const Vec3& from, SpindleState spindle = {1000, true})
{
    Toolpath t;
    for (const Record& r : expandCycleHole(cycle, cycle.holes.front(), from, spindle))
        t.add(r);
    return traceOf(t);
}

Cycle cycleOf(CycleKind kind)
{
    Cycle c;
    c.kind = kind;
    c.clearanceZ = 25;
    c.retractZ = 2;
    c.topZ = 0;
    c.bottomZ = -10;
    c.peckMm = 4;
    c.feedMmPerMin = 120;
    c.holes = {{10, 10, 0}};
    return c;
}

}  // namespace

TEST(CycleExpansion, DrillRapidsOverTheHoleFeedsDownAndReturnsToClearance)
{
    EXPECT_EQ(expanded(cycleOf(CycleKind::Drill), {0, 0, 50}), "rapid 10.0000 10.0000 50.0000\n"
                                                               "rapid 10.0000 10.0000 2.0000\n"
                                                               "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                                                               "rapid 10.0000 10.0000 25.0000\n");
}

// A peck depth that would make millions of pecks (Q0.0000001 for Q1) is an error where the cycle
// comes from; expanded anyway (the backplot, the statistics) it makes no motion into the hole
// rather than filling the memory. The limit is on the pecks, not on the holes or the other kinds.
TEST(CycleExpansion, TooManyPecksMakeNoMotionIntoTheHole)
{
    Cycle c = cycleOf(CycleKind::Peck);
    EXPECT_FALSE(tooManyPecks(c));
    c.peckMm = 1e-7;
    const std::optional<std::string> why = tooManyPecks(c);
    ASSERT_TRUE(why);
    EXPECT_EQ(*why, "peck depth 0.0000001 mm makes 100000000 pecks over 10 mm, more than the 10000 a cycle may "
                    "make; use at least 0.001 mm");
    EXPECT_EQ(expanded(c, {10, 10, 25}), "rapid 10.0000 10.0000 2.0000\n"
                                         "rapid 10.0000 10.0000 25.0000\n");
    c.kind = CycleKind::ChipBreak;
    EXPECT_TRUE(tooManyPecks(c));
    c.peckMm = 0.002;
    EXPECT_FALSE(tooManyPecks(c));
    c.kind = CycleKind::Drill;
    c.peckMm = 1e-7;
    EXPECT_FALSE(tooManyPecks(c));
}

TEST(CycleExpansion, BelowTheRPlaneTheToolGoesUpFirst)
{
    Cycle c = cycleOf(CycleKind::DrillDwell);
    c.dwellSeconds = 0.5;
    c.returnToClearance = false;
    EXPECT_EQ(expanded(c, {0, 0, -5}), "rapid 0.0000 0.0000 2.0000\n"
                                       "rapid 10.0000 10.0000 2.0000\n"
                                       "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                                       "dwell 0.5000\n"
                                       "rapid 10.0000 10.0000 2.0000\n");
}

TEST(CycleExpansion, PeckRetractsFullyChipBreakLiftsALittle)
{
    EXPECT_EQ(expanded(cycleOf(CycleKind::Peck), {10, 10, 25}), "rapid 10.0000 10.0000 2.0000\n"
                                                                "linear 10.0000 10.0000 -4.0000 f 120.0000 plunge\n"
                                                                "rapid 10.0000 10.0000 2.0000\n"
                                                                "rapid 10.0000 10.0000 -3.5000\n"
                                                                "linear 10.0000 10.0000 -8.0000 f 120.0000 plunge\n"
                                                                "rapid 10.0000 10.0000 2.0000\n"
                                                                "rapid 10.0000 10.0000 -7.5000\n"
                                                                "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                                                                "rapid 10.0000 10.0000 25.0000\n");
    EXPECT_EQ(expanded(cycleOf(CycleKind::ChipBreak), {10, 10, 25}),
              "rapid 10.0000 10.0000 2.0000\n"
              "linear 10.0000 10.0000 -4.0000 f 120.0000 plunge\n"
              "rapid 10.0000 10.0000 -3.5000\n"
              "linear 10.0000 10.0000 -8.0000 f 120.0000 plunge\n"
              "rapid 10.0000 10.0000 -7.5000\n"
              "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
              "rapid 10.0000 10.0000 25.0000\n");
    Cycle noPeck = cycleOf(CycleKind::Peck);
    noPeck.peckMm = 0;  // would never reach the bottom: drilled in one go
    EXPECT_EQ(expanded(noPeck, {10, 10, 2}), "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                                             "rapid 10.0000 10.0000 25.0000\n");
}

TEST(CycleExpansion, TapReversesTheSpindleBoreFeedsOut)
{
    EXPECT_EQ(expanded(cycleOf(CycleKind::Tap), {10, 10, 25}, {800, true}),
              "rapid 10.0000 10.0000 2.0000\n"
              "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
              "spindle 800.0000 ccw\n"
              "linear 10.0000 10.0000 2.0000 f 120.0000 exit\n"
              "spindle 800.0000 cw\n"
              "rapid 10.0000 10.0000 25.0000\n");
    Cycle bore = cycleOf(CycleKind::Bore);
    bore.returnToClearance = false;
    EXPECT_EQ(expanded(bore, {10, 10, 25}), "rapid 10.0000 10.0000 2.0000\n"
                                            "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                                            "linear 10.0000 10.0000 2.0000 f 120.0000 exit\n");
}

TEST(CycleExpansion, ReturnPlaneIsNeverBelowR)
{
    Cycle c = cycleOf(CycleKind::Drill);
    EXPECT_EQ(cycleReturnZ(c), 25);
    c.returnToClearance = false;
    EXPECT_EQ(cycleReturnZ(c), 2);
    c.returnToClearance = true;
    c.clearanceZ = 1;  // a clearance plane below R: the tool still comes up to R
    EXPECT_EQ(cycleReturnZ(c), 2);
}

TEST(CycleExpansion, FromAPositionWhoseXYIsUnknown)
{
    // A CL that retracted in Z alone before the cycle: the climb to R moves Z alone and the
    // rapid over the hole is always written, since nothing says the tool is there already.
    const Cycle drill = cycleOf(CycleKind::Drill);
    KnownPosition low;
    low.moveTo(Rapid{{0, 0, -3}, AxisMask{AxisMask::kZ}});
    Toolpath t;
    for (const Record& r : expandCycleHole(drill, {10, 10, 0}, low, {}))
        t.add(r);
    EXPECT_EQ(traceOf(t), "rapid z 2.0000\n"
                          "rapid 10.0000 10.0000 2.0000\n"
                          "linear 10.0000 10.0000 -10.0000 f 120.0000 plunge\n"
                          "rapid 10.0000 10.0000 25.0000\n");
}
