// Program statistics: extents, lengths and the time estimate for each feed mode, arcs with their
// bulges, cycles expanded, dwells, per-tool totals and the rapid rate the caller gives.
#include "toolpath/ProgramStats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace camwb::toolpath;
namespace tp = camwb::toolpath;
using camwb::base::Vec3;

TEST(ProgramStats, LinesAndRapids)
{
    tp::Toolpath p;
    p.add(tp::ToolChange{{3}});
    p.add(tp::Rapid{{0, 0, 50}});  // first move: only sets the position
    p.add(tp::Rapid{{0, 0, 10}});
    p.add(tp::Linear{{0, 0, 0}, 100});
    p.add(tp::Linear{{100, 0, 0}, 600});
    p.add(tp::Dwell{2.5});
    p.add(tp::Rapid{{100, 0, 50}});
    const ProgramStats s = programStats(p);
    EXPECT_EQ(s.rapidMmPerMin, 5000);
    EXPECT_DOUBLE_EQ(s.totals.rapidLengthMm, 90);
    EXPECT_DOUBLE_EQ(s.totals.feedLengthMm, 110);
    EXPECT_NEAR(s.totals.rapidSeconds, 90.0 / 5000 * 60, 1e-9);
    EXPECT_NEAR(s.totals.feedSeconds, 6.0 + 10.0, 1e-9);
    EXPECT_DOUBLE_EQ(s.totals.dwellSeconds, 2.5);
    EXPECT_EQ(s.totals.cuttingExtents.min, (Vec3{0, 0, 0}));
    EXPECT_EQ(s.totals.cuttingExtents.max, (Vec3{100, 0, 10}));
    EXPECT_EQ(s.totals.rapidExtents.max, (Vec3{100, 0, 50}));
    EXPECT_EQ(s.totals.allExtents.min, (Vec3{0, 0, 0}));
    ASSERT_EQ(s.tools.size(), 1u);
    EXPECT_EQ(s.tools[0].toolNumber, 3);
    EXPECT_EQ(s.rapids, 3);
    EXPECT_EQ(s.feedMoves, 2);
    EXPECT_EQ(s.toolChanges, 1);

    StatsOptions o;
    o.rapidMmPerMin = 30000;  // a machine's (kinematics::estimateRapidMmPerMin)
    EXPECT_NEAR(programStats(p, o).totals.rapidSeconds, 90.0 / 30000 * 60, 1e-9);
    o.rapidMmPerMin = 0;  // none given: the default
    EXPECT_EQ(programStats(p, o).rapidMmPerMin, kDefaultRapidMmPerMin);
}

TEST(ProgramStats, ArcBulgesAndHelixLength)
{
    tp::Toolpath p;
    p.add(tp::Rapid{{10, 0, 0}});
    tp::Arc half;  // ccw half circle through +Y
    half.to = {-10, 0, 0};
    half.center = {0, 0, 0};
    half.feedMmPerMin = 1000;
    p.add(half);
    const ProgramStats s = programStats(p);
    EXPECT_NEAR(s.totals.feedLengthMm, 10 * std::numbers::pi, 1e-9);
    EXPECT_NEAR(s.totals.cuttingExtents.max.y, 10, 1e-9);
    EXPECT_NEAR(s.totals.cuttingExtents.min.y, 0, 1e-9);

    tp::Toolpath h;
    h.add(tp::Rapid{{10, 0, 0}});
    tp::Arc helix;  // two full cw turns down 4 mm
    helix.to = {10, 0, -4};
    helix.center = {0, 0, 0};
    helix.clockwise = true;
    helix.turns = 1;
    helix.feedMmPerMin = 1000;
    h.add(helix);
    const ProgramStats hs = programStats(h);
    EXPECT_NEAR(hs.totals.feedLengthMm, std::hypot(40 * std::numbers::pi, 4), 1e-9);
    EXPECT_NEAR(hs.totals.cuttingExtents.min.x, -10, 1e-9);
    EXPECT_NEAR(hs.totals.cuttingExtents.min.y, -10, 1e-9);
    EXPECT_NEAR(hs.totals.cuttingExtents.min.z, -4, 1e-9);
}

TEST(ProgramStats, FeedModes)
{
    tp::Toolpath p;
    p.add(tp::Rapid{{0, 0, 0}});
    p.add(tp::Spindle{1000, true});
    p.add(tp::FeedModeChange{tp::FeedMode::PerRevolution});
    p.add(tp::Linear{{100, 0, 0}, 0.1});  // 100 mm/min: 60 s
    p.add(tp::FeedModeChange{tp::FeedMode::InverseTime});
    p.add(tp::Linear{{0, 0, 0}, 2});  // half a minute
    p.add(tp::FeedModeChange{tp::FeedMode::PerMinute});
    p.add(tp::Linear{{0, 10, 0}, 0});  // no feed: counted, no time
    const ProgramStats s = programStats(p);
    EXPECT_NEAR(s.totals.feedSeconds, 90, 1e-9);
    EXPECT_EQ(s.movesWithoutFeed, 1);
}

TEST(ProgramStats, CyclesExpandAndToolsSplit)
{
    tp::Toolpath p;
    p.add(tp::ToolChange{{1}});
    p.add(tp::Rapid{{0, 0, 20}});
    tp::Cycle c;
    c.kind = tp::CycleKind::Drill;
    c.clearanceZ = 20;
    c.retractZ = 2;
    c.topZ = 0;
    c.bottomZ = -10;
    c.feedMmPerMin = 120;
    c.holes = {{10, 0, 0}, {20, 0, 0}};
    p.add(c);
    p.add(tp::ToolChange{{2}});
    p.add(tp::Linear{{20, 10, 20}, 600});
    const ProgramStats s = programStats(p);
    EXPECT_EQ(s.cycleHoles, 2);
    ASSERT_EQ(s.tools.size(), 2u);
    EXPECT_NEAR(s.tools[0].totals.feedLengthMm, 24, 1e-9);  // 12 mm per hole from R 2 to -10
    EXPECT_NEAR(s.tools[0].totals.feedSeconds, 12, 1e-9);
    EXPECT_NEAR(s.tools[0].totals.cuttingExtents.min.z, -10, 1e-9);
    EXPECT_NEAR(s.tools[1].totals.feedLengthMm, 10, 1e-9);
    EXPECT_NEAR(s.totals.feedLengthMm, 34, 1e-9);
}

// 3+2: moves in a tilted plane's frame count in the workpiece frame for the extents; lengths are
// the same in any frame, and a move across the plane change starts where the last one ended.
TEST(ProgramStats, ExtentsOfATiltedPlaneAreTheWorkpieces)
{
    tp::Toolpath p;
    p.add(tp::Rapid{{0, 0, 50}});
    // Turned 90 degrees about X: the frame's z is the workpiece's -Y, its y the workpiece's +Z.
    p.add(tp::WorkingPlane{{0, 0, 0}, {1, 0, 0}, {0, -1, 0}});
    p.add(tp::Rapid{{0, 50, 0}});  // the same point as before, in the new frame: no length
    p.add(tp::Linear{{0, 50, 20}, 100});
    p.add(tp::WorkingPlane{});
    p.add(tp::Linear{{0, -20, 50}, 100});  // where the last move ended: no length either
    const ProgramStats s = programStats(p);
    EXPECT_NEAR(s.totals.rapidLengthMm, 0, 1e-12);
    EXPECT_NEAR(s.totals.feedLengthMm, 20, 1e-12);
    EXPECT_NEAR(s.totals.allExtents.min.y, -20, 1e-12);
    EXPECT_NEAR(s.totals.allExtents.max.y, 0, 1e-12);
    EXPECT_NEAR(s.totals.allExtents.max.z, 50, 1e-12);
}
