// Our plain ISO interpreter against LinuxCNC's own (`rs274`) on the same programs: the ISO
// goldens that read without errors (tests/golden/nc/iso) and the LinuxCNC post's goldens. Our
// records, turned into what LinuxCNC does with them by the same model the post round trip uses
// (cycles expanded into LinuxCNC's moves, M6 and M2 side effects: LinuxCncModel.h), must be the
// motion rs274 prints, within the written precision.
#include "LinuxCncModel.h"
#include "MotionCompare.h"
#include "Rs274Runner.h"
#include "Rs274Trace.h"

#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace camwb::external::test {
namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    fs::path ngc;
};

std::vector<Case> cases()
{
    const fs::path root(CAMWB_TEST_DATA_DIR);
    std::vector<Case> out;
    // Left out: canned-cycles (G86 spindle stop and rapid out, which CL cycles cannot say) and
    // units-and-feed-modes (rs274 prints inch programs in inches; Rs274Trace reads program units).
    for (const char* name :
         {"milling-program", "arcs-planes", "parameters-expressions", "subroutines-loops", "masked-first-moves"})
        out.push_back({std::string("iso_") + name, root / "tests/golden/nc/iso" / name / "input.ngc"});
    for (const char* name : {"arcs", "cycles", "nx-cls", "freecad-dump"})
        out.push_back({std::string("post_") + name, root / "posts/linuxcnc/tests" / name / "expected.ngc"});
    for (Case& c : out)
        for (char& ch : c.name)
            if (ch == '-')
                ch = '_';
    return out;
}

class IsoAgainstRs274 : public testing::TestWithParam<Case> {};

TEST_P(IsoAgainstRs274, SameMotion)
{
    const Case& c = GetParam();
    const fs::path dir = fs::path(testing::TempDir()) / ("camwb-iso-rs274-" + std::to_string(::getpid())) / c.name;
    fs::create_directories(dir);
    std::vector<Rs274Tool> tools;
    for (int n = 1; n <= 20; ++n)
        tools.push_back({n, 10.0 * n + 0.5, 0});
    const std::string toolTable = (dir / "tools.tbl").string();
    ASSERT_TRUE(writeRs274ToolTable(toolTable, tools).ok());

    auto run = runRs274(CAMWB_RS274, c.ngc.string(), toolTable, dir.string());
    ASSERT_TRUE(run.ok()) << run.error().toString();
    ASSERT_EQ(run.value().exitCode, 0) << run.value().errors;
    auto theirs = readRs274Trace(run.value().trace);
    ASSERT_TRUE(theirs.ok()) << theirs.error().toString();

    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult ours = nc::interpretFile(c.ngc.string(), nc::Dialect::Iso, {}, recorder);
    for (const nc::Diagnostic& d : ours.diagnostics)
        EXPECT_NE(d.severity, nc::Severity::Error) << nc::formatDiagnostic(d);

    const auto difference = compareMotion(expectedMotion(recorder.toolpath(), false), theirs.value().motion);
    EXPECT_FALSE(difference) << c.ngc << ": " << *difference;
    if (!HasFailure())
        fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Programs, IsoAgainstRs274, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace camwb::external::test
