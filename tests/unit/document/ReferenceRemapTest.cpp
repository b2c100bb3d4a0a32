// The operations' references looked up on another model by what they are (document/ReferenceRemap.h):
// the same model loaded again keeps every reference; the same part moved keeps none (same numbers,
// other places); a mesh has nothing to refer to; a model that was not loaded checks nothing.
#include "document/ReferenceRemap.h"
#include "ExampleJob.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace camwb;

namespace {

using document::test::example;
const std::string kExampleStep = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.step";

std::filesystem::path scratch()
{
    const auto dir = std::filesystem::temp_directory_path() / "camwb-remap-test";
    std::filesystem::create_directories(dir);
    return dir;
}

std::string readAll(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string writeFile(const std::string& name, const std::string& text)
{
    const std::string path = (scratch() / name).string();
    std::ofstream(path) << text;
    return path;
}

// The example part moved along X: every 3D point of the STEP file shifted by 10 mm (2D points are
// parameters of curves on surfaces and stay). The representation's own placement is one of those
// points, so the part ends up 20 mm along.
std::string movedExample()
{
    const std::string text = readAll(kExampleStep);
    const std::regex point(R"(CARTESIAN_POINT\('',\(([-0-9.E+]+),([-0-9.E+]+),([-0-9.E+]+)\)\))");
    std::string out;
    auto last = text.cbegin();
    for (std::sregex_iterator it(text.begin(), text.end(), point), end; it != end; ++it) {
        out.append(last, text.cbegin() + it->position());
        out += "CARTESIAN_POINT('',(" + std::to_string(std::stod((*it)[1]) + 10.0) + "," + (*it)[2].str() + "," +
               (*it)[3].str() + "))";
        last = text.cbegin() + it->position() + it->length();
    }
    out.append(last, text.cend());
    return writeFile("moved.step", out);
}

std::size_t referenceCount(const std::vector<document::Operation>& operations)
{
    std::size_t n = 0;
    for (const document::Operation& op : operations)
        n += op.geometry.faces.size() + op.geometry.edges.size() + op.geometry.holes.size();
    return n;
}

}  // namespace

TEST(ReferenceRemap, TheSameModelLoadedAgainKeepsEveryReference)
{
    auto again = occ::Model::load(kExampleStep);
    ASSERT_TRUE(again.ok()) << again.error().toString();
    std::vector<document::Operation> operations = example().job.operations;
    // An edge reference too: the first edge of the model, whatever it is.
    operations[0].geometry.edges = {1};
    const document::RemappedOperations remapped = document::remapReferences(operations, example().model, again.value());
    EXPECT_TRUE(remapped.checked);
    EXPECT_TRUE(remapped.lost.empty()) << document::describeLost(remapped.lost, operations);
    ASSERT_EQ(remapped.operations.size(), operations.size());
    for (std::size_t i = 0; i < operations.size(); ++i) {
        EXPECT_EQ(remapped.operations[i].geometry.faces, operations[i].geometry.faces) << i;
        EXPECT_EQ(remapped.operations[i].geometry.edges, operations[i].geometry.edges) << i;
        EXPECT_EQ(remapped.operations[i].geometry.holes, operations[i].geometry.holes) << i;
    }
}

TEST(ReferenceRemap, TheSameNumbersAtOtherPlacesAreLost)
{
    auto moved = occ::Model::load(movedExample());
    ASSERT_TRUE(moved.ok()) << moved.error().toString();
    ASSERT_NEAR(moved->boundsMin().x, example().model.boundsMin().x + 20.0, 1e-6);
    ASSERT_EQ(moved->faceCount(), example().model.faceCount());  // every number still exists
    const auto& operations = example().job.operations;
    const document::RemappedOperations remapped = document::remapReferences(operations, example().model, moved.value());
    EXPECT_TRUE(remapped.checked);
    EXPECT_EQ(remapped.lost.size(), referenceCount(operations));
    EXPECT_EQ(referenceCount(remapped.operations), 0u);
    const std::string described = document::describeLost(remapped.lost, operations);
    EXPECT_NE(described.find("contour \"Outer contour\": face 2"), std::string::npos) << described;
    EXPECT_NE(described.find("helix \"Through hole D10\": hole 21"), std::string::npos) << described;
}

TEST(ReferenceRemap, AMeshHasNothingToReferTo)
{
    const std::string stl = writeFile("box.stl", "solid box\n"
                                                 "facet normal 0 0 1\nouter loop\nvertex 0 0 1\nvertex 1 0 1\n"
                                                 "vertex 0 1 1\nendloop\nendfacet\nendsolid box\n");
    auto mesh = occ::Model::load(stl);
    ASSERT_TRUE(mesh.ok()) << mesh.error().toString();
    const auto& operations = example().job.operations;
    const document::RemappedOperations remapped = document::remapReferences(operations, example().model, mesh.value());
    EXPECT_EQ(remapped.lost.size(), referenceCount(operations));
    EXPECT_EQ(remapped.lost.front().operation, 0);
    EXPECT_EQ(remapped.lost.front().reference, "face 2");
}

TEST(ReferenceRemap, WithoutTheOldModelNothingIsCheckedOrDropped)
{
    const auto& operations = example().job.operations;
    const document::RemappedOperations remapped = document::remapReferences(operations, occ::Model(), example().model);
    EXPECT_FALSE(remapped.checked);
    EXPECT_TRUE(remapped.lost.empty());
    EXPECT_EQ(referenceCount(remapped.operations), referenceCount(operations));
}
