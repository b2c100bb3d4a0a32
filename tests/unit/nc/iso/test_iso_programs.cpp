// Whole programs: the LinuxCNC post's goldens read back without a diagnostic, and smoke tests.
#include "IsoTestSupport.h"

#include "nc/ToolTable.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace camwb::nc::iso::test {
namespace {

std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(IsoPrograms, SmokeTrace)
{
    const IsoRun r = run("%\nG21 G90 G17\nG0 X1 Y2 Z3\nG1 X4 F100\nG2 X6 Y2 I1 J0\nM2\n%\n");
    EXPECT_EQ(r.diagnostics(), "");
    EXPECT_TRUE(r.result.completed);
    EXPECT_EQ(r.trace, "3 rapid 1.0000 2.0000 3.0000 s 0.0000 t 0\n"
                       "4 linear 4.0000 2.0000 3.0000 f 100.0000 s 0.0000 t 0\n"
                       "5 arc cw 6.0000 2.0000 3.0000 c 5.0000 2.0000 3.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000 "
                       "s 0.0000 t 0\n");
}

TEST(IsoPrograms, LinuxCncPostGoldensReadWithoutDiagnostics)
{
    const std::filesystem::path root = std::filesystem::path(CAMWB_TEST_DATA_DIR) / "posts/linuxcnc/tests";
    int cases = 0;
    for (const auto& dir : std::filesystem::directory_iterator(root)) {
        const auto ngc = dir.path() / "expected.ngc";
        if (!std::filesystem::exists(ngc))
            continue;
        ++cases;
        // Tools of radius 0, so that compensated goldens read as written (the compensation itself
        // is compared with rs274 in tests/external).
        ToolTable tools;
        for (int n = 0; n <= 20; ++n)
            tools.set({n, n, 0.0, 0.0, {}});
        InterpretOptions options;
        options.toolTable = &tools;
        const IsoRun r = run(readFile(ngc), options);
        // The every-record CL passes SINUMERIK text through ("TRANS X10"): LinuxCNC refuses it too.
        const bool passThrough = dir.path().filename() == "every-record";
        EXPECT_EQ(r.diagnostics(),
                  passThrough ? "31:1: error: unknown word TRANSX (a letter and a number expected)\n" : "")
            << ngc;
        EXPECT_TRUE(r.result.completed) << ngc;
    }
    EXPECT_GE(cases, 5);
}

}  // namespace
}  // namespace camwb::nc::iso::test
