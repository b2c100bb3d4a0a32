// Cutter compensation against LinuxCNC's own (`rs274 -t <tool table>`) with tools of non-zero
// diameter: the ISO interpreter's compensated path (nc/CutterCompensation.h with LinuxCNC's rules)
// must be the tool-centre path rs274 prints, within the written precision. The programs: the ISO
// compensation golden (outside and inside corners, arcs into arcs, a helix, rapids, G41.1) and
// the LinuxCNC post's compensated golden, each with its tools' diameters.
#include "LinuxCncModel.h"
#include "MotionCompare.h"
#include "Rs274Runner.h"
#include "Rs274Trace.h"

#include "nc/Interpreter.h"
#include "nc/ToolTable.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <unistd.h>

namespace camwb::external::test {
namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    fs::path ngc;
    nc::ToolTable tools;
};

std::vector<Case> cases()
{
    const fs::path root(CAMWB_TEST_DATA_DIR);
    std::vector<Case> out;
    const fs::path golden = root / "tests/golden/nc/iso/cutter-comp";
    auto table = nc::readToolTable((golden / "tools.tbl").string());
    out.push_back({"iso_golden", golden / "input.ngc", table ? table.value() : nc::ToolTable{}});
    // The post's CL: T1 6 mm and T2 10 mm (posts/linuxcnc/tests/cutter-comp/input.trace).
    nc::ToolTable postTools;
    postTools.set({1, 1, 6.0, 40.0, {}});
    postTools.set({2, 2, 10.0, 40.0, {}});
    out.push_back({"post_golden", root / "posts/linuxcnc/tests/cutter-comp/expected.ngc", postTools});
    // Smaller and larger tools on the same post program: other corners become tangent, inside
    // corners trim further.
    nc::ToolTable other;
    other.set({1, 1, 2.0, 40.0, {}});
    other.set({2, 2, 16.0, 40.0, {}});
    out.push_back({"post_golden_other_tools", out.back().ngc, other});
    return out;
}

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class CutterCompAgainstRs274 : public testing::TestWithParam<Case> {};

TEST_P(CutterCompAgainstRs274, SameToolCentrePath)
{
    const Case& c = GetParam();
    ASSERT_FALSE(c.tools.empty()) << c.name << ": no tools";
    const fs::path dir = fs::path(testing::TempDir()) / ("camwb-comp-rs274-" + std::to_string(::getpid())) / c.name;
    fs::create_directories(dir);
    std::vector<Rs274Tool> rs274Tools;
    for (const auto& [number, tool] : c.tools.tools())
        rs274Tools.push_back({number, tool.lengthMm, tool.diameterMm});
    const std::string toolTable = (dir / "tools.tbl").string();
    ASSERT_TRUE(writeRs274ToolTable(toolTable, rs274Tools).ok());

    auto run = runRs274(CAMWB_RS274, c.ngc.string(), toolTable, dir.string());
    ASSERT_TRUE(run.ok()) << run.error().toString();
    ASSERT_EQ(run.value().exitCode, 0) << run.value().errors;
    auto theirs = readRs274Trace(run.value().trace);
    ASSERT_TRUE(theirs.ok()) << theirs.error().toString();

    nc::InterpretOptions options;
    options.toolTable = &c.tools;
    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult ours = nc::interpretFile(c.ngc.string(), nc::Dialect::Iso, options, recorder);
    EXPECT_TRUE(ours.diagnostics.empty()) << nc::formatDiagnostic(ours.diagnostics.front());

    const auto difference = compareMotion(expectedMotion(recorder.toolpath(), false), theirs.value().motion);
    EXPECT_FALSE(difference) << c.ngc << ": " << *difference;
    if (!HasFailure())
        fs::remove_all(dir);
}

// A tool too large for an inside corner or arc: rs274 stops with an error, the trace reports one.
TEST(CutterCompAgainstRs274, BothRefuseATooLargeTool)
{
    const fs::path ngc = fs::path(CAMWB_TEST_DATA_DIR) / "posts/linuxcnc/tests/cutter-comp/expected.ngc";
    const fs::path dir = fs::path(testing::TempDir()) / ("camwb-comp-rs274-" + std::to_string(::getpid())) / "large";
    fs::create_directories(dir);
    const std::string toolTable = (dir / "tools.tbl").string();
    ASSERT_TRUE(writeRs274ToolTable(toolTable, {{1, 40, 6}, {2, 40, 24}}).ok());  // R12 in an R10 corner
    auto run = runRs274(CAMWB_RS274, ngc.string(), toolTable, dir.string());
    ASSERT_TRUE(run.ok()) << run.error().toString();
    EXPECT_NE(run.value().exitCode, 0) << "rs274 accepted a 24 mm tool in the pocket";

    nc::ToolTable tools;
    tools.set({1, 1, 6, 40, {}});
    tools.set({2, 2, 24, 40, {}});
    nc::InterpretOptions options;
    options.toolTable = &tools;
    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult ours = nc::interpretFile(ngc.string(), nc::Dialect::Iso, options, recorder);
    EXPECT_TRUE(ours.hasErrors());
    fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Programs, CutterCompAgainstRs274, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace camwb::external::test
