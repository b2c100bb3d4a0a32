// The roughing's second look at its regions: the model's sections say the tool-centre regions of
// a drafted cavity and a boss keep clear (flat, ball, bull-nose), and a region pushed into the
// model by half a millimetre is caught at its level.
#include "ops/surface/SectionCheck.h"
#include "RoughingTestUtil.h"
#include "geom/ArcFit.h"
#include "geom/RegionOps.h"
#include "ops/surface/ToolCentre.h"

#include <gtest/gtest.h>

#include <ostream>

namespace camwb::ops {
namespace {

using namespace test;

struct Case {
    const char* kind;
    double corner;
};
void PrintTo(const Case& c, std::ostream* out) { *out << c.kind << " corner " << c.corner; }

class SectionCheck : public ::testing::TestWithParam<Case> {};

TEST_P(SectionCheck, RegionsFromTheShadowsKeepClearAndAGrownOneIsCaught)
{
    const sim::TriangleMesh cavity = heightMesh(draftedCavity(12, 8, 6, 2), 0, 0, 60, 50, 160, 0);
    const sim::TriangleMesh boss = heightMesh(draftedBoss(4, 10, 10, 3), 0, 0, 60, 50, 160, 0);
    const ToolController tc = toolController(GetParam().kind, 6, GetParam().corner);
    const double side = 0.3, bottom = 0.2, tol = 0.01;
    for (const sim::TriangleMesh* model : {&cavity, &boss}) {
        const surface::ToolCentreRegions centres(*model, tc.tool, {side, bottom, tol});
        const std::vector<geom::Region> area = geom::offsetRegions(
            {geom::Region{geom::fitLinesAndArcs({{0, 0}, {60, 0}, {60, 50}, {0, 50}}, true, tol), {}}}, 0, tol);
        const std::vector<double> levels{18.5, 15, 11.2, 8.2, 5};
        std::vector<std::vector<geom::Region>> regions;
        for (double z : levels)
            regions.push_back(centres.at(z, area));
        const surface::SectionClearance clearance{3 + side, centres.fullRadiusHeightMm(), bottom, tol};
        EXPECT_FALSE(surface::firstLevelTouchingSection(*model, levels, regions, clearance).has_value());
        // The regions grown by half a millimetre come into the model at the first level with walls.
        std::vector<std::vector<geom::Region>> grown;
        for (const auto& region : regions)
            grown.push_back(geom::intersect(geom::offsetRegions(region, 0.5, tol), area, tol));
        const auto caught = surface::firstLevelTouchingSection(*model, levels, grown, clearance);
        ASSERT_TRUE(caught.has_value());
        EXPECT_FALSE(regions[*caught].empty());
    }
}

INSTANTIATE_TEST_SUITE_P(Tools, SectionCheck, ::testing::Values(Case{"flat", 0}, Case{"ball", 3}, Case{"bull", 1}),
                         [](const auto& info) { return std::string(info.param.kind); });

}  // namespace
}  // namespace camwb::ops
