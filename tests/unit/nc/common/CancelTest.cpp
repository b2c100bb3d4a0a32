// A superseded trace stops: with the cancel flag set, every dialect gives up within
// kCancelCheckBlocks blocks, marks the result cancelled and says nothing about it.
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

namespace camwb::nc {
namespace {

// 5000 straight moves in the dialect's own words.
std::string longProgram(Dialect dialect)
{
    std::string text = dialect == Dialect::Heidenhain ? "0 BEGIN PGM LONG MM\n" : "";
    for (int i = 1; i <= 5000; ++i) {
        const std::string x = std::to_string(i % 100);
        text += dialect == Dialect::Heidenhain ? std::to_string(i) + " L X+" + x + " Y+0 F500\n"
                                               : "G1 X" + x + " Y0 F500\n";
    }
    if (dialect == Dialect::Heidenhain)
        text += "5001 END PGM LONG MM\n";
    return text;
}

class Cancel : public testing::TestWithParam<Dialect> {};

TEST_P(Cancel, StopsWithinACheckIntervalWithoutADiagnostic)
{
    const std::string text = longProgram(GetParam());
    InterpretOptions options;
    options.dialect = GetParam();

    toolpath::ToolpathRecorder whole;
    const InterpretResult full = interpret(text, options, whole);
    EXPECT_FALSE(full.cancelled);
    EXPECT_TRUE(full.completed);
    EXPECT_GE(whole.toolpath().size(), 5000u);

    std::atomic<bool> cancel{true};
    options.cancel = &cancel;
    toolpath::ToolpathRecorder part;
    const InterpretResult stopped = interpret(text, options, part);
    EXPECT_TRUE(stopped.cancelled);
    EXPECT_FALSE(stopped.completed);
    EXPECT_TRUE(stopped.diagnostics.empty());
    EXPECT_LE(stopped.blocksExecuted, kCancelCheckBlocks);
    EXPECT_LT(part.toolpath().size(), whole.toolpath().size());
}

INSTANTIATE_TEST_SUITE_P(EveryDialect, Cancel, testing::Values(Dialect::Sinumerik, Dialect::Heidenhain, Dialect::Iso),
                         [](const testing::TestParamInfo<Dialect>& info) { return dialectName(info.param); });

}  // namespace
}  // namespace camwb::nc
