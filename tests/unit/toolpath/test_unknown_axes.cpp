// An UnknownAxes record (an untraced M140 MB MAX, G53 or SUPA read back from NC) makes every
// consumer of the toolpath module forget those axes: nothing is drawn, measured or spanned from
// their old values, and the path goes on once the moves give them again.
#include "toolpath/KnownPosition.h"
#include "toolpath/ProgramStats.h"
#include "toolpath/ToolpathPolylines.h"

#include <gtest/gtest.h>

using namespace camwb::toolpath;
using camwb::base::Vec3;

namespace {

// In at Z 50, down to Z -5, then up to where the program does not say; across in X and Y (Z still
// unknown), down to Z 5 and on.
Toolpath retractToNowhere()
{
    Toolpath p;
    p.add(Rapid{{10, 10, 50}});
    p.add(Linear{{10, 10, -5}, 100});
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}});
    p.add(Rapid{{90, 90, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
    p.add(Rapid{{0, 0, 5}, AxisMask{AxisMask::kZ}});
    p.add(Linear{{90, 90, -5}, 100});
    return p;
}

}  // namespace

TEST(UnknownAxes, KnownPositionForgetsOnlyThoseAxes)
{
    KnownPosition at(Vec3{1, 2, 3});
    at.forget(AxisMask{AxisMask::kZ});
    EXPECT_EQ(at.known(), (AxisMask{AxisMask::kX | AxisMask::kY}));
    EXPECT_FALSE(at.point());
    at.moveTo(Vec3{0, 0, 7}, AxisMask{AxisMask::kZ});
    ASSERT_TRUE(at.point());
    EXPECT_EQ(*at.point(), (Vec3{1, 2, 7}));
}

TEST(UnknownAxes, TheBackplotDrawsNothingFromTheOldPlace)
{
    const ToolpathPolylines lines = ToolpathPolylines::fromToolpath(retractToNowhere());
    // The plunge, then the last plunge from (90, 90, 5): no rapid from (10, 10, -5) or to
    // (90, 90, -5), where the tool never was.
    ASSERT_EQ(lines.segments().size(), 2u);
    const auto& pts = lines.points();
    EXPECT_EQ(pts[lines.segments()[0].from], (Vec3{10, 10, 50}));
    EXPECT_EQ(pts[lines.segments()[0].to], (Vec3{10, 10, -5}));
    EXPECT_EQ(pts[lines.segments()[1].from], (Vec3{90, 90, 5}));
    EXPECT_EQ(pts[lines.segments()[1].to], (Vec3{90, 90, -5}));
    EXPECT_EQ(lines.segmentCount(PathSegmentKind::Rapid), 0u);
}

TEST(UnknownAxes, ProgramStatsCountNoLengthToOrFromTheUnknownPlace)
{
    const ProgramStats s = programStats(retractToNowhere());
    EXPECT_DOUBLE_EQ(s.totals.feedLengthMm, 55 + 10);
    EXPECT_DOUBLE_EQ(s.totals.rapidLengthMm, 0);  // the only rapid with a known start is the first
    EXPECT_EQ(s.rapids, 3);
    EXPECT_EQ(s.totals.rapidExtents.min.z, 5);  // never at Z -5 on a rapid
}
