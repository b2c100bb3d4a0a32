// Which feed each pocket move says it uses: down from the safe height and plunge entries (Plunge),
// the helix and ramp down to each level (Entry), clearing and links (Cutting), the wall finishing
// pass and the floor's own level (Finishing).
#include "PocketTestSupport.h"

#include "../support/FeedKinds.h"
#include "toolpath/ArcGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace camwb;
using namespace camwb::ops::pocket::test;
using ops::test::expectFeedKindsAgreeWithSections;
using toolpath::FeedKind;

namespace {

struct FeedMove {
    std::size_t record = 0;
    Vec3 from, to;
    bool arc = false;
    double length = 0;
    FeedKind kind = FeedKind::Unspecified;
};

std::vector<FeedMove> feedMoves(const toolpath::Toolpath& tp)
{
    std::vector<FeedMove> out;
    Vec3 at;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const toolpath::Record& r = tp.record(i);
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            at = rapid->to;
        } else if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            out.push_back({i, at, l->to, false, distance(at, l->to), l->feedKind});
            at = l->to;
        } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            out.push_back({i, at, a->to, true, toolpath::arcLength(at, *a), a->feedKind});
            at = a->to;
        }
    }
    return out;
}

// Straight down is Plunge, down while moving in XY Entry, level moves Cutting or Finishing.
void expectKindsFollowTheMoves(const std::vector<FeedMove>& moves)
{
    for (const FeedMove& m : moves) {
        const bool down = m.to.z < m.from.z - 1e-9;
        const bool inXY = m.arc || distance(m.from.xy(), m.to.xy()) > 1e-9;
        if (down && !inXY)
            EXPECT_EQ(m.kind, FeedKind::Plunge) << "record " << m.record;
        else if (down)
            EXPECT_EQ(m.kind, FeedKind::Entry) << "record " << m.record;
        else
            EXPECT_TRUE(m.kind == FeedKind::Cutting || m.kind == FeedKind::Finishing) << "record " << m.record;
    }
}

// Length of the moves of `kind` per level (Z of their end).
std::map<double, double> lengthByLevel(const std::vector<FeedMove>& moves, FeedKind kind)
{
    std::map<double, double> out;
    for (const FeedMove& m : moves)
        if (m.kind == kind)
            out[m.to.z] += m.length;
    return out;
}

}  // namespace

TEST(PocketFeedKinds, HelixEntriesArePlungeThenEntryAndClearingCuts)
{
    auto p = baseParams();  // offset pattern, helix entry, two levels
    auto result = ops::computePocket({rectRegion(0, 0, 40, 30)}, p, toolOf(8), 0);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const toolpath::Toolpath& tp = result->toolpath;
    expectFeedKindsAgreeWithSections(tp);
    const std::vector<FeedMove> moves = feedMoves(tp);
    expectKindsFollowTheMoves(moves);
    ASSERT_FALSE(moves.empty());
    EXPECT_EQ(moves.front().kind, FeedKind::Plunge);  // safe height down to the top
    int helixArcs = 0;
    for (const FeedMove& m : moves)
        helixArcs += m.kind == FeedKind::Entry && m.arc;
    EXPECT_GT(helixArcs, 0);
    EXPECT_TRUE(lengthByLevel(moves, FeedKind::Finishing).empty());
    EXPECT_GT(lengthByLevel(moves, FeedKind::Cutting)[-4], 0);
}

TEST(PocketFeedKinds, RampEntriesAreEntryPlungeEntriesArePlunge)
{
    auto p = baseParams();
    p.pattern = ops::PocketPattern::ZigZag;
    p.entry = ops::EntryKind::Ramp;
    auto ramped = ops::computePocket({rectRegion(0, 0, 40, 30)}, p, toolOf(6), 0);
    ASSERT_TRUE(ramped.ok()) << ramped.error().message;
    expectFeedKindsAgreeWithSections(ramped->toolpath);
    const std::vector<FeedMove> rampMoves = feedMoves(ramped->toolpath);
    expectKindsFollowTheMoves(rampMoves);
    EXPECT_GT(
        std::count_if(rampMoves.begin(), rampMoves.end(), [](const FeedMove& m) { return m.kind == FeedKind::Entry; }),
        0);

    p.entry = ops::EntryKind::Plunge;
    auto plunged = ops::computePocket({rectRegion(0, 0, 40, 30)}, p, toolOf(6), 0);
    ASSERT_TRUE(plunged.ok()) << plunged.error().message;
    expectFeedKindsAgreeWithSections(plunged->toolpath);
    const std::vector<FeedMove> plungeMoves = feedMoves(plunged->toolpath);
    expectKindsFollowTheMoves(plungeMoves);
    EXPECT_EQ(std::count_if(plungeMoves.begin(), plungeMoves.end(),
                            [](const FeedMove& m) { return m.kind == FeedKind::Entry; }),
              0);
}

TEST(PocketFeedKinds, TheWallPassAndTheFloorLevelAreFinishing)
{
    auto p = baseParams();
    p.entry = ops::EntryKind::Plunge;
    p.heights = {20, 3, 0, -3};
    p.stepDownMm = 1.5;
    p.wallStockMm = 0.3;
    p.finishWalls = true;
    auto walls = ops::computePocket({rectRegion(0, 0, 30, 20)}, p, toolOf(5), 0);
    ASSERT_TRUE(walls.ok()) << walls.error().message;
    expectFeedKindsAgreeWithSections(walls->toolpath);
    const std::vector<FeedMove> wallMoves = feedMoves(walls->toolpath);
    expectKindsFollowTheMoves(wallMoves);
    // At each level one loop round the tool-centre rectangle at zero stock: 25 x 15 mm (its
    // corners rounded within the offset's tolerance), the same at both levels.
    const std::map<double, double> finished = lengthByLevel(wallMoves, FeedKind::Finishing);
    ASSERT_EQ(finished.size(), 2u);
    for (const auto& [z, length] : finished)
        EXPECT_NEAR(length, 80, 0.2) << "level " << z;
    EXPECT_NEAR(finished.begin()->second, finished.rbegin()->second, 1e-9);

    p.finishWalls = false;
    p.floorStockMm = 0.2;
    p.finishFloor = true;
    auto floor = ops::computePocket({rectRegion(0, 0, 30, 20)}, p, toolOf(5), 0);
    ASSERT_TRUE(floor.ok()) << floor.error().message;
    expectFeedKindsAgreeWithSections(floor->toolpath);
    const std::vector<FeedMove> floorMoves = feedMoves(floor->toolpath);
    expectKindsFollowTheMoves(floorMoves);
    // Only the floor's own level finishes, and there every move along the pattern does.
    const std::map<double, double> floorFinished = lengthByLevel(floorMoves, FeedKind::Finishing);
    ASSERT_EQ(floorFinished.size(), 1u);
    EXPECT_EQ(floorFinished.begin()->first, -3);
    // The links between cuts at that level stay Cutting: much shorter than the pattern itself.
    std::map<double, double> floorCut = lengthByLevel(floorMoves, FeedKind::Cutting);
    EXPECT_GT(floorFinished.begin()->second, 2 * floorCut[-3]);
    EXPECT_GT(floorFinished.begin()->second, 0.5 * floorCut[-2.8]);
}
