// The example part built, written as STEP, read back: faces, the top face's profile, the pocket
// floor with its island, the holes, meshing, and the face indices the example job relies on.
#include "OccTestUtil.h"

#include "occ/ExamplePart.h"
#include "occ/Model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <thread>
#include <vector>

namespace camwb::occ {
namespace {

constexpr double kPi = std::numbers::pi;

class ExamplePartTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        path = (test::scratchDir() / "example-block.step").string();
        const base::Status written = writeExamplePart(path);
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

    static inline std::string path;
    static inline Model* model = nullptr;
};

struct SegmentCounts {
    int lines = 0;
    int arcs = 0;
};

SegmentCounts countSegments(const geom::Profile& profile)
{
    SegmentCounts counts;
    for (const geom::Segment& s : profile.segments)
        (s.isArc() ? counts.arcs : counts.lines)++;
    return counts;
}

// Index of the planar face with the given normal Z sign and plane Z, 0 if none.
int findZFace(const Model& model, double normalZ, double z)
{
    for (int i = 1; i <= model.faceCount(); ++i) {
        const FaceInfo f = model.face(i);
        if (f.planar && std::abs(f.normal.z - normalZ) < 1e-9 && std::abs(f.planeZ - z) < 1e-9)
            return i;
    }
    return 0;
}

TEST(ModelTest, DefaultIsEmpty)
{
    const Model model;
    EXPECT_TRUE(model.empty());
    EXPECT_FALSE(model.hasBRep());
    EXPECT_EQ(model.faceCount(), 0);
    EXPECT_EQ(model.topPlanarFace(), 0);
    EXPECT_FALSE(model.planarFaceOuterProfile(1).ok());
    EXPECT_TRUE(model.mesh().empty());
}

TEST_F(ExamplePartTest, FacesOfTheBlock)
{
    EXPECT_FALSE(model->empty());
    EXPECT_TRUE(model->hasBRep());
    // Block: 4 sides + 4 corner cylinders + top + bottom; pocket: 4 walls + 4 corners + floor; island:
    // side + top; through hole: 1; drilled holes: 4 x (side + the drill's conical point).
    EXPECT_EQ(model->faceCount(), 10 + 9 + 2 + 1 + 8);
    int planar = 0;
    for (int i = 1; i <= model->faceCount(); ++i) {
        const FaceInfo f = model->face(i);
        EXPECT_EQ(f.index, i);
        EXPECT_GT(f.areaMm2, 0);
        if (f.planar) {
            ++planar;
            EXPECT_NEAR(f.normal.length(), 1.0, 1e-12);
        }
    }
    EXPECT_EQ(planar, 4 + 2 + 4 + 1 + 1);
    EXPECT_EQ(model->face(0).index, 0);
    EXPECT_EQ(model->face(model->faceCount() + 1).index, 0);
}

TEST_F(ExamplePartTest, TopPlanarFaceIsTheTopAtZ15)
{
    const int top = model->topPlanarFace();
    ASSERT_GT(top, 0);
    const FaceInfo f = model->face(top);
    EXPECT_TRUE(f.planar);
    EXPECT_NEAR(f.normal.z, 1.0, 1e-12);
    EXPECT_NEAR(f.planeZ, 15.0, 1e-9);
    const double outline = 90 * 60 - (4 - kPi) * 64;
    const double pocket = 44 * 36 - (4 - kPi) * 36;
    const double holes = kPi * 25 + 4 * kPi * 2.5 * 2.5;
    EXPECT_NEAR(f.areaMm2, outline - pocket - holes, 1e-6 * outline);
}

TEST_F(ExamplePartTest, TopOuterProfileIsTheRoundedRectangle)
{
    const base::Result<geom::Profile> result = model->planarFaceOuterProfile(model->topPlanarFace());
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const geom::Profile& profile = result.value();
    EXPECT_TRUE(profile.closed);
    EXPECT_TRUE(profile.isContinuous(1e-9));
    const double expected = 90 * 60 - (4 - kPi) * 64;
    EXPECT_GT(profile.signedArea(), 0);  // counter-clockwise
    EXPECT_NEAR(profile.signedArea(), expected, 1e-6 * expected);

    const SegmentCounts counts = countSegments(profile);
    EXPECT_EQ(counts.lines, 4);
    EXPECT_EQ(counts.arcs, 4);
    std::set<std::pair<long, long>> centres;
    for (const geom::Segment& s : profile.segments) {
        if (!s.isArc())
            continue;
        EXPECT_NEAR(s.radius(), 8.0, 1e-6);
        EXPECT_NEAR(distance(s.end, s.center), 8.0, 1e-6);
        EXPECT_TRUE(s.ccw);  // convex corners of a counter-clockwise outline
        EXPECT_NEAR(s.sweep(), kPi / 2, 1e-9);
        centres.insert({std::lround(s.center.x), std::lround(s.center.y)});
    }
    EXPECT_EQ(centres, (std::set<std::pair<long, long>>{{8, 8}, {82, 8}, {82, 52}, {8, 52}}));
    EXPECT_NEAR(profile.length(), 2 * (90 - 16) + 2 * (60 - 16) + 2 * kPi * 8, 1e-6);
}

TEST_F(ExamplePartTest, PocketFloorRegionHasTheIsland)
{
    const int floor = findZFace(*model, 1.0, 10.0);
    ASSERT_GT(floor, 0);
    const double outline = 44 * 36 - (4 - kPi) * 36;
    const base::Result<geom::Profile> profile = model->planarFaceOuterProfile(floor);
    ASSERT_TRUE(profile.ok()) << profile.error().toString();
    EXPECT_NEAR(profile->signedArea(), outline, 1e-6 * outline);

    const base::Result<geom::Region> region = model->planarFaceRegion(floor);
    ASSERT_TRUE(region.ok()) << region.error().toString();
    EXPECT_NEAR(region->outer.signedArea(), outline, 1e-6 * outline);
    EXPECT_TRUE(region->outer.isContinuous(1e-9));
    const SegmentCounts counts = countSegments(region->outer);
    EXPECT_EQ(counts.arcs, 4);
    EXPECT_EQ(counts.lines, 4);
    std::set<std::pair<long, long>> centres;
    for (const geom::Segment& s : region->outer.segments)
        if (s.isArc()) {
            EXPECT_NEAR(s.radius(), 6.0, 1e-9);
            centres.insert({std::lround(s.center.x), std::lround(s.center.y)});
        }
    EXPECT_EQ(centres, (std::set<std::pair<long, long>>{{17, 18}, {49, 18}, {49, 42}, {17, 42}}));

    ASSERT_EQ(region->holes.size(), 1u);  // the island, D10 at the pocket centre
    const geom::Profile& island = region->holes[0];
    EXPECT_NEAR(island.signedArea(), -kPi * 25, 1e-9);
    for (const geom::Segment& s : island.segments) {
        ASSERT_TRUE(s.isArc());
        EXPECT_NEAR(s.center.x, 33, 1e-9);
        EXPECT_NEAR(s.center.y, 30, 1e-9);
        EXPECT_NEAR(s.radius(), 5, 1e-9);
    }
    // A D6 end mill fits between the island and every wall.
    EXPECT_GE(geom::distanceToProfile({33, 30}, region->outer) - 5, 6);
}

TEST_F(ExamplePartTest, OneThroughHoleAndFourBlindHoles)
{
    const std::vector<geom::Hole> holes = model->holes();
    ASSERT_EQ(holes.size(), 5u);
    int through = 0;
    std::set<std::pair<long, long>> blind;
    for (const geom::Hole& h : holes) {
        EXPECT_NEAR(h.topZ, 15, 1e-9);
        if (h.through) {
            ++through;
            EXPECT_NEAR(h.diameterMm, 10, 1e-9);
            EXPECT_NEAR(h.center.x, 72, 1e-9);
            EXPECT_NEAR(h.center.y, 30, 1e-9);
            EXPECT_NEAR(h.bottomZ, 0, 1e-9);
        } else {
            EXPECT_NEAR(h.diameterMm, 5, 1e-9);
            EXPECT_NEAR(h.bottomZ, 7, 1e-9);
            EXPECT_NEAR(h.center.x, std::round(h.center.x), 1e-9);
            EXPECT_NEAR(h.center.y, std::round(h.center.y), 1e-9);
            blind.insert({std::lround(h.center.x), std::lround(h.center.y)});
        }
    }
    EXPECT_EQ(through, 1);
    EXPECT_EQ(blind, (std::set<std::pair<long, long>>{{8, 8}, {82, 8}, {82, 52}, {8, 52}}));
}

TEST_F(ExamplePartTest, BottomFaceLooksDownButItsProfileIsCounterClockwise)
{
    const int bottom = findZFace(*model, -1.0, 0.0);
    ASSERT_GT(bottom, 0);
    const base::Result<geom::Profile> result = model->planarFaceOuterProfile(bottom);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const double expected = 90 * 60 - (4 - kPi) * 64;
    EXPECT_NEAR(result->signedArea(), expected, 1e-6 * expected);
    for (const geom::Segment& s : result->segments)
        if (s.isArc())
            EXPECT_TRUE(s.ccw);
}

TEST_F(ExamplePartTest, ProfileErrors)
{
    int cylinder = 0, wall = 0;
    for (int i = 1; i <= model->faceCount(); ++i) {
        const FaceInfo f = model->face(i);
        if (!f.planar && cylinder == 0)
            cylinder = i;
        if (f.planar && std::abs(f.normal.z) < 1e-9 && wall == 0)
            wall = i;
    }
    ASSERT_GT(cylinder, 0);
    ASSERT_GT(wall, 0);
    const auto nonPlanar = model->planarFaceOuterProfile(cylinder);
    ASSERT_FALSE(nonPlanar.ok());
    EXPECT_NE(nonPlanar.error().message.find("not planar"), std::string::npos) << nonPlanar.error().message;
    const auto side = model->planarFaceOuterProfile(wall);
    ASSERT_FALSE(side.ok());
    EXPECT_NE(side.error().message.find("not normal to Z"), std::string::npos) << side.error().message;
    EXPECT_FALSE(model->planarFaceOuterProfile(0).ok());
    EXPECT_FALSE(model->planarFaceOuterProfile(model->faceCount() + 1).ok());
}

TEST_F(ExamplePartTest, MeshCoversEveryFace)
{
    const DisplayMesh mesh = model->mesh(0.05);
    ASSERT_FALSE(mesh.empty());
    ASSERT_FALSE(mesh.triangles.empty());
    EXPECT_EQ(mesh.triangles.size() % 3, 0u);
    EXPECT_EQ(mesh.triangleFace.size(), mesh.triangles.size() / 3);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    const std::size_t vertices = mesh.positions.size() / 3;
    for (std::uint32_t index : mesh.triangles)
        ASSERT_LT(index, vertices);
    std::set<int> faces(mesh.triangleFace.begin(), mesh.triangleFace.end());
    EXPECT_EQ(faces.size(), static_cast<std::size_t>(model->faceCount()));
    EXPECT_EQ(*faces.begin(), 1);
    EXPECT_EQ(*faces.rbegin(), model->faceCount());

    // Triangles of the top face wind counter-clockwise seen from above and carry +Z normals.
    const int top = model->topPlanarFace();
    for (std::size_t t = 0; t < mesh.triangleFace.size(); ++t) {
        if (mesh.triangleFace[t] != top)
            continue;
        auto vertex = [&](int k) {
            const std::size_t v = mesh.triangles[3 * t + k];
            return base::Vec3{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
        };
        const base::Vec3 a = vertex(0), b = vertex(1), c = vertex(2);
        EXPECT_GT((b - a).cross(c - a).z, 0);
        EXPECT_NEAR(a.z, 15.0, 1e-5);
        EXPECT_NEAR(mesh.normals[3 * mesh.triangles[3 * t] + 2], 1.0f, 1e-6f);
    }

    EXPECT_FALSE(mesh.featureEdges.empty());
    for (const auto& edge : mesh.featureEdges)
        EXPECT_GE(edge.size(), 2u);

    const double tol = 1e-6;
    EXPECT_NEAR(mesh.boundsMin.x, 0, tol);
    EXPECT_NEAR(mesh.boundsMin.y, 0, tol);
    EXPECT_NEAR(mesh.boundsMin.z, 0, tol);
    EXPECT_NEAR(mesh.boundsMax.x, 90, tol);
    EXPECT_NEAR(mesh.boundsMax.y, 60, tol);
    EXPECT_NEAR(mesh.boundsMax.z, 15, tol);
    EXPECT_EQ(model->boundsMin(), mesh.boundsMin);
    EXPECT_EQ(model->boundsMax(), mesh.boundsMax);
}

TEST_F(ExamplePartTest, MeshingFromSeveralThreads)
{
    const Model copy = *model;  // copies share the data
    DisplayMesh fine, coarse;
    std::thread a([&] { fine = copy.mesh(0.01); });
    std::thread b([&] { coarse = model->mesh(0.5); });
    a.join();
    b.join();
    EXPECT_FALSE(fine.triangles.empty());
    EXPECT_FALSE(coarse.triangles.empty());
    EXPECT_EQ(fine.triangleFace.size(), fine.triangles.size() / 3);
    EXPECT_EQ(coarse.triangleFace.size(), coarse.triangles.size() / 3);
}

// OCCT's STEP reader shares state between readers: unguarded, three threads loading once each
// crashed in about one run in 200 (STEPControl_Reader's constructor); four threads loading six
// times each give the race many more chances.
TEST_F(ExamplePartTest, LoadingFromSeveralThreads)
{
    constexpr int kThreads = 4, kLoads = 6;
    std::vector<base::Result<Model>> results(kThreads * kLoads, base::makeError("not run"));
    std::vector<std::thread> threads;
    for (int i = 0; i < kThreads; ++i)
        threads.emplace_back([&, i] {
            for (int k = 0; k < kLoads; ++k)
                results[std::size_t(i * kLoads + k)] = Model::load(path);
        });
    for (std::thread& t : threads)
        t.join();
    for (const auto& r : results) {
        ASSERT_TRUE(r.ok()) << r.error().toString();
        EXPECT_EQ(r->faceCount(), model->faceCount());
        EXPECT_EQ(r->topPlanarFace(), model->topPlanarFace());
    }
}

TEST_F(ExamplePartTest, CommittedExampleMatchesTheGenerator)
{
    const std::string committed = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.step";
    const base::Result<Model> loaded = Model::load(committed);
    ASSERT_TRUE(loaded.ok()) << loaded.error().toString();
    EXPECT_EQ(loaded->faceCount(), model->faceCount());
    EXPECT_EQ(loaded->edgeCount(), model->edgeCount());
    const int top = loaded->topPlanarFace();
    EXPECT_NEAR(loaded->face(top).planeZ, 15.0, 1e-9);
    EXPECT_EQ(loaded->boundsMax(), model->boundsMax());
}

// The example job names faces by index: these must not move when the file is regenerated.
TEST_F(ExamplePartTest, FaceIndicesTheExampleJobUses)
{
    const Model committed =
        Model::load(std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.step").value();
    for (const Model* m : std::vector<const Model*>{model, &committed}) {
        EXPECT_EQ(m->topPlanarFace(), 2);
        EXPECT_EQ(findZFace(*m, 1.0, 10.0), 25);  // pocket floor
        const FaceInfo islandTop = m->face(30);
        EXPECT_TRUE(islandTop.planar);
        EXPECT_NEAR(islandTop.planeZ, 15, 1e-9);
        EXPECT_NEAR(islandTop.areaMm2, kPi * 25, 1e-6);
        std::vector<int> holeFaces;
        for (const geom::Hole& h : m->holes())
            holeFaces.push_back(h.faceIndex);
        EXPECT_EQ(holeFaces, (std::vector<int>{11, 20, 21, 22, 23}));
        for (int side : {1, 6, 7, 10})
            EXPECT_NEAR(std::abs(m->face(side).normal.x) + std::abs(m->face(side).normal.y), 1, 1e-12);
    }
}

}  // namespace
}  // namespace camwb::occ
