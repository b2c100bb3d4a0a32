// Operation references resolved on the example part (face and hole indices pinned by the occ
// tests): pocket regions with their islands, holes, derived and overridden heights, and errors.
#include "document/OperationGeometry.h"
#include "ExampleJob.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"

#include <gtest/gtest.h>

using namespace camwb;

namespace {

using document::test::Example;
using document::test::example;
constexpr int kTopFace = 2, kBottomFace = 5, kPocketFloor = 25, kIslandTop = 30, kThroughHole = 21;

document::Operation pocketOf(std::vector<int> faces)
{
    document::Operation op;
    op.params = ops::PocketParams{};
    op.geometry.faces = std::move(faces);
    return op;
}

}  // namespace

TEST(OperationGeometry, PocketFloorBringsItsIslandAsAHole)
{
    auto g = document::resolveGeometry(pocketOf({kPocketFloor}), example().model);
    ASSERT_TRUE(g.ok()) << g.error().toString();
    ASSERT_EQ(g->regions.size(), 1u);
    EXPECT_EQ(g->regions[0].holes.size(), 1u);
    EXPECT_GT(g->regions[0].outer.signedArea(), 0);
}

TEST(OperationGeometry, AFaceInsideAnotherSelectedFaceBecomesItsIsland)
{
    // The bottom face (the block's outline with the through hole) and the island's top: the
    // island top lies inside the outline, so it is a second hole of the one region.
    auto g = document::resolveGeometry(pocketOf({kIslandTop, kBottomFace}), example().model);
    ASSERT_TRUE(g.ok()) << g.error().toString();
    ASSERT_EQ(g->regions.size(), 1u);
    EXPECT_EQ(g->regions[0].holes.size(), 2u);
    // The island top over the top face's pocket opening is not inside the top face: two regions.
    auto apart = document::resolveGeometry(pocketOf({kTopFace, kIslandTop}), example().model);
    ASSERT_TRUE(apart.ok()) << apart.error().toString();
    EXPECT_EQ(apart->regions.size(), 2u);
}

TEST(OperationGeometry, HeightsAreDerivedUnlessOverridden)
{
    const Example& ex = example();
    document::Operation op = pocketOf({kPocketFloor});
    auto g = document::resolveGeometry(op, ex.model);
    ASSERT_TRUE(g.ok());
    ops::Heights h = document::resolveHeights(op, g.value(), ex.model, ex.job.stock);
    EXPECT_DOUBLE_EQ(h.startZ, 16);  // the stock top, above the model's 15
    EXPECT_DOUBLE_EQ(h.finalZ, 10);  // the floor face
    EXPECT_DOUBLE_EQ(h.safeZ, 18);
    EXPECT_DOUBLE_EQ(h.clearanceZ, 26);
    op.heights.finalZ = 11;
    op.heights.clearanceZ = 40;
    h = document::resolveHeights(op, g.value(), ex.model, ex.job.stock);
    EXPECT_DOUBLE_EQ(h.finalZ, 11);
    EXPECT_DOUBLE_EQ(h.clearanceZ, 40);
    EXPECT_DOUBLE_EQ(h.safeZ, 18);

    document::Operation helix;
    helix.params = ops::HelixParams{};
    helix.geometry.holes = {kThroughHole};
    auto holes = document::resolveGeometry(helix, ex.model);
    ASSERT_TRUE(holes.ok()) << holes.error().toString();
    ASSERT_EQ(holes->holes.size(), 1u);
    EXPECT_DOUBLE_EQ(holes->holes[0].diameterMm, 10);
    h = document::resolveHeights(helix, holes.value(), ex.model, ex.job.stock);
    EXPECT_DOUBLE_EQ(h.startZ, 15);  // the hole's top
    EXPECT_DOUBLE_EQ(h.finalZ, 0);
}

TEST(OperationGeometry, AHelixOnAPickedCircleTakesItsDepthFromTheHeights)
{
    const Example& ex = example();
    constexpr int kThroughHoleTopCircle = 22;
    document::Job job = ex.job;
    document::Operation& helix = job.operations[2];
    ASSERT_EQ(helix.kind(), document::OperationKind::Helix);
    helix.geometry = {{}, {kThroughHoleTopCircle}, {}};
    auto refused = document::resolveGeometry(helix, ex.model);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("has no depth: untick \"depths from holes\""), std::string::npos)
        << refused.error().message;

    std::get<ops::HelixParams>(helix.params).depthsFromHoles = false;
    auto g = document::resolveGeometry(helix, ex.model);
    ASSERT_TRUE(g.ok()) << g.error().toString();
    ASSERT_EQ(g->holes.size(), 1u);
    EXPECT_NEAR(g->holes[0].diameterMm, 10, 1e-9);
    EXPECT_NEAR(g->holes[0].center.x, 72, 1e-9);
    EXPECT_NEAR(g->holes[0].center.y, 30, 1e-9);
    const ops::Heights h = document::resolveHeights(helix, g.value(), ex.model, ex.job.stock);
    EXPECT_DOUBLE_EQ(h.startZ, 15);
    EXPECT_DOUBLE_EQ(h.finalZ, 0);  // the model's bottom

    helix.heights.finalZ = 5;
    auto result = document::computeOperation(job, 2, ex.model);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_GT(result->counts.helices, 0);
    double lowest = 1e9;
    for (const toolpath::Record& r : result->toolpath.records())
        if (const auto* arc = std::get_if<toolpath::Arc>(&r))
            lowest = std::min(lowest, arc->to.z);
    EXPECT_DOUBLE_EQ(lowest, 5);
}

TEST(OperationGeometry, BadReferencesAreNamed)
{
    const occ::Model& model = example().model;
    auto message = [&](const document::Operation& op) {
        auto g = document::resolveGeometry(op, model);
        EXPECT_FALSE(g.ok());
        return g.ok() ? std::string() : g.error().message;
    };
    document::Operation pocket = pocketOf({99});
    pocket.setName("P");
    EXPECT_EQ(message(pocket), "pocket \"P\": face 99 is not in the model (it has 30 faces)");
    pocket.geometry.faces.clear();
    EXPECT_EQ(message(pocket), "pocket \"P\": nothing selected: choose faces");
    pocket.geometry.edges = {3};
    EXPECT_NE(message(pocket).find("edges are not supported"), std::string::npos);

    document::Operation drill;
    drill.params = ops::DrillParams{};
    drill.setName("D");
    drill.geometry.holes = {kTopFace};
    EXPECT_EQ(message(drill), "drilling \"D\": face 2 is not a vertical cylindrical hole");
    drill.geometry = {{kTopFace}, {}, {}};
    EXPECT_NE(message(drill).find("works on holes"), std::string::npos);
    // No model (a job whose model file is missing): said so, not blamed on the model's kind.
    EXPECT_EQ(document::resolveGeometry(drill, occ::Model{}).error().message, "drilling \"D\": no model is loaded");
}
