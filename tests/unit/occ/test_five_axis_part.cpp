// The five-axis example part and the model seen in a tilted frame (3+2): four inclined faces at
// 30 degrees, a hole square to each found as a vertical hole once the model is turned along the
// face's normal, face indices kept by the turn, and the errors of a frame that is none.
#include "OccTestUtil.h"

#include "occ/ExamplePart.h"
#include "occ/Model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace camwb::occ {
namespace {

constexpr double kPi = std::numbers::pi;

class FiveAxisPartTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        const std::string path = (test::scratchDir() / "example-five-axis.step").string();
        const base::Status written = writeFiveAxisExamplePart(path);
        ASSERT_TRUE(written.ok()) << written.error().toString();
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

base::Vec3 sideNormal(int quarter)
{
    const double a = quarter * kPi / 2;
    return {0.5 * std::cos(a), 0.5 * std::sin(a), std::sqrt(3.0) / 2};
}

// The planar face with this outward normal and the largest area (the inclined face, not the boss).
int faceWithNormal(const Model& m, const base::Vec3& normal)
{
    int best = 0;
    double area = 0;
    for (int i = 1; i <= m.faceCount(); ++i) {
        const FaceInfo f = m.face(i);
        if (f.planar && distance(f.normal, normal) < 1e-9 && f.areaMm2 > area) {
            best = i;
            area = f.areaMm2;
        }
    }
    return best;
}

// The frame whose z is `normal` and whose x is the workpiece X projected on the plane.
struct Frame {
    base::Vec3 x, z;
};
Frame frameAlong(const base::Vec3& normal)
{
    const base::Vec3 x = base::Vec3{1, 0, 0} - normal * normal.x;
    return {x * (1 / x.length()), normal};
}

}  // namespace

TEST_F(FiveAxisPartTest, InclinedFacesCapAndBounds)
{
    EXPECT_NEAR(model->boundsMin().x, -40, 1e-6);
    EXPECT_NEAR(model->boundsMax().y, 40, 1e-6);
    EXPECT_NEAR(model->boundsMin().z, 0, 1e-6);
    EXPECT_NEAR(model->boundsMax().z, 40, 1e-6);  // the cap's top: 20 + 20
    for (int quarter = 0; quarter < 4; ++quarter) {
        const int face = faceWithNormal(*model, sideNormal(quarter));
        EXPECT_GT(face, 0) << "inclined face " << quarter;
        // A trapezoid 15 / sin 30 = 30 mm up the slope, 80 and 28.04 mm wide, less a hole D6
        // (and on -X, less the boss's footprint; on +X exactly less the drafted boss' circle R5.5).
        const double trapezoid = 30 * (80 + (80 - 2 * 15 / std::tan(kPi / 6))) / 2;
        const double footprint = quarter == 0 ? 5.5 * 5.5 * kPi : 0;
        EXPECT_LT(model->face(face).areaMm2, trapezoid - 9 * kPi - footprint + 1e-6) << quarter;
        EXPECT_GT(model->face(face).areaMm2, trapezoid - 9 * kPi - footprint - 81) << quarter;
        if (quarter == 0)
            EXPECT_NEAR(model->face(face).areaMm2, trapezoid - 9 * kPi - footprint, 1e-6);
    }
    // No vertical holes: all four are square to the inclined faces.
    EXPECT_TRUE(model->holes().empty());
}

TEST_F(FiveAxisPartTest, EachHoleIsVerticalAlongItsFacesNormal)
{
    for (int quarter = 0; quarter < 4; ++quarter) {
        const base::Vec3 n = sideNormal(quarter);
        const Frame f = frameAlong(n);
        auto framed = model->inFrame({}, f.x, f.z);
        ASSERT_TRUE(framed.ok()) << framed.error().toString();
        EXPECT_EQ(framed->faceCount(), model->faceCount());
        const std::vector<geom::Hole> holes = framed->holes();
        ASSERT_EQ(holes.size(), 1u) << quarter;
        const geom::Hole& h = holes[0];
        EXPECT_NEAR(h.diameterMm, 6, 1e-6);
        EXPECT_NEAR(h.topZ - h.bottomZ, 8, 1e-6);
        EXPECT_FALSE(h.through);
        // The hole's top centre in the workpiece frame: on the face, half way up (Z 27.5).
        const base::Vec3 y = f.z.cross(f.x);
        const base::Vec3 top = f.x * h.center.x + y * h.center.y + f.z * h.topZ;
        EXPECT_NEAR(top.z, 27.5, 1e-6) << quarter;
        EXPECT_NEAR(std::hypot(top.x, top.y), std::hypot(40 - 7.5 / std::tan(kPi / 6), quarter == 2 ? 12.0 : 0.0),
                    1e-6);
        // The same face index in both frames, and its axis is the face's normal.
        const std::optional<base::Vec3> axis = model->cylinderAxis(h.faceIndex);
        ASSERT_TRUE(axis.has_value());
        EXPECT_NEAR(std::abs(axis->dot(n)), 1, 1e-9);
        // The inclined face lies flat in its frame, its normal +Z.
        const FaceInfo inclined = framed->face(faceWithNormal(*model, n));
        EXPECT_NEAR(inclined.normal.z, 1, 1e-9);
        EXPECT_NEAR(inclined.planeZ, h.topZ, 1e-6);
    }
}

TEST_F(FiveAxisPartTest, TheBossTopIsAFaceOfItsOwnPlane)
{
    const base::Vec3 n = sideNormal(2);
    int boss = 0;
    for (int i = 1; i <= model->faceCount(); ++i) {
        const FaceInfo f = model->face(i);
        if (f.planar && distance(f.normal, n) < 1e-9 && std::abs(f.areaMm2 - 80) < 1e-6)
            boss = i;
    }
    ASSERT_GT(boss, 0);
    const Frame f = frameAlong(n);
    auto framed = model->inFrame({}, f.x, f.z);
    ASSERT_TRUE(framed.ok());
    auto profile = framed->planarFaceOuterProfile(boss);
    ASSERT_TRUE(profile.ok()) << profile.error().toString();
    // 3 mm above the inclined face (20 + 10 sqrt 3 along the normal).
    EXPECT_NEAR(framed->face(boss).planeZ, 20 + 10 * std::sqrt(3.0) + 3, 1e-6);
}

TEST_F(FiveAxisPartTest, AFrameThatIsNoneIsAnError)
{
    EXPECT_FALSE(model->inFrame({}, {1, 0, 0}, {1, 0, 0}).ok());
    EXPECT_FALSE(model->inFrame({}, {2, 0, 0}, {0, 0, 1}).ok());
    EXPECT_FALSE(Model().inFrame({}, {1, 0, 0}, {0, 0, 1}).ok());
    EXPECT_FALSE(model->cylinderAxis(0).has_value());
    EXPECT_FALSE(model->cylinderAxis(faceWithNormal(*model, sideNormal(0))).has_value());  // planar
}

}  // namespace camwb::occ
