// The round-trip comparison must see through what posts legitimately change (arcs split or
// linearised, cycles written natively) and catch what they must not (a point, feed, tool or order).
#include "MotionMatch.h"

#include <gtest/gtest.h>

#include <cmath>

namespace camwb::nc::test {
namespace {

using namespace camwb::toolpath;

Toolpath arcPath(double feed = 200)
{
    Toolpath p;
    p.add(ToolChange{Tool{1}});
    p.add(Spindle{3000, true});
    p.add(Rapid{{10, 0, 2}});
    p.add(Linear{{10, 0, 0}, 100});
    p.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, feed});
    return p;
}

TEST(MotionMatch, SameMotionMatches) { EXPECT_FALSE(matchMotion(arcPath(), arcPath())); }

TEST(MotionMatch, SplitArcMatches)
{
    Toolpath split = arcPath();
    Toolpath halves;
    for (std::size_t i = 0; i + 1 < split.size(); ++i)
        halves.add(split.record(i));
    halves.add(Arc{{0, 10, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 200});
    halves.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 200});
    EXPECT_FALSE(matchMotion(halves, arcPath()));
}

TEST(MotionMatch, LinearisedArcMatchesWithinItsTolerance)
{
    Toolpath lines;
    const Toolpath a = arcPath();
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
        lines.add(a.record(i));
    for (int k = 1; k <= 64; ++k) {
        const double t = M_PI * k / 64;
        lines.add(Linear{{10 * std::cos(t), 10 * std::sin(t), 0}, 200});
    }
    MatchTolerance tol;
    EXPECT_TRUE(matchMotion(lines, arcPath(), tol));  // chords stray 0.003 mm from the arc
    tol.pointMm = tol.backPointMm = 0.0035;
    EXPECT_FALSE(matchMotion(lines, arcPath(), tol));
}

TEST(MotionMatch, CatchesWrongPointFeedToolAndDirection)
{
    Toolpath moved = arcPath();
    Toolpath p;
    for (std::size_t i = 0; i + 1 < moved.size(); ++i)
        p.add(moved.record(i));
    p.add(Arc{{-10, 0, 0}, {0, 0, 0}, {0, 0, 1}, true, 0, 200});  // the other half circle
    const auto why = matchMotion(p, arcPath());
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("not on the rest"), std::string::npos) << *why;

    const auto feed = matchMotion(arcPath(250), arcPath());
    ASSERT_TRUE(feed);
    EXPECT_NE(feed->find("feed differs"), std::string::npos) << *feed;

    Toolpath otherTool = arcPath();
    Toolpath t;
    t.add(ToolChange{Tool{2}});
    for (std::size_t i = 1; i < otherTool.size(); ++i)
        t.add(otherTool.record(i));
    const auto tool = matchMotion(t, arcPath());
    ASSERT_TRUE(tool);
    EXPECT_NE(tool->find("tool differs"), std::string::npos) << *tool;
}

TEST(MotionMatch, NativeCycleMatchesItsMoves)
{
    Cycle c;
    c.kind = CycleKind::Drill;
    c.clearanceZ = 10;
    c.retractZ = 2;
    c.bottomZ = -5;
    c.feedMmPerMin = 80;
    c.holes = {{5, 5, 0}};
    Toolpath native;
    native.add(Linear{{0, 0, 10}, 500});
    native.add(c);
    Toolpath moves;
    moves.add(Linear{{0, 0, 10}, 500});
    moves.add(Rapid{{5, 5, 10}});
    moves.add(Rapid{{5, 5, 2}});
    moves.add(Linear{{5, 5, -5}, 80});
    moves.add(Rapid{{5, 5, 10}});
    EXPECT_FALSE(matchMotion(moves, native));
    // Extra positioning above the transit's lowest point is the post's business; going deeper is not.
    moves.add(Rapid{{5, 5, 12}});
    EXPECT_FALSE(matchMotion(moves, native));
    Toolpath deeper;
    deeper.add(Linear{{0, 0, 10}, 500});
    deeper.add(Rapid{{5, 5, 1}});
    deeper.add(Rapid{{5, 5, 2}});
    deeper.add(Linear{{5, 5, -5}, 80});
    deeper.add(Rapid{{5, 5, 10}});
    const auto why = matchMotion(deeper, native);
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("lowest rapid differs"), std::string::npos) << *why;
}

}  // namespace
}  // namespace camwb::nc::test
