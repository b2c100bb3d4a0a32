// Model::load on every path that is not the happy STEP one: missing and damaged files,
// unknown extensions, progress and cancellation, STL meshes.
#include "OccTestUtil.h"

#include "occ/ExamplePart.h"
#include "occ/Model.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace camwb::occ {
namespace {

std::string exampleStep()
{
    static const std::string path = [] {
        const std::string p = (test::scratchDir() / "formats-example.step").string();
        const base::Status written = writeExamplePart(p);
        EXPECT_TRUE(written.ok()) << written.error().toString();
        return p;
    }();
    return path;
}

TEST(LoadErrors, MissingFileNamesTheFile)
{
    const std::string path = (test::scratchDir() / "no-such-part.step").string();
    const base::Result<Model> r = Model::load(path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, path);
    EXPECT_EQ(r.error().message, "file not found");
}

TEST(LoadErrors, GarbageStepNamesTheFile)
{
    const std::string path = test::writeScratchFile(
        "garbage.step", "this is not a STEP file\nreally not; #1 = FOO(\n\x01\x02 random words 12 34 ,,,\n");
    const base::Result<Model> r = Model::load(path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, path);
    EXPECT_EQ(r.error().message.rfind("not a STEP file or damaged", 0), 0u) << r.error().message;
}

TEST(LoadErrors, EmptyAndRandomFilesOfEveryKindFailCleanly)
{
    std::mt19937 random(1234);
    for (const char* ext : {".step", ".stp", ".iges", ".igs", ".brep", ".brp", ".stl", ".STEP"}) {
        for (int variant = 0; variant < 3; ++variant) {
            std::string content;
            if (variant == 1)
                for (int i = 0; i < 2000; ++i)
                    content.push_back(static_cast<char>(random() & 0xff));
            if (variant == 2)
                for (int i = 0; i < 200; ++i)
                    content += "solid facet vertex 1 2 endloop #" + std::to_string(random() % 100) + " = (\n";
            const std::string path = test::writeScratchFile("random" + std::to_string(variant) + ext, content);
            const base::Result<Model> r = Model::load(path);
            ASSERT_FALSE(r.ok()) << path;
            EXPECT_EQ(r.error().file, path);
            EXPECT_FALSE(r.error().message.empty());
        }
    }
}

TEST(LoadErrors, UnsupportedExtension)
{
    const std::string path = test::writeScratchFile("part.dxf", "0\nSECTION\n");
    const base::Result<Model> r = Model::load(path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, path);
    EXPECT_NE(r.error().message.find("unsupported"), std::string::npos);
}

TEST(LoadErrors, DirectoryIsNotAFile)
{
    const std::string path = (test::scratchDir() / "folder.step").string();
    std::filesystem::create_directories(path);
    const base::Result<Model> r = Model::load(path);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, path);
}

TEST(LoadProgress, ReportsRisingFractionsUpToOne)
{
    std::vector<double> seen;
    const base::Result<Model> r = Model::load(exampleStep(), [&](double f) {
        seen.push_back(f);
        return true;
    });
    ASSERT_TRUE(r.ok()) << r.error().toString();
    ASSERT_GE(seen.size(), 2u);
    EXPECT_EQ(seen.front(), 0.0);
    for (std::size_t i = 1; i < seen.size(); ++i)
        EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_NEAR(seen.back(), 1.0, 1e-9);
}

TEST(LoadProgress, FalseAtTheStartCancels)
{
    int calls = 0;
    const base::Result<Model> r = Model::load(exampleStep(), [&](double) {
        ++calls;
        return false;
    });
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "cancelled");
    EXPECT_EQ(r.error().file, exampleStep());
    EXPECT_EQ(calls, 1);
}

TEST(LoadProgress, FalseDuringTheTransferCancels)
{
    double last = 0;
    const base::Result<Model> r = Model::load(exampleStep(), [&](double f) {
        last = f;
        return f < 0.4;
    });
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "cancelled");
    EXPECT_LT(last, 1.0);
}

// A unit tetrahedron, written the way CAD systems write ASCII STL.
std::string tetrahedronStl()
{
    return "solid tetra\n"
           " facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 10 0\n   vertex 10 0 0\n  endloop\n "
           "endfacet\n"
           " facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 10 0 0\n   vertex 0 0 10\n  endloop\n "
           "endfacet\n"
           " facet normal -1 0 0\n  outer loop\n   vertex 0 0 0\n   vertex 0 0 10\n   vertex 0 10 0\n  endloop\n "
           "endfacet\n"
           " facet normal 1 1 1\n  outer loop\n   vertex 10 0 0\n   vertex 0 10 0\n   vertex 0 0 10\n  endloop\n "
           "endfacet\n"
           "endsolid tetra\n";
}

TEST(LoadStl, AsciiMeshIsDisplayOnly)
{
    const std::string path = test::writeScratchFile("tetra.STL", tetrahedronStl());
    bool progressed = false;
    const base::Result<Model> r = Model::load(path, [&](double) { return progressed = true; });
    ASSERT_TRUE(r.ok()) << r.error().toString();
    EXPECT_TRUE(progressed);
    const Model& model = r.value();
    EXPECT_FALSE(model.empty());
    EXPECT_FALSE(model.hasBRep());
    EXPECT_EQ(model.faceCount(), 0);
    EXPECT_EQ(model.topPlanarFace(), 0);
    EXPECT_FALSE(model.planarFaceOuterProfile(1).ok());

    const DisplayMesh mesh = model.mesh();
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.triangleFace.size(), 4u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_TRUE(mesh.featureEdges.empty());
    EXPECT_EQ(mesh.boundsMin, (base::Vec3{0, 0, 0}));
    EXPECT_EQ(mesh.boundsMax, (base::Vec3{10, 10, 10}));
    EXPECT_EQ(model.boundsMax(), (base::Vec3{10, 10, 10}));
    // Facet normals point out of the solid: the bottom facet looks down.
    EXPECT_FLOAT_EQ(mesh.normals[2], -1.0f);
}

}  // namespace
}  // namespace camwb::occ

namespace camwb::occ {
namespace {

// modules/occ is the only place OCCT is included, and only privately: its public headers stay clean.
TEST(PublicHeaders, IncludeNoOcctHeader)
{
    for (const char* header : {"Model.h", "ExamplePart.h", "DisplayMesh.h"}) {
        const std::string path = std::string(CAMWB_TEST_DATA_DIR) + "/modules/occ/" + header;
        std::ifstream in(path);
        ASSERT_TRUE(in) << path;
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind("#include", 0) != 0)
                continue;
            EXPECT_EQ(line.find(".hxx"), std::string::npos) << path << ": " << line;
            EXPECT_EQ(line.find("detail/"), std::string::npos) << path << ": " << line;
        }
    }
}

}  // namespace
}  // namespace camwb::occ
