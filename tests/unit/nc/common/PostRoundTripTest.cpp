// Round trip of every post golden (posts/<id>/tests/<case>/) and of the example job's goldens
// (tests/golden/jobs/example-block: the NC and the CL the operations made): the NC the post wrote,
// read back by our interpreter for its dialect, must move the machine as the CL it was posted
// from does, within the output precision (MotionMatch.h).
#include "MotionMatch.h"

#include "nc/Interpreter.h"
#include "nc/ToolTable.h"
#include "toolpath/ClImport.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

namespace camwb::nc::test {
namespace {

namespace fs = std::filesystem;

struct PostCase {
    std::string name;  // "<post>_<case>" for the test name
    fs::path dir;
    fs::path input, nc;  // the CL and the NC; empty: input.* and expected.* in dir
};

void PrintTo(const PostCase& c, std::ostream* out) { *out << c.name; }

std::vector<PostCase> postCases()
{
    std::vector<PostCase> cases;
    const fs::path posts = fs::path(CAMWB_TEST_DATA_DIR) / "posts";
    for (const auto& post : fs::directory_iterator(posts)) {
        if (!post.is_directory() || !fs::exists(post.path() / "tests"))
            continue;
        for (const auto& dir : fs::directory_iterator(post.path() / "tests")) {
            // A case whose NC the interpreters cannot read back yet says why in `no-roundtrip`
            // (the five-axis goldens until the Heidenhain interpreter runs M128 and B/C).
            if (!dir.is_directory() || fs::exists(dir.path() / "no-roundtrip"))
                continue;
            std::string name = post.path().filename().string() + "_" + dir.path().filename().string();
            std::replace_if(
                name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
            // A case posting a job names the CL golden of its operations in `cl` (the round trip
            // reads CL files, it does not compute jobs).
            fs::path cl;
            if (std::ifstream named(dir.path() / "cl"); named) {
                std::string relative;
                std::getline(named, relative);
                cl = fs::path(CAMWB_TEST_DATA_DIR) / relative;
            }
            cases.push_back({name, dir.path(), cl});
        }
    }
    std::sort(cases.begin(), cases.end(), [](const PostCase& a, const PostCase& b) { return a.name < b.name; });
    const fs::path example = fs::path(CAMWB_TEST_DATA_DIR) / "tests/golden/jobs/example-block";
    cases.push_back({"example_job", example, example / "expected.trace", example / "expected.mpf"});
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

// Per NC line, the CL's pass-through text written there (else empty): such lines are the CL
// author's business (APT INSERT), not necessarily valid for the control, so their diagnostics
// are not the post's fault.
std::vector<std::string> passThroughLines(const fs::path& nc, const toolpath::Toolpath& cl)
{
    std::vector<std::string> texts;
    for (const toolpath::Record& r : cl.records())
        if (const auto* p = std::get_if<toolpath::PassThrough>(&r))
            texts.push_back(p->text);
    std::vector<std::string> lines;
    std::ifstream in(nc);
    for (std::string line; std::getline(in, line);) {
        std::string found;
        for (const std::string& text : texts)
            if (!text.empty() && line.size() >= text.size() &&
                line.compare(line.size() - text.size(), text.size(), text) == 0)
                found = text;
        lines.push_back(found);
    }
    return lines;
}

toolpath::Toolpath pecksFromRPlane(const toolpath::Toolpath& cl)
{
    toolpath::Toolpath out;
    for (std::size_t i = 0; i < cl.size(); ++i) {
        toolpath::Record r = cl.record(i);
        if (auto* c = std::get_if<toolpath::Cycle>(&r))
            if (c->kind == toolpath::CycleKind::Peck || c->kind == toolpath::CycleKind::ChipBreak)
                c->topZ = c->retractZ;
        out.add(r, cl.source(i));
    }
    return out;
}

// Written with 3 decimals in mm or 4 in inch: up to 0.00005 in (0.00127 mm) per axis.
MatchTolerance writtenTolerance()
{
    MatchTolerance tolerance;
    tolerance.pointMm = tolerance.backPointMm = 0.0025;
    return tolerance;
}

class PostRoundTrip : public testing::TestWithParam<PostCase> {};

TEST_P(PostRoundTrip, NcTracesBackToTheCl)
{
    const fs::path dir = GetParam().dir;
    const fs::path input = GetParam().input.empty() ? onlyFile(dir, "input") : GetParam().input;
    const fs::path nc = GetParam().nc.empty() ? onlyFile(dir, "expected", ".warnings") : GetParam().nc;
    ASSERT_FALSE(input.empty()) << dir;
    ASSERT_FALSE(nc.empty()) << dir;

    const auto format = toolpath::clFormatFromExtension(input.string());
    ASSERT_TRUE(format) << input;
    auto cl = toolpath::readClFile(input.string(), *format);
    ASSERT_TRUE(cl) << cl.error().toString();

    // Where the CL asks for cutter compensation its moves are the contour, not the tool centre:
    // the control offsets them. This round trip checks that the post wrote the contour the CL
    // holds, so the interpreter compensates by radius 0 (every tool of the CL in the table with
    // diameter 0). The offset itself is checked against LinuxCNC's rs274 (tests/external) and by
    // the compensation's own property tests, not against our own filter applied twice.
    ToolTable zeroRadius;
    for (const toolpath::Record& r : cl.value().toolpath.records())
        if (const auto* change = std::get_if<toolpath::ToolChange>(&r))
            zeroRadius.set({change->tool.number, 0, 0.0, 0.0, {}});
    InterpretOptions options;
    options.toolTable = &zeroRadius;
    toolpath::ToolpathRecorder recorder;
    const InterpretResult result = interpretFile(nc.string(), std::nullopt, options, recorder);
    const std::vector<std::string> passThrough = passThroughLines(nc, cl.value().toolpath);
    for (const Diagnostic& d : result.diagnostics)
        if (d.line < 1 || d.line > static_cast<int>(passThrough.size()) || passThrough[d.line - 1].empty())
            ADD_FAILURE() << formatDiagnostic(d);
    EXPECT_TRUE(result.completed) << nc;

    // G83/G73 count pecks from the R plane (LinuxCNC's G-code reference), the CL from the hole
    // top, and ISO has no word for the top: what the control does is the expectation.
    toolpath::Toolpath expected = cl.value().toolpath;
    if (result.files.size() && guessDialect("", nc.string()) == Dialect::Iso)
        expected = pecksFromRPlane(expected);

    MatchTolerance tolerance = writtenTolerance();
    // Arcs the post linearises within 0.01 mm (its warnings say so): chords and arc may be that far apart.
    std::ifstream warnings(dir / "expected.warnings");
    const std::string warned((std::istreambuf_iterator<char>(warnings)), std::istreambuf_iterator<char>());
    if (warned.find("written as lines within 0.01 mm") != std::string::npos)
        tolerance.pointMm = tolerance.backPointMm = 0.0125;
    const auto difference = matchMotion(recorder.toolpath(), expected, tolerance);
    EXPECT_FALSE(difference) << nc << ": " << *difference;
}

// The round trip must be able to fail: the example job's Klartext with one coordinate moved by
// 0.1 mm, and the thesis case with its plunge feed parameter changed, no longer move as their CL.
std::optional<std::string> klartextDifference(const std::string& caseName, const std::string& from,
                                              const std::string& to, const fs::path& clFile)
{
    const fs::path dir = fs::path(CAMWB_TEST_DATA_DIR) / "posts/heidenhain-itnc530/tests" / caseName;
    std::ifstream in(dir / "expected.h");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos)
        return std::nullopt;
    text.replace(at, from.size(), to);
    const fs::path mutated = fs::path(testing::TempDir()) / ("mutated-" + caseName + ".h");
    std::ofstream(mutated) << text;
    auto cl = toolpath::readClFile(clFile.string(), *toolpath::clFormatFromExtension(clFile.string()));
    EXPECT_TRUE(cl.ok());
    toolpath::ToolpathRecorder recorder;
    interpretFile(mutated.string(), std::nullopt, {}, recorder);
    return matchMotion(recorder.toolpath(), cl.value().toolpath, writtenTolerance());
}

TEST(PostRoundTripCanFail, AMovedKlartextCoordinateOrAChangedFeedParameter)
{
    const fs::path root = CAMWB_TEST_DATA_DIR;
    EXPECT_TRUE(klartextDifference("example-job", "L Z+13 F150", "L Z+13.1 F150",
                                   root / "tests/golden/jobs/example-block/expected.trace"));
    EXPECT_TRUE(klartextDifference("thesis", "Q603=300 ;", "Q603=310 ;",
                                   root / "posts/heidenhain-itnc530/tests/thesis/input.trace"));
}

INSTANTIATE_TEST_SUITE_P(PostGoldens, PostRoundTrip, testing::ValuesIn(postCases()),
                         [](const testing::TestParamInfo<PostCase>& info) { return info.param.name; });

}  // namespace
}  // namespace camwb::nc::test
