// The program start: no axis is known until a block gives it in absolute terms, so the first
// moves carry only the axes they give, and a block that needs an unknown axis is an error. The
// block "n" of program() is on line n + 1.
#include "TestSupport.h"

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

TEST(HeidenhainStart, FirstMoveInZOnlyMovesZ)
{
    const Traced r = run(program("2 L Z+5 FMAX\n3 L X+10 Y+20 FMAX\n4 L X+11 Z-1 F100\n"), InterpretOptions{});
    EXPECT_EQ(r.count(Severity::Error), 0u);
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[0].axes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(rapids[0].to.z, 5);
    EXPECT_TRUE(rapids[1].axes.all());
    expectNear(rapids[1].to, {10, 20, 5});
    ASSERT_EQ(r.all<Linear>().size(), 1u);
    EXPECT_TRUE(r.all<Linear>()[0].axes.all());
    EXPECT_EQ(r.trace().substr(0, r.trace().find('\n')), "3 rapid z 5.0000 s 0.0000 t 1");
}

TEST(HeidenhainStart, FirstMoveGivingEveryAxisIsAFullMove)
{
    const Traced r = run(program("2 L X+1 Y+2 Z+3 FMAX\n"), InterpretOptions{});
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.all<Rapid>()[0].axes.all());
    EXPECT_EQ(r.trace(), "3 rapid 1.0000 2.0000 3.0000 s 0.0000 t 1\n");
}

TEST(HeidenhainStart, IncrementalMoveOnAnUnknownAxisIsAnError)
{
    const Traced r = run(program("2 L Z+5 FMAX\n3 L IX+2 IZ+1 FMAX\n4 L X+0 Y+0 FMAX\n"), InterpretOptions{});
    EXPECT_EQ(r.diagnostics(), (std::vector<std::string>{"4:3: error: X is unknown here: no absolute X has been "
                                                         "programmed yet, and an incremental move needs it; nothing "
                                                         "moves"}));
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 2u);  // the incremental block moved nothing
    expectNear(rapids[1].to, {0, 0, 5});
}

TEST(HeidenhainStart, CircleAndCycleCallBeforeXAndYAreKnownAreErrors)
{
    const Traced r = run(program("2 L Z+5 FMAX\n3 CC X+0 Y+0\n4 C X+10 Y+0 DR- F100\n"
                                 "5 CYCL DEF 200 DRILLING Q200=2 Q201=-7 Q206=100 Q202=2 Q203=0 Q204=10 Q211=0\n"
                                 "6 CYCL CALL\n7 CC\n"),
                         InterpretOptions{});
    EXPECT_TRUE(r.has(Severity::Error, 5, "X is unknown here")) << ::testing::PrintToString(r.diagnostics());
    EXPECT_TRUE(r.has(Severity::Error, 5, "the circle needs it"));
    EXPECT_TRUE(r.has(Severity::Error, 7, "the cycle call needs it"));
    EXPECT_TRUE(r.has(Severity::Error, 8, "the circle centre CC needs it"));
    EXPECT_EQ(r.count(Severity::Error), 3u);
    EXPECT_TRUE(r.all<Arc>().empty());
    EXPECT_TRUE(r.all<Cycle>().empty());
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
