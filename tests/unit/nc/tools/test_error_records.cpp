// Records of blocks with an error: flagged by file and line (main program and called programs),
// and left out of the program statistics (an arc whose radii disagree adds no bulge, no length).
#include "nc/tools/ErrorRecords.h"
#include "toolpath/ProgramStats.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

using namespace camwb::nc;
namespace tp = camwb::toolpath;
using camwb::base::Vec3;

namespace {

struct Traced {
    tp::Toolpath program;
    InterpretResult result;
};

Traced traceIso(const std::string& text)
{
    tp::ToolpathRecorder recorder;
    InterpretOptions options;
    options.dialect = Dialect::Iso;
    options.fileName = "bad-arc.ngc";
    Traced traced;
    traced.result = interpret(text, options, recorder);
    traced.program = recorder.take();
    return traced;
}

// Line 4: the radius is 100 at the start and 90 at the end.
const char* const kBadArc = "G21 G90 G17\nG0 X0 Y0 Z0\nG1 X10 F100\nG2 X20 Y0 I100 J0\nG1 X30\nM30\n";

}  // namespace

TEST(ErrorRecords, FlagsTheRecordsOfErrorLines)
{
    const Traced t = traceIso(kBadArc);
    ASSERT_TRUE(t.result.hasErrors());
    const std::vector<bool> flags = recordsInError(t.program, t.result);
    ASSERT_EQ(flags.size(), t.program.size());
    int flagged = 0;
    for (std::size_t i = 0; i < flags.size(); ++i) {
        EXPECT_EQ(flags[i], t.program.source(i).line == 4) << "record " << i;
        flagged += flags[i] ? 1 : 0;
    }
    EXPECT_EQ(flagged, 1);
    EXPECT_TRUE(std::holds_alternative<tp::Arc>(
        t.program.record(std::size_t(std::find(flags.begin(), flags.end(), true) - flags.begin()))));
}

TEST(ErrorRecords, NoErrorsNoFlags)
{
    const Traced t = traceIso("G0 X0 Y0 Z0\nG1 X10 F100\nG2 X20 Y0 I5 J0\nM30\n");
    EXPECT_FALSE(t.result.hasErrors());
    EXPECT_TRUE(recordsInError(t.program, t.result).empty());
}

TEST(ErrorRecords, CalledProgramsByFileIndex)
{
    tp::Toolpath program;
    program.add(tp::Linear{{1, 0, 0}, 100}, tp::SourceRef{-1, -1, 3, 0});
    program.add(tp::Linear{{2, 0, 0}, 100}, tp::SourceRef{-1, -1, 3, 1});  // line 3 of SUB.SPF
    program.add(tp::Linear{{3, 0, 0}, 100}, tp::SourceRef{-1, -1, 4, 1});
    InterpretResult result;
    result.files = {"MAIN.MPF", "SUB.SPF"};
    result.diagnostics.push_back({Severity::Error, "SUB.SPF", 3, 1, "bad"});
    result.diagnostics.push_back({Severity::Warning, "SUB.SPF", 4, 1, "doubtful, not wrong"});
    result.diagnostics.push_back({Severity::Error, "OTHER.SPF", 4, 1, "never read"});
    EXPECT_EQ(recordsInError(program, result), (std::vector<bool>{false, true, false}));
}

TEST(ErrorRecords, StatisticsLeaveThemOut)
{
    const Traced t = traceIso(kBadArc);
    const tp::ProgramStats all = tp::programStats(t.program);
    EXPECT_GT(all.totals.cuttingExtents.max.y - all.totals.cuttingExtents.min.y, 100);  // the wrong circle
    const std::vector<bool> flags = recordsInError(t.program, t.result);
    tp::StatsOptions options;
    options.recordsInError = &flags;
    const tp::ProgramStats s = tp::programStats(t.program, options);
    EXPECT_EQ(s.movesLeftOut, 1);
    EXPECT_EQ(s.arcs, 0);
    EXPECT_EQ(s.totals.cuttingExtents.min, (Vec3{0, 0, 0}));
    EXPECT_EQ(s.totals.cuttingExtents.max, (Vec3{30, 0, 0}));
    EXPECT_DOUBLE_EQ(s.totals.feedLengthMm, 20);  // X0 -> X10 and X20 -> X30: the next move starts at the arc's end
    EXPECT_NEAR(s.totals.feedSeconds, 20.0 / 100 * 60, 1e-9);
}
