// Program structure of Klartext: comments and structure items as Comment records, BLK FORM,
// TOOL CALL variants (number, name, Q parameter, speed only, F AUTO), STOP and M0/M1, the header
// forms of the iTNC 530 post, source lines through continuations, lone CR line ends.
#include "TestSupport.h"

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

TEST(HeidenhainBlocks, CommentsAndStructureItems)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 ;STROJ: MCVL1000\n2 ;\n3 * - ROUGHING 1\n"
                         "4 L X+1 FMAX ;inline\n5 BLK FORM 0.1 Z X+0 Y+0 Z-20\n6 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto comments = r.all<Comment>();
    ASSERT_EQ(comments.size(), 3u);
    EXPECT_EQ(comments[0].text, "STROJ: MCVL1000");
    EXPECT_EQ(comments[1].text, "ROUGHING 1");
    EXPECT_EQ(comments[2].text, "inline");
    EXPECT_EQ(r.lines<Comment>(), (std::vector<int>{2, 4, 5}));
}

TEST(HeidenhainBlocks, ToolCallVariants)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 Q7 = 12\n"
                         "2 TOOL CALL 3 Z S1000 F250 DL+0.1 DR-0.05\n"
                         "3 L X+1 F AUTO M3\n"
                         "4 TOOL CALL S2000\n"
                         "5 TOOL CALL Q7 Z S500\n"
                         "6 TOOL CALL \"MILL_D10\" Z S800\n"
                         "7 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto tools = r.all<ToolChange>();
    ASSERT_EQ(tools.size(), 3u);
    EXPECT_EQ(tools[0].tool.number, 3);
    EXPECT_EQ(tools[1].tool.number, 12);
    EXPECT_EQ(tools[2].tool.name, "MILL_D10");
    EXPECT_EQ(r.all<Linear>()[0].feedMmPerMin, 250);
    const auto spindles = r.all<Spindle>();
    // M3 at 1000, the speed change while running, then the stops at each tool change.
    ASSERT_EQ(spindles.size(), 3u);
    EXPECT_EQ(spindles[0].rpm, 1000);
    EXPECT_EQ(spindles[1].rpm, 2000);
    EXPECT_EQ(spindles[2].rpm, 0);
}

TEST(HeidenhainBlocks, StopsAndOptionalStops)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S100\n2 L X+1 FMAX M3 M8\n3 STOP\n"
                         "4 L M1\n5 L X+2 FMAX M0\n6 END PGM T MM\n");
    const auto stops = r.all<ProgramStop>();
    ASSERT_EQ(stops.size(), 3u);
    EXPECT_FALSE(stops[0].optional);
    EXPECT_TRUE(stops[1].optional);
    EXPECT_EQ(r.lines<ProgramStop>(), (std::vector<int>{4, 5, 6}));
    // M0 also stops the spindle and the coolant, after the move.
    EXPECT_EQ(r.all<Spindle>().back().rpm, 0);
    EXPECT_EQ(r.all<Coolant>().back().mode, CoolantMode::Off);
}

TEST(HeidenhainBlocks, HeaderFormsOfThePost)
{
    // BLK FORM, M135 M126 (M functions the trace has no record for), coolant in a block of its own.
    const Traced r = run("0 BEGIN PGM NAME MM\n1 BLK FORM 0.1 Z X-75 Y-75 Z+85\n2 BLK FORM 0.2 X+75 Y+75 Z+105\n"
                         "3 M135 M126\n4 TOOL CALL 1 Z S3500\n5 L Z+150 R0 FMAX\n6 L X+1.5 Y-2 R0 FMAX M3\n"
                         "7 L M8\n8 L M30\n9 END PGM NAME MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    ASSERT_EQ(r.all<Rapid>().size(), 2u);
    expectNear(r.all<Rapid>()[1].to, {1.5, -2, 150});
    ASSERT_FALSE(r.all<Coolant>().empty());
    EXPECT_EQ(r.all<Coolant>().front().mode, CoolantMode::Flood);
    EXPECT_EQ(r.lines<Coolant>().front(), 8);
    EXPECT_TRUE(r.result.completed);
}

// M136: F per spindle revolution until M137 (the iTNC post writes it for per-revolution CL feeds).
TEST(HeidenhainBlocks, M136FeedsPerRevolution)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 L Z+5 R0 FMAX\n2 L M136\n3 L Z-1 F0.1\n4 L M137\n5 L Z+5 F200\n"
                         "6 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto modes = r.all<FeedModeChange>();
    ASSERT_EQ(modes.size(), 2u);
    EXPECT_EQ(modes[0].mode, FeedMode::PerRevolution);
    EXPECT_EQ(modes[1].mode, FeedMode::PerMinute);
    ASSERT_EQ(r.all<Linear>().size(), 2u);
    EXPECT_DOUBLE_EQ(r.all<Linear>()[0].feedMmPerMin, 0.1);
    EXPECT_DOUBLE_EQ(r.all<Linear>()[1].feedMmPerMin, 200);
}

TEST(HeidenhainBlocks, LoneCarriageReturnsAndUnnumberedBlocks)
{
    const Traced r = run("BEGIN PGM T MM\rL X+1 FMAX\rL X+2 FMAX\rEND PGM T MM\r");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    EXPECT_EQ(r.lines<Rapid>(), (std::vector<int>{2, 3}));
}

TEST(HeidenhainBlocks, ProgramEndStopsBeforeSubprograms)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 L X+1 FMAX\n2 L M2\n3 LBL 1\n4 L X+9 FMAX\n5 LBL 0\n"
                         "6 END PGM T MM\n");
    EXPECT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_TRUE(r.result.completed);
    EXPECT_EQ(r.result.blocksExecuted, 3);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
