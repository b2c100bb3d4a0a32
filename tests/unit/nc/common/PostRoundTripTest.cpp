// Round trip of every post golden (posts/<id>/tests/<case>/) and of the example jobs' goldens
// (tests/golden/jobs/example-block and example-five-axis: the NC and the CL the operations made): the NC the post
// wrote, read back by our interpreter for its dialect, must move the machine as the CL it was posted from does, within
// the output precision (MotionMatch.h).
#include "MotionMatch.h"

#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "nc/ToolTable.h"
#include "post/PostProcessor.h"
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
    fs::path post;       // the post's script: its default machine is the case's unless it names one
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
            const fs::path script = post.path().parent_path() / (post.path().filename().string() + ".js");
            cases.push_back({name, dir.path(), cl, {}, script});
        }
    }
    std::sort(cases.begin(), cases.end(), [](const PostCase& a, const PostCase& b) { return a.name < b.name; });
    const fs::path example = fs::path(CAMWB_TEST_DATA_DIR) / "tests/golden/jobs/example-block";
    cases.push_back({"example_job", example, example / "expected.trace", example / "expected.mpf"});
    const fs::path fiveAxis = fs::path(CAMWB_TEST_DATA_DIR) / "tests/golden/jobs/example-five-axis";
    cases.push_back({"example_five_axis_job", fiveAxis, fiveAxis / "expected.trace", fiveAxis / "expected.h",
                     posts / "heidenhain-itnc530.js"});
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

// The first line of a case's file, or "".
std::string firstLine(const fs::path& file)
{
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// The machine the case was posted for: its `machine` file, else its post's default machine (the
// golden run passes the same, tests/golden/RunPostGolden.cmake). Five-axis NC reads back only
// through the machine's kinematics.
std::optional<kinematics::Machine> caseMachine(const PostCase& c, post::PostInfo* info)
{
    std::string id = firstLine(c.dir / "machine");
    if (!c.post.empty() && fs::exists(c.post)) {
        auto post = post::PostProcessor::load(c.post.string());
        EXPECT_TRUE(post) << post.error().toString();
        if (post) {
            *info = post.value().info();
            if (id.empty())
                id = info->defaultMachine;
        }
    }
    if (id.empty())
        return std::nullopt;
    auto machine = kinematics::findMachine(id, {(fs::path(CAMWB_TEST_DATA_DIR) / "resources/machines").string()});
    EXPECT_TRUE(machine) << machine.error().toString();
    return machine ? std::optional(std::move(machine).value()) : std::nullopt;
}

// The post's property `name` as the case sets it (`properties`: name=value lines), or "".
std::string caseProperty(const fs::path& dir, const std::string& name)
{
    std::ifstream in(dir / "properties");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(name + "=", 0) == 0)
            return line.substr(name.size() + 1);
    return {};
}

// Written with 3 decimals in mm or 4 in inch: up to 0.00005 in (0.00127 mm) per axis.
MatchTolerance writtenTolerance()
{
    MatchTolerance tolerance;
    tolerance.pointMm = tolerance.backPointMm = 0.0025;
    return tolerance;
}

// Case `c`'s NC file `nc` read back by our interpreter (through the case's machine) and matched
// against the case's CL: the first difference, or none. A diagnostic neither expected nor the
// post's own warning fails the test.
std::optional<std::string> roundTrip(const PostCase& c, const fs::path& nc)
{
    const fs::path dir = c.dir;
    const fs::path input = c.input.empty() ? onlyFile(dir, "input") : c.input;
    const auto format = toolpath::clFormatFromExtension(input.string());
    if (input.empty() || !format)
        return "no CL input in " + dir.string();
    auto cl = toolpath::readClFile(input.string(), *format);
    if (!cl)
        return cl.error().toString();
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
    post::PostInfo info;
    const std::optional<kinematics::Machine> machine = caseMachine(c, &info);
    options.machine = machine ? &*machine : nullptr;
    toolpath::ToolpathRecorder recorder;
    const InterpretResult result = interpretFile(nc.string(), std::nullopt, options, recorder);
    const std::vector<std::string> passThrough = passThroughLines(nc, cl.value().toolpath);
    // What the reader cannot know by design is listed per case in `roundtrip-warnings` ("line:
    // message" lines): M140 MB MAX from an unknown position leaves the tip unknown, so the moves
    // until X, Y and Z are given again are untraced; a retract traced to the end of Z's travel
    // makes the program's Z span the whole travel (the MAS MCVL 1000's file puts the workpiece
    // zero at the bottom of Z, and the tilted table takes the part 0.6 mm below it).
    std::vector<std::string> expectedWarnings;
    std::ifstream expectedFile(dir / "roundtrip-warnings");
    for (std::string line; std::getline(expectedFile, line);)
        expectedWarnings.push_back(line);
    // The machine's limits, checked again on what the NC does, give the warnings the post gave.
    std::ifstream warningsFile(dir / "expected.warnings");
    const std::string postWarned((std::istreambuf_iterator<char>(warningsFile)), std::istreambuf_iterator<char>());
    for (const Diagnostic& d : result.diagnostics) {
        const std::string listed = std::to_string(d.line) + ": " + d.message;
        const bool expectedHere =
            d.severity == Severity::Warning &&
            (std::find(expectedWarnings.begin(), expectedWarnings.end(), listed) != expectedWarnings.end() ||
             postWarned.find(d.message) != std::string::npos);
        if (!expectedHere &&
            (d.line < 1 || d.line > static_cast<int>(passThrough.size()) || passThrough[d.line - 1].empty()))
            ADD_FAILURE() << formatDiagnostic(d);
    }
    EXPECT_TRUE(result.completed) << nc;

    // G83/G73 count pecks from the R plane (LinuxCNC's G-code reference), the CL from the hole
    // top, and ISO has no word for the top: what the control does is the expectation.
    toolpath::Toolpath expected = cl.value().toolpath;
    if (result.files.size() && guessDialect("", nc.string()) == Dialect::Iso)
        expected = pecksFromRPlane(expected);

    MatchTolerance tolerance = writtenTolerance();
    // A five-axis CL (millimetre programs only) read through the chain: the tip within 0.001 mm
    // (three decimals put it at most 0.00087 mm off).
    const auto& records = expected.records();
    if (machine && machine->kinematics.fiveAxis() && caseProperty(dir, "units") != "inch" &&
        std::any_of(records.begin(), records.end(),
                    [](const auto& r) { return std::holds_alternative<toolpath::ToolAxisMove>(r); }))
        tolerance.pointMm = tolerance.backPointMm = 0.001;
    // Arcs the post linearises within 0.01 mm (its warnings say so): chords and arc may be that far apart.
    if (postWarned.find("written as lines within 0.01 mm") != std::string::npos)
        tolerance.pointMm = tolerance.backPointMm = 0.0125;
    // Machine coordinates (the iTNC post's tcpm=off, for the program or an operation): the machine
    // moves its axes linearly between blocks and the post cut the moves until the tip stays
    // within its tolerance of the CL.
    const auto& traced = recorder.toolpath().records();
    if (machine && std::any_of(traced.begin(), traced.end(), [](const toolpath::Record& r) {
            const auto* move = std::get_if<toolpath::ToolAxisMove>(&r);
            return move && move->jointInterpolated && move->feedMmPerMin > 0;
        })) {
        tolerance.machineMotion = &machine->kinematics;
        tolerance.pointMm += info.capabilities.toleranceMm;
        tolerance.backPointMm += info.capabilities.toleranceMm;
        tolerance.axisBetweenRad = 1e-3;
    }
    return matchMotion(recorder.toolpath(), expected, tolerance);
}

class PostRoundTrip : public testing::TestWithParam<PostCase> {};

TEST_P(PostRoundTrip, NcTracesBackToTheCl)
{
    const PostCase& c = GetParam();
    const fs::path nc = c.nc.empty() ? onlyFile(c.dir, "expected", ".warnings") : c.nc;
    ASSERT_FALSE(nc.empty()) << c.dir;
    const auto difference = roundTrip(c, nc);
    EXPECT_FALSE(difference) << nc << ": " << *difference;
}

// The iTNC post's expected.h of `caseName` with `from` replaced by `to`, written to a temporary
// file; empty when `from` is not in it.
fs::path mutatedKlartext(const std::string& caseName, const std::string& from, const std::string& to)
{
    const fs::path dir = fs::path(CAMWB_TEST_DATA_DIR) / "posts/heidenhain-itnc530/tests" / caseName;
    std::ifstream in(dir / "expected.h");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos)
        return {};
    text.replace(at, from.size(), to);
    const fs::path mutated = fs::path(testing::TempDir()) / ("mutated-" + caseName + ".h");
    std::ofstream(mutated) << text;
    return mutated;
}

// The round trip must be able to fail: the example job's Klartext with one coordinate moved by
// 0.1 mm, and the thesis case with its plunge feed parameter changed, no longer move as their CL.
std::optional<std::string> klartextDifference(const std::string& caseName, const std::string& from,
                                              const std::string& to, const fs::path& clFile)
{
    const fs::path mutated = mutatedKlartext(caseName, from, to);
    if (mutated.empty())
        return std::nullopt;
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

// A five-axis case of the iTNC post with one word changed, read back through its machine as the
// golden itself is.
std::optional<std::string> fiveAxisDifference(const std::string& caseName, const std::string& from,
                                              const std::string& to)
{
    const fs::path mutated = mutatedKlartext(caseName, from, to);
    if (mutated.empty())
        return std::nullopt;
    const fs::path root = CAMWB_TEST_DATA_DIR;
    return roundTrip(
        {caseName, root / "posts/heidenhain-itnc530/tests" / caseName, {}, {}, root / "posts/heidenhain-itnc530.js"},
        mutated);
}

// A C word 0.01 degree off turns the tool axis 9e-5 rad (with M128 the tip stays); without TCPM
// it moves the tip too; a tip 0.02 mm off the CL is beyond the 0.0125 mm the off mode allows.
TEST(PostRoundTripCanFail, AFiveAxisAngleOrTipOff)
{
    const auto angle = fiveAxisDifference("five-axis-m128", "L X-10 Y+17.321 C-120", "L X-10 Y+17.321 C-120.01");
    ASSERT_TRUE(angle);
    EXPECT_NE(angle->find("tool axis differs"), std::string::npos) << *angle;
    EXPECT_TRUE(fiveAxisDifference("five-axis-off", "L X+10 Y+0 Z+22.68 C-120", "L X+10 Y+0 Z+22.68 C-120.01"));
    EXPECT_TRUE(fiveAxisDifference("five-axis-off", "L X+11.431 Z+15.816 B-15", "L X+11.451 Z+15.816 B-15"));
    EXPECT_FALSE(fiveAxisDifference("five-axis-off", "L X+11.431 Z+15.816 B-15", "L X+11.431 Z+15.816 B-15"));
}

// The same CL posted with tool-tip control (M128, FUNCTION TCPM) and in machine coordinates
// (tcpm=off) moves the tool alike in the workpiece frame: each mode's NC, read back through the
// MAS MCVL 1000, against the M128 program's (within the off mode's linearisation tolerance).
TEST(PostRoundTripModes, TcpmAndMachineCoordinatesMoveTheToolAlike)
{
    const fs::path cases = fs::path(CAMWB_TEST_DATA_DIR) / "posts/heidenhain-itnc530/tests";
    auto machine =
        kinematics::findMachine("mas-mcvl1000", {(fs::path(CAMWB_TEST_DATA_DIR) / "resources/machines").string()});
    ASSERT_TRUE(machine) << machine.error().toString();
    auto trace = [&](const std::string& caseName) {
        InterpretOptions options;
        options.machine = &machine.value();
        toolpath::ToolpathRecorder recorder;
        const InterpretResult result =
            interpretFile((cases / caseName / "expected.h").string(), std::nullopt, options, recorder);
        EXPECT_TRUE(result.completed) << caseName;
        return recorder.toolpath();
    };
    const toolpath::Toolpath m128 = trace("five-axis-m128");
    MatchTolerance tolerance;
    tolerance.pointMm = tolerance.backPointMm = 0.002;
    EXPECT_FALSE(matchMotion(trace("five-axis-function-tcpm"), m128, tolerance));
    tolerance.pointMm += 0.01;
    tolerance.axisBetweenRad = 1e-3;
    tolerance.machineMotion = &machine.value().kinematics;
    const auto off = matchMotion(trace("five-axis-off"), m128, tolerance);
    EXPECT_FALSE(off) << *off;
}

// The working plane counts: the CYCLE800 case with one plane's angle or origin changed in the NC
// no longer moves as its CL (read back through its machine, as the golden itself is).
std::optional<std::string> swivelDifference(const std::string& from, const std::string& to)
{
    const fs::path root = CAMWB_TEST_DATA_DIR;
    const fs::path dir = root / "posts/sinumerik840d/tests/planes-cycle800";
    std::ifstream in(dir / "expected.mpf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos)
        return std::nullopt;
    text.replace(at, from.size(), to);
    const fs::path mutated = fs::path(testing::TempDir()) / "mutated-planes-cycle800.mpf";
    std::ofstream(mutated) << text;
    return roundTrip({"planes-cycle800", dir, {}, {}, root / "posts/sinumerik840d.js"}, mutated);
}

TEST(PostRoundTripCanFail, AChangedPlaneAngleOrOrigin)
{
    const std::string plane = "CYCLE800(1,\"TC1\",0,27,0.000,0.000,0.000,0,-30,0,0,0,0,1)";
    EXPECT_FALSE(swivelDifference(plane, plane));  // unchanged it matches
    EXPECT_TRUE(swivelDifference(plane, "CYCLE800(1,\"TC1\",0,27,0.000,0.000,0.000,0,-30.1,0,0,0,0,1)"));
    EXPECT_TRUE(swivelDifference(plane, "CYCLE800(1,\"TC1\",0,27,0.000,0.000,0.000,0.1,-30,0,0,0,0,1)"));
    EXPECT_TRUE(swivelDifference(plane, "CYCLE800(1,\"TC1\",0,27,0.100,0.000,0.000,0,-30,0,0,0,0,1)"));
}

INSTANTIATE_TEST_SUITE_P(PostGoldens, PostRoundTrip, testing::ValuesIn(postCases()),
                         [](const testing::TestParamInfo<PostCase>& info) { return info.param.name; });

}  // namespace
}  // namespace camwb::nc::test
