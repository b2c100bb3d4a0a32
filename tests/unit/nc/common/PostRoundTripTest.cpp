// Round trip of every post golden (posts/<id>/tests/<case>/): the NC the post wrote
// (expected.<ext>), read back by our interpreter for its dialect, must move the machine as the CL
// it was posted from (input.*) does, within the output precision (MotionMatch.h).
#include "MotionMatch.h"

#include "nc/Interpreter.h"
#include "toolpath/ClImport.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace camwb::nc::test {
namespace {

namespace fs = std::filesystem;

struct PostCase {
    std::string name;  // "<post>_<case>" for the test name
    fs::path dir;
};

std::vector<PostCase> postCases()
{
    std::vector<PostCase> cases;
    const fs::path posts = fs::path(CAMWB_TEST_DATA_DIR) / "posts";
    for (const auto& post : fs::directory_iterator(posts)) {
        if (!post.is_directory() || !fs::exists(post.path() / "tests"))
            continue;
        for (const auto& dir : fs::directory_iterator(post.path() / "tests")) {
            if (!dir.is_directory())
                continue;
            std::string name = post.path().filename().string() + "_" + dir.path().filename().string();
            std::replace_if(
                name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
            cases.push_back({name, dir.path()});
        }
    }
    std::sort(cases.begin(), cases.end(), [](const PostCase& a, const PostCase& b) { return a.name < b.name; });
    return cases;
}

fs::path onlyFile(const fs::path& dir, const std::string& stem, const std::string& unlessExtension = {})
{
    for (const auto& entry : fs::directory_iterator(dir)) {
        const fs::path p = entry.path();
        if (p.stem() == stem && p.extension() != unlessExtension)
            return p;
    }
    return {};
}

class PostRoundTrip : public testing::TestWithParam<PostCase> {};

TEST_P(PostRoundTrip, NcTracesBackToTheCl)
{
    const fs::path dir = GetParam().dir;
    const fs::path input = onlyFile(dir, "input");
    const fs::path nc = onlyFile(dir, "expected", ".warnings");
    ASSERT_FALSE(input.empty()) << dir;
    ASSERT_FALSE(nc.empty()) << dir;

    const auto format = toolpath::clFormatFromExtension(input.string());
    ASSERT_TRUE(format) << input;
    auto cl = toolpath::readClFile(input.string(), *format);
    ASSERT_TRUE(cl) << cl.error().toString();

    toolpath::ToolpathRecorder recorder;
    const InterpretResult result = interpretFile(nc.string(), std::nullopt, {}, recorder);
    for (const Diagnostic& d : result.diagnostics)
        ADD_FAILURE() << formatDiagnostic(d);
    EXPECT_TRUE(result.completed) << nc;

    MatchTolerance tolerance;
    // Written with 3 decimals in mm or 4 in inch: up to 0.00005 in (0.00127 mm) per axis.
    tolerance.pointMm = tolerance.backPointMm = 0.0025;
    // Oblique arcs the post linearises within 0.01 mm: chords and arc may be that far apart.
    if (dir.filename() == "linearised")
        tolerance.backPointMm = 0.0125;
    const auto difference = matchMotion(recorder.toolpath(), cl.value().toolpath, tolerance);
    EXPECT_FALSE(difference) << nc << ": " << *difference;
}

INSTANTIATE_TEST_SUITE_P(PostGoldens, PostRoundTrip, testing::ValuesIn(postCases()),
                         [](const testing::TestParamInfo<PostCase>& info) { return info.param.name; });

}  // namespace
}  // namespace camwb::nc::test
