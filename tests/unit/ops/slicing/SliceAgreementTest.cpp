// The mesh slicer against OCCT's exact section (occ::Model::sectionLoops) on the example block and
// a fresh five-axis example part: at many levels both sections have as many loops, each point of
// one lies within the meshing deflection (over the sine of the wall's slope: a horizontal distance)
// of the other, and their areas agree. Also the levels on the block's floors, its flat levels,
// and sectionLoops' errors.
#include "SliceTestUtil.h"

#include "document/Simulate.h"
#include "occ/ExamplePart.h"
#include "occ/Model.h"
#include "ops/surface/MeshSlicer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <unistd.h>

namespace camwb::ops::surface {
namespace {

using test::Loops;
constexpr double kDeflection = 0.01;    // the mesh's
constexpr double kExactChord = 0.0005;  // OCCT's section edges discretised within this

occ::Model loadModel(const std::string& path)
{
    base::Result<occ::Model> model = occ::Model::load(path);
    if (!model)
        ADD_FAILURE() << model.error().toString();
    return model ? model.value() : occ::Model();
}

const occ::Model& exampleBlock()
{
    static const occ::Model model =
        loadModel(std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.step");
    return model;
}

// The model's mesh as the 3D operations slice it: welded across the faces' edges.
sim::TriangleMesh weldedMesh(const occ::Model& model)
{
    return sim::weldVertices(document::designMesh(model, kDeflection));
}

const occ::Model& fiveAxisPart()
{
    static const occ::Model model = [] {
        const std::string path =
            (std::filesystem::temp_directory_path() / ("camwb-slicing-" + std::to_string(::getpid()) + ".step"))
                .string();
        const base::Status written = occ::writeFiveAxisExamplePart(path);
        EXPECT_TRUE(written.ok()) << written.error().toString();
        occ::Model loaded = loadModel(path);
        std::filesystem::remove(path);
        return loaded;
    }();
    return model;
}

// Compares the mesh's section with OCCT's at each level (OCCT's taken at z + exactOffset), allowing
// allowed(z) between them; returns the largest distance seen.
double expectAgreement(const occ::Model& model, const std::vector<double>& levels,
                       const std::function<double(double)>& allowed, double exactOffset = 0)
{
    const std::vector<MeshSection> sections = sliceMesh(weldedMesh(model), levels);
    double worst = 0;
    for (const MeshSection& s : sections) {
        const base::Result<Loops> exact = model.sectionLoops(s.z + exactOffset, kExactChord);
        if (!exact) {
            ADD_FAILURE() << exact.error().toString();
            continue;
        }
        EXPECT_EQ(s.loops.size(), exact.value().size()) << "z " << s.z;
        EXPECT_EQ(s.openChains, 0u) << "z " << s.z;
        const double d = test::hausdorff(s.loops, exact.value());
        worst = std::max(worst, d);
        EXPECT_LE(d, allowed(s.z)) << "z " << s.z;
        // The areas differ by no more than the band the loops may stray in.
        EXPECT_NEAR(test::signedArea(s.loops), test::signedArea(exact.value()),
                    allowed(s.z) * test::perimeter(exact.value()))
            << "z " << s.z;
    }
    return worst;
}

TEST(SliceAgreement, ExampleBlockMatchesOcctsSection)
{
    // Vertical walls only: the horizontal distance is the deflection's.
    std::vector<double> levels;
    for (double z = 0.13; z < 15; z += 0.37)
        levels.push_back(z);
    const double worst =
        expectAgreement(exampleBlock(), levels, [](double) { return kDeflection + kExactChord + 1e-4; });
    std::cout << "example block: largest distance " << worst << " mm over " << levels.size() << " levels\n";
}

TEST(SliceAgreement, FiveAxisPartMatchesOcctsSection)
{
    // Inclined planes (exact in the mesh), holes square to them (walls 60 degrees from horizontal)
    // and the spherical cap (R20 about Z 20, from Z 35 to 40): there a wall sloping at angle a
    // strays the deflection / sin(a) horizontally; sin(a) = r / 20 at the section's radius r.
    auto allowed = [](double z) {
        const double sine = z <= 35 ? std::sin(60 * std::numbers::pi / 180) : std::sqrt(400 - (z - 20) * (z - 20)) / 20;
        return 1.1 * kDeflection / sine + kExactChord + 1e-4;
    };
    std::vector<double> levels;
    for (double z = 0.21; z < 39.5; z += 0.53)
        levels.push_back(z);
    const double worst = expectAgreement(fiveAxisPart(), levels, allowed);
    std::cout << "five-axis part: largest distance " << worst << " mm over " << levels.size() << " levels\n";
}

TEST(SliceAgreement, LevelsOnTheBlocksFloorsAreTakenJustAboveThem)
{
    // Z 7: where the blind holes' walls meet their drill points, Z 10: the pocket's floor. OCCT's section exactly there
    // has the floors' faces in it; a micron above, the walls only.
    expectAgreement(
        exampleBlock(), {7, 10}, [](double) { return kDeflection + kExactChord + 1e-4; }, 1e-6);
    const std::vector<MeshSection> s = sliceMesh(weldedMesh(exampleBlock()), {15, 10, 0});
    EXPECT_TRUE(s[0].loops.empty()) << "nothing above the top";
    // At Z 10: the outline, the pocket (a hole), the island in it, the through hole and four blind holes.
    EXPECT_EQ(s[1].loops.size(), 8u);
    EXPECT_EQ(s[2].loops.size(), 2u) << "on the bottom: the outline and the through hole";
    const std::vector<geom::Region> regions = sectionRegions(s[1], 0.01);
    ASSERT_EQ(regions.size(), 2u) << "the block with its holes, and the island";
    EXPECT_NEAR(geom::totalArea(regions), test::signedArea(s[1].loops), 1e-6);
}

TEST(SliceAgreement, FlatLevelsOfTheExampleParts)
{
    // The block: the pocket's floor at 10, the top and the island's top at 15 (the bottom faces
    // down; the blind holes end in 118 degree drill points, no floor). The five-axis part: only its
    // top at 35 (the holes' floors and the boss's top are inclined).
    EXPECT_EQ(flatLevels(document::designMesh(exampleBlock(), kDeflection)), (std::vector<double>{10, 15}));
    EXPECT_EQ(flatLevels(document::designMesh(fiveAxisPart(), kDeflection)), (std::vector<double>{35}));
}

TEST(SliceAgreement, SectionLoopsErrors)
{
    EXPECT_FALSE(exampleBlock().sectionLoops(5, 0).ok());
    const base::Result<Loops> above = exampleBlock().sectionLoops(20, 0.01);
    ASSERT_TRUE(above.ok()) << above.error().toString();
    EXPECT_TRUE(above.value().empty());
    const std::string stl =
        (std::filesystem::temp_directory_path() / ("camwb-slicing-" + std::to_string(::getpid()) + ".stl")).string();
    ASSERT_TRUE(sim::writeStl(document::designMesh(exampleBlock(), 0.1), stl).ok());
    const occ::Model mesh = loadModel(stl);
    std::filesystem::remove(stl);
    const base::Result<Loops> fromStl = mesh.sectionLoops(5, 0.01);
    ASSERT_FALSE(fromStl.ok());
    EXPECT_NE(fromStl.error().message.find("STL"), std::string::npos) << fromStl.error().message;
}

}  // namespace
}  // namespace camwb::ops::surface
