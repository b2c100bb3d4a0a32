// The mould example part (occ::writeMouldExamplePart): a valid closed solid, its faces and
// bounds, the flat floors a level must land on, the dome, no undercut (machinable from +Z), and
// the committed resources/examples/example-mould.step is what the generator writes, byte for byte.
#include "OccTestUtil.h"

#include "occ/ExamplePart.h"
#include "occ/Model.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <set>

namespace camwb::occ {
namespace {

// The file's bytes, less the product name's counter ("Open CASCADE STEP translator 7.6 2"): OCCT
// counts the files one process writes, so it depends on which tests ran before.
std::string readStep(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return std::regex_replace(bytes, std::regex("STEP translator 7\\.6 [0-9]+"), "STEP translator 7.6 N");
}

class MouldPartTest : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        path = (test::scratchDir() / "example-mould.step").string();
        const base::Status written = writeMouldExamplePart(path);
        ASSERT_TRUE(written.ok()) << written.error().toString();
        STEPControl_Reader reader;
        ASSERT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
        reader.TransferRoots();
        shape = new TopoDS_Shape(reader.OneShape());
        base::Result<Model> loaded = Model::load(path);
        ASSERT_TRUE(loaded.ok()) << loaded.error().toString();
        model = new Model(loaded.value());
    }
    static void TearDownTestSuite()
    {
        delete model;
        delete shape;
    }
    static inline std::string path;
    static inline TopoDS_Shape* shape = nullptr;
    static inline Model* model = nullptr;
};

TEST_F(MouldPartTest, OneValidClosedSolid)
{
    int solids = 0;
    for (TopExp_Explorer it(*shape, TopAbs_SOLID); it.More(); it.Next())
        ++solids;
    EXPECT_EQ(solids, 1);
    EXPECT_TRUE(BRepCheck_Analyzer(*shape).IsValid());
    // Closed: every edge is shared by exactly two faces (no free or non-manifold edge).
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(*shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int i = 1; i <= edgeFaces.Extent(); ++i)
        if (!BRep_Tool::Degenerated(TopoDS::Edge(edgeFaces.FindKey(i))))
            EXPECT_EQ(edgeFaces(i).Extent(), 2) << "edge " << i;
}

TEST_F(MouldPartTest, FacesBoundsAndFloors)
{
    EXPECT_EQ(model->faceCount(), 34);
    EXPECT_NEAR(model->boundsMin().x, 0, 1e-6);
    EXPECT_NEAR(model->boundsMin().y, 0, 1e-6);
    EXPECT_NEAR(model->boundsMin().z, 0, 1e-6);
    EXPECT_NEAR(model->boundsMax().x, 100, 1e-6);
    EXPECT_NEAR(model->boundsMax().y, 80, 1e-6);
    EXPECT_NEAR(model->boundsMax().z, 30, 1e-6);
    // Flat faces facing up: the top (Z 30), the shelf (Z 20) and the cavity floor (Z 10), nothing else.
    std::multiset<double> upLevels;
    for (int i = 1; i <= model->faceCount(); ++i) {
        const FaceInfo f = model->face(i);
        if (f.planar && f.normal.z > 1 - 1e-9)
            upLevels.insert(std::round(f.planeZ * 1e6) / 1e6);
    }
    EXPECT_EQ(upLevels, (std::multiset<double>{10, 20, 30}));
}

// The dome's top is at Z 16, below the shelf and the top; the cavity reaches down to the floor.
TEST_F(MouldPartTest, TheDomeRisesFromTheFloor)
{
    int spheres = 0;
    for (TopExp_Explorer it(*shape, TopAbs_FACE); it.More(); it.Next()) {
        BRepAdaptor_Surface surface(TopoDS::Face(it.Current()));
        if (surface.GetType() != GeomAbs_Sphere)
            continue;
        ++spheres;
        Bnd_Box box;
        BRepBndLib::AddOptimal(it.Current(), box, false, false);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        EXPECT_NEAR(z1, 16, 1e-6);
        EXPECT_GT(z0, 10);  // the R2 fillet takes its foot
        EXPECT_NEAR((x0 + x1) / 2, 60, 1e-6);
        EXPECT_NEAR((y0 + y1) / 2, 40, 1e-6);
    }
    EXPECT_EQ(spheres, 1);
}

// Three-axis machinable: no face looks down except the block's bottom, so every vertical line
// enters the material once, through faces seen from +Z (no undercut). Normals sampled on a grid.
TEST_F(MouldPartTest, NoUndercut)
{
    int bottoms = 0, drafted = 0;
    for (TopExp_Explorer it(*shape, TopAbs_FACE); it.More(); it.Next()) {
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        BRepGProp_Face surface(face);  // its normal follows the face's orientation
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        double lowest = 1, highest = -1;
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j) {
                const gp_Pnt2d uv(u0 + (u1 - u0) * i / 10, v0 + (v1 - v0) * j / 10);
                if (BRepClass_FaceClassifier(face, uv, 1e-7).State() == TopAbs_OUT)
                    continue;  // the grid covers the face's UV box, the face may not fill it
                gp_Pnt point;
                gp_Vec normal;
                surface.Normal(uv.X(), uv.Y(), point, normal);
                if (normal.Magnitude() < 1e-9)
                    continue;  // a degenerate corner of a blend has no normal
                const double nz = normal.Z() / normal.Magnitude();
                lowest = std::min(lowest, nz);
                highest = std::max(highest, nz);
            }
        if (lowest < -1 + 1e-9) {
            ++bottoms;
            continue;
        }
        EXPECT_GE(lowest, -1e-9) << "a face looks down";
        // Walls drafted 10 degrees: their normals rise sin 10 above the horizontal.
        if (std::abs(highest - lowest) < 1e-9 && std::abs(lowest - std::sin(10 * M_PI / 180)) < 1e-9)
            ++drafted;
    }
    EXPECT_EQ(bottoms, 1);
    EXPECT_EQ(drafted, 9);  // the ±Y and +X walls, the -X wall above the shelf, the shelf's wall, 4 corner cones
}

TEST_F(MouldPartTest, TheCommittedFileIsWhatTheGeneratorWrites)
{
    const std::string again = (test::scratchDir() / "example-mould-again.step").string();
    ASSERT_TRUE(writeMouldExamplePart(again).ok());
    const std::string bytes = readStep(path);
    EXPECT_GT(bytes.size(), 1000u);
    EXPECT_TRUE(readStep(again) == bytes) << "writing the part twice gave different files";
    EXPECT_TRUE(readStep(std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-mould.step") == bytes)
        << "resources/examples/example-mould.step is not what the generator writes; regenerate it with "
           "camwb-make-example resources/examples/example-mould.step mould";
}

}  // namespace
}  // namespace camwb::occ
