// Swarf milling's model questions: the drafted boss of the five-axis example as a ruled cone
// (rulings, normals, lengths along its bottom edge), faces that are not ruled refused by name, the
// existing features' face numbers kept, and the gouge check catching a tool in a neighbouring wall.
#include "OccShapes.h"
#include "OccTestUtil.h"

#include "occ/ExamplePart.h"
#include "occ/Model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace camwb::occ {
namespace {

constexpr double kPi = std::numbers::pi;

class SwarfFaceTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        const std::string path = (test::scratchDir() / "example-five-axis-swarf.step").string();
        ASSERT_TRUE(writeFiveAxisExamplePart(path).ok());
        base::Result<Model> loaded = Model::load(path);
        ASSERT_TRUE(loaded.ok()) << loaded.error().toString();
        model = new Model(loaded.value());
    }
    static void TearDownTestSuite()
    {
        delete model;
        model = nullptr;
    }
    static inline Model* model = nullptr;
};

const base::Vec3 kPlusXNormal{0.5, 0, std::sqrt(3.0) / 2};

int coneFace(const Model& m)
{
    for (int i = 1; i <= m.faceCount(); ++i) {
        auto swarf = m.swarfFace(i);
        if (swarf && swarf->surface == "cone")
            return i;
    }
    return 0;
}

TEST_F(SwarfFaceTest, TheDraftedBossIsAConeDrivenAlongItsBottomCircle)
{
    const int face = coneFace(*model);
    ASSERT_GT(face, 0);
    auto swarf = model->swarfFace(face);
    ASSERT_TRUE(swarf.ok()) << swarf.error().toString();
    EXPECT_TRUE(swarf->closed);
    EXPECT_EQ(model->edge(swarf->edge).curve, EdgeInfo::Curve::Circle);
    // The boss' axis: the +X face's normal through its centre 14 mm along +Y.
    const base::Vec3 centre{40 - 7.5 / std::tan(kPi / 6), 14, 27.5};
    for (int i = 0; i < 12; ++i) {
        const RulingPoint r = swarf->at(swarf->t0 + (swarf->t1 - swarf->t0) * i / 12);
        EXPECT_NEAR(r.ruling.length(), 1, 1e-12);
        EXPECT_NEAR(r.normal.length(), 1, 1e-12);
        EXPECT_NEAR(r.ruling.dot(r.normal), 0, 1e-9);
        // On the inclined face, R5.5 about the axis; the ruling 15 degrees in from the axis, up.
        const base::Vec3 d = r.point - centre;
        EXPECT_NEAR(d.dot(kPlusXNormal), 0, 1e-6);
        EXPECT_NEAR(d.length(), 5.5, 1e-6);
        EXPECT_NEAR(std::acos(r.ruling.dot(kPlusXNormal)) * 180 / kPi, 15, 1e-6);
        EXPECT_LT(r.ruling.dot(d), 0);  // narrowing upward
        EXPECT_GT(r.normal.dot(d), 0);  // away from the material: outward
        EXPECT_NEAR(r.lengthMm, 5 / std::cos(kPi / 12), 1e-3);
    }
}

TEST_F(SwarfFaceTest, TheEarlierFeaturesKeepTheirFaceNumbers)
{
    // The example job drills faces 18, 13, 14 and 8 (the holes on +X, -Y, +Y, -X), contours the boss
    // top (face 26) and swarfs the cone (face 1). The fused cone renumbered them all (they were 11,
    // 14, 18, 21 and 3 before it): a change of the generator must update the job.
    const std::pair<int, base::Vec3> holes[] = {
        {18, {0.5, 0, -0.866}}, {13, {0, -0.5, -0.866}}, {14, {0, 0.5, -0.866}}, {8, {-0.5, 0, -0.866}}};
    for (const auto& [hole, axis] : holes) {
        ASSERT_TRUE(model->cylinderAxis(hole).has_value()) << hole;
        EXPECT_NEAR(distance(*model->cylinderAxis(hole), axis), 0, 1e-3) << hole;
    }
    EXPECT_TRUE(model->face(26).planar);
    EXPECT_NEAR(model->face(26).areaMm2, 80, 1e-6);
    EXPECT_NEAR(model->face(26).normal.x, -0.5, 1e-9);
    EXPECT_EQ(coneFace(*model), 1);
}

TEST_F(SwarfFaceTest, FacesThatAreNotRuledAreRefusedByName)
{
    int sphere = 0;
    for (int i = 1; i <= model->faceCount(); ++i) {
        auto swarf = model->swarfFace(i);
        if (!swarf && swarf.error().message.find("sphere") != std::string::npos)
            sphere = i;
    }
    ASSERT_GT(sphere, 0);
    const std::string message = model->swarfFace(sphere).error().message;
    EXPECT_NE(message.find("face " + std::to_string(sphere) + " is a sphere, not a ruled developable surface"),
              std::string::npos)
        << message;
    EXPECT_FALSE(model->swarfFace(model->faceCount() + 1).ok());
    // An edge that is not the face's.
    const int face = coneFace(*model);
    auto other = model->swarfFace(face, model->edgeCount());
    ASSERT_FALSE(other.ok());
    EXPECT_NE(other.error().message.find("is not an edge of face"), std::string::npos) << other.error().message;
    // The cone's seam is one of its rulings: no drive edge.
    auto seam = model->swarfFace(face, 1);
    ASSERT_FALSE(seam.ok());
    EXPECT_NE(seam.error().message.find("runs along the rulings of face"), std::string::npos) << seam.error().message;
}

TEST_F(SwarfFaceTest, ThePlanarInclinedFaceHasRulingsUpTheSlope)
{
    // The +X inclined face: its lowest edge is the block's top edge at X 40, Z 20.
    int face = 0;
    double area = 0;
    for (int i = 1; i <= model->faceCount(); ++i)
        if (model->face(i).planar && distance(model->face(i).normal, kPlusXNormal) < 1e-9 &&
            model->face(i).areaMm2 > area) {
            face = i;
            area = model->face(i).areaMm2;
        }
    ASSERT_GT(face, 0);
    auto swarf = model->swarfFace(face);
    ASSERT_TRUE(swarf.ok()) << swarf.error().toString();
    const RulingPoint r = swarf->at((swarf->t0 + swarf->t1) / 2);
    EXPECT_NEAR(r.point.z, 20, 1e-9);
    EXPECT_NEAR(r.ruling.x, -std::sqrt(3.0) / 2, 1e-9);
    EXPECT_NEAR(r.ruling.z, 0.5, 1e-9);
    EXPECT_NEAR(distance(r.normal, kPlusXNormal), 0, 1e-9);
}

// A block with a pocket 40 x 20 x 10: a tool along the pocket's -Y wall, its side on the wall,
// is clear in the middle and in the end walls near the corners.
TEST(GougeCheck, AToolInTheNeighbouringWallIsCaught)
{
    const Model m =
        test::loadShape(test::cut(test::box(0, 0, 0, 60, 40, 20), test::box(10, 10, 10, 50, 30, 20)), "gouge-pocket");
    const double r = 3;
    auto pose = [&](double x) { return ToolPose{{x, 10 + r, 10}, {0, 0, 1}}; };
    EXPECT_FALSE(m.firstGouge({pose(20), pose(40)}, r, 12, 0.01).has_value());
    // Exactly in the corner the tool touches both walls: no gouge beyond the tolerance.
    EXPECT_FALSE(m.firstGouge({pose(10 + r), pose(30)}, r, 12, 0.01).has_value());
    // 1 mm further the tool is 1 mm in the +X end wall (x = 50).
    const std::optional<Gouge> g = m.firstGouge({pose(30), pose(40), pose(50 - r + 1)}, r, 12, 0.01);
    ASSERT_TRUE(g.has_value());
    EXPECT_EQ(g->pose, 2);
    EXPECT_GT(g->point.x, 50);
    ASSERT_GT(g->face, 0);
    EXPECT_TRUE(m.face(g->face).planar);
    EXPECT_NEAR(std::abs(m.face(g->face).normal.x), 1, 1e-9);
    // A tool tipped into the floor is caught as well.
    EXPECT_TRUE(m.firstGouge({ToolPose{{30, 20, 9.9}, {0, 0, 1}}}, r, 12, 0.01).has_value());
}

}  // namespace
}  // namespace camwb::occ
