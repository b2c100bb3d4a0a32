// CL trace goldens of representative contours, compared with the files under golden/.
// Regenerate with CAMWB_UPDATE_GOLDEN=1 (the test then writes the files and passes); review
// each changed file before committing it.
#include "../support/FeedKinds.h"
#include "../support/OpsGolden.h"
#include "ContourTestUtil.h"
#include "toolpath/TraceWriter.h"

using namespace camwb;
using namespace camwb::ops::test;

namespace {

void compareWithGolden(const std::string& name, const toolpath::Toolpath& tp)
{
    expectGolden("contour", name + ".trace", toolpath::traceOf(tp));
    expectFeedKindsAgreeWithSections(tp);  // the trace shows each move's kind, not its section's feeds
}

toolpath::Toolpath compute(const std::vector<Profile>& loops, const ops::ContourParams& p)
{
    auto r = ops::computeContour(loops, p, tool(), 0);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return r.ok() ? r.value().toolpath : toolpath::Toolpath{};
}

}  // namespace

// The first profile's trace (a rectangle, one level, plunge): unchanged but for the strategy.
TEST(ContourGolden, RectangleOneLevel)
{
    compareWithGolden("rectangle-one-level", compute({geom::test::rectangle(0, 0, 40, 20)}, params()));
}

// Two levels, arc leads, ramp entry, two tabs on the last level, 0.5 mm radial stock.
TEST(ContourGolden, PlateLeadsRampTabs)
{
    auto p = params();
    p.stepDownMm = 2;
    p.leadIn = p.leadOut = ops::LeadKind::Arc;
    p.leadRadiusMm = 6;
    p.entry = ops::EntryKind::Ramp;
    p.rampAngleDeg = 5;
    p.tabCount = 2;
    p.tabWidthMm = 4;
    p.tabHeightMm = 1.5;
    p.radialStockMm = 0.5;
    compareWithGolden("plate-leads-ramp-tabs", compute({geom::test::roundedRectangle(0, 0, 90, 60, 8)}, p));
}

// An inside contour with cutter compensation (G41 in a straight approach, G40 on leaving), helix.
TEST(ContourGolden, PocketWallCompensatedHelix)
{
    auto p = params(ops::ContourSide::Inside);
    p.compensation = ops::CompensationOutput::Control;
    p.leadIn = p.leadOut = ops::LeadKind::Arc;
    p.leadRadiusMm = 8;
    p.entry = ops::EntryKind::Helix;
    p.helixDiameterMm = 6;
    p.helixPitchMm = 1.5;
    compareWithGolden("pocket-wall-compensated-helix", compute({geom::test::roundedRectangle(0, 0, 80, 50, 12)}, p));
}
