// The NC listings of the reference theses that no single dialect's tests own: they must read
// with warnings at most (five-axis words, elided blocks), never errors. The SINUMERIK and
// Heidenhain listings are tested in their dialects' folders.
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

namespace camwb::nc {
namespace {

const std::string kData = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/reference/";

bool anyMentions(const std::vector<Diagnostic>& diagnostics, const std::string& text)
{
    for (const Diagnostic& d : diagnostics)
        if (d.message.find(text) != std::string::npos)
            return true;
    return false;
}

// seed-002 §5.2: the Hurco VMX 42SR program (ISO with G71, B/C axes, M128, "...." elisions).
TEST(ReferenceListing, HurcoFiveAxisProgramReadsWithWarningsOnly)
{
    toolpath::ToolpathRecorder recorder;
    const InterpretResult result = interpretFile(kData + "seed-002-hurco-vmx42sr.nc", std::nullopt, {}, recorder);
    for (const Diagnostic& d : result.diagnostics)
        EXPECT_NE(d.severity, Severity::Error) << formatDiagnostic(d);
    EXPECT_FALSE(result.diagnostics.empty());
    EXPECT_TRUE(anyMentions(result.diagnostics, "five-axis"));
}

}  // namespace
}  // namespace camwb::nc
