// The axes an NC program has given, shared by the three interpreters: which one a block misses
// and the one wording of the error.
#include "nc/KnownAxes.h"

#include "kinematics/Machine.h"
#include "nc/Interpreter.h"

#include <gtest/gtest.h>

namespace camwb::nc {
namespace {

using toolpath::AxisMask;

TEST(KnownAxes, NothingIsKnownAtTheStart)
{
    const KnownAxes known;
    EXPECT_TRUE(known.mask().none());
    EXPECT_FALSE(known.complete());
    EXPECT_EQ(known.missing(axisBit(2)), 2);
    EXPECT_EQ(known.missing(kNoAxes), -1);
}

TEST(KnownAxes, AtTheStartTheCallersPositionOrALathesMissingY)
{
    InterpretOptions options;
    EXPECT_TRUE(knownAtStart(options).mask().none());
    kinematics::Machine mill;
    mill.axes = {{"X"}, {"Y"}, {"Z"}};
    options.machine = &mill;
    EXPECT_TRUE(knownAtStart(options).mask().none());
    kinematics::Machine lathe;
    lathe.axes = {{"X"}, {"Z"}};
    options.machine = &lathe;
    EXPECT_EQ(knownAtStart(options).mask(), AxisMask{AxisMask::kY});  // no Y axis: Y is 0
    kinematics::Machine unknown;                                      // no axes listed: nothing can be said
    options.machine = &unknown;
    EXPECT_TRUE(knownAtStart(options).mask().none());
    options.start = toolpath::Vec3{1, 2, 3};
    EXPECT_TRUE(knownAtStart(options).complete());
}

TEST(KnownAxes, BeforeMustBeKnownAfterMayBeGiven)
{
    KnownAxes known;
    known.give(axisBit(2));
    EXPECT_EQ(known.mask(), AxisMask{AxisMask::kZ});
    // An arc in G17: X and Y before the block, Z known or given.
    EXPECT_EQ(known.missing(planeMask(17), AxisMask{}, kXyAxes), 0);
    known.give(kXyAxes);
    EXPECT_TRUE(known.complete());
    EXPECT_EQ(known.missing(planeMask(17), AxisMask{}), -1);
    // A canned cycle: Z before, X and Y known or given.
    KnownAxes zOnly;
    zOnly.give(axisBit(2));
    EXPECT_EQ(zOnly.missing(axisBit(2), kXyAxes, kXyAxes), -1);
    EXPECT_EQ(zOnly.missing(axisBit(2), kXyAxes, axisBit(0)), 1);
    EXPECT_EQ(planeMask(18), axisBit(0) | axisBit(2));
    EXPECT_EQ(planeMask(19), axisBit(1) | axisBit(2));
}

TEST(KnownAxes, OneWordingForEveryDialect)
{
    EXPECT_EQ(unknownAxisMessage(1, "the arc"),
              "Y is unknown here: no absolute Y has been programmed yet, and the arc needs it; nothing moves");
}

}  // namespace
}  // namespace camwb::nc
