// The thesis' program as the oracle (seed REQ-14, spec): KOD5.MPF calling the reconstructed
// subprograms of seed §4.3, read by the SINUMERIK interpreter, against computeGroove with Kod 1,
// block by block; and the plunge counts of REQ-10 pass by pass.
#include "GrooveTestUtil.h"
#include "nc/Interpreter.h"
#include "ops/turning/GrooveSweeps.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace camwb::ops::test {
namespace {

std::string dataDir() { return std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/seed-001"; }

toolpath::Toolpath traceKod5()
{
    nc::InterpretOptions options;
    options.dialect = nc::Dialect::Sinumerik;
    options.fileName = dataDir() + "/KOD5.MPF";
    options.resolveProgram = nc::folderResolver(dataDir() + "/reconstructed", {".SPF"});
    std::ifstream in(options.fileName, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult result = nc::interpret(text.str(), options, recorder);
    EXPECT_TRUE(result.completed);
    EXPECT_FALSE(result.hasErrors());
    return recorder.take();
}

turning::GrooveSetup kod1Setup() { return {sim::grooveGeometry({}), 3, 0.8, 1, 1}; }

// Alignment: KOD5.MPF's own move N68 G0 X=R0+200 (file 0) is where the caller parks the tool; the
// operation's counterpart is its first Rapid to X = R0 + finalRetractMm. Both are left out; from
// PODPROG_ZAPICH's N72 G0 Z=R24 on, move k of the subprograms (files 1..5) is move k + 1 of the
// operation, up to and including DNO_ZL's N240 G0 X=R0+100 (the operation's last rapid). N72
// G0 Z=R24 still has the caller's X (KOD5's R0 is 0 when N68 runs: X 200; the operation's 280),
// so move 0's X is not compared; every X after it is the strategy's own.
TEST(GrooveOracle, Req14Kod1IsTheThesisProgramBlockByBlock)
{
    const std::vector<ResolvedMove> nc =
        resolvedMoves(traceKod5(), [](const toolpath::SourceRef& s) { return s.file > 0; });
    auto computed = computeGroove({}, grooveTool(), 0);
    ASSERT_TRUE(computed.ok()) << computed.error().message;
    std::vector<ResolvedMove> op = resolvedMoves(computed->toolpath);
    ASSERT_FALSE(op.empty());
    EXPECT_TRUE(op.front().rapid);
    EXPECT_EQ(op.front().axes, toolpath::AxisMask{toolpath::AxisMask::kX});
    EXPECT_DOUBLE_EQ(op.front().x, 280);
    op.erase(op.begin());
    ASSERT_EQ(nc.size(), 574u);
    ASSERT_EQ(op.size(), nc.size());
    int rapids = 0;
    for (std::size_t k = 0; k < nc.size(); ++k) {
        SCOPED_TRACE("move " + std::to_string(k));
        ASSERT_EQ(op[k].rapid, nc[k].rapid);
        if (k > 0)
            EXPECT_NEAR(op[k].x, nc[k].x, 1e-4);
        EXPECT_NEAR(op[k].z, nc[k].z, 1e-4);
        rapids += op[k].rapid;
    }
    EXPECT_EQ(rapids, 574 - 203);
}

// REQ-14's figures: the call sequence, four passes, the path lengths. The seed's lengths leave
// out the approach N72 G0 Z, N73 G0 X (they start wherever the caller left the tool).
TEST(GrooveOracle, Req14CallsAndPathLengths)
{
    auto moves = turning::grooveMoves(kod1Setup(), "groove", {});
    ASSERT_TRUE(moves.ok());
    EXPECT_EQ(moves->calls, (std::vector<std::string>{"ZL", "ZP", "ZL", "ZP", "ZL", "ZP", "ZL", "DNO_ZL"}));
    EXPECT_EQ(moves->passes.size(), 4u);
    EXPECT_FALSE(moves->fallback);
    auto computed = computeGroove({}, grooveTool(), 0);
    ASSERT_TRUE(computed.ok());
    const std::vector<ResolvedMove> op = resolvedMoves(computed->toolpath);
    double feed = 0, rapid = 0;
    for (std::size_t k = 3; k < op.size(); ++k)  // op[1], op[2]: N72, N73
        (op[k].rapid ? rapid : feed) += std::hypot(op[k].x - op[k - 1].x, op[k].z - op[k - 1].z);
    EXPECT_NEAR(feed, 4662.5, 0.05);
    EXPECT_NEAR(rapid, 5251.4, 0.05);
}

// REQ-10: L1, L2 rounded by ROUNDUP(L - 1), B and the next Rp (Z, X) in passes 1 to 3.
TEST(GrooveOracle, Req10PlungeCountsOfKod1)
{
    auto moves = turning::grooveMoves(kod1Setup(), "groove", {});
    ASSERT_TRUE(moves.ok());
    ASSERT_GE(moves->passes.size(), 3u);
    const turning::GroovePass& p1 = moves->passes[0];
    EXPECT_NEAR(p1.l1, 26.815956, 1e-6);
    EXPECT_EQ(p1.r27, 26);
    EXPECT_NEAR(p1.bz, 177.930644, 1e-6);
    EXPECT_NEAR(p1.bx, 124.191159, 1e-6);
    EXPECT_NEAR(p1.l2, 25.326730, 1e-6);
    EXPECT_EQ(p1.r28, 25);
    EXPECT_NEAR(p1.rpz, 114.1231, 5e-5);
    EXPECT_NEAR(p1.rpx, 99.1912, 5e-5);
    const turning::GroovePass& p2 = moves->passes[1];
    EXPECT_EQ(p2.r27, 22);
    EXPECT_EQ(p2.r28, 21);
    EXPECT_NEAR(p2.bz, 172.4011, 5e-5);
    EXPECT_NEAR(p2.bx, 77.1912, 5e-5);
    EXPECT_NEAR(p2.rpz, 117.1979, 5e-5);
    EXPECT_NEAR(p2.rpx, 56.1912, 5e-5);
    const turning::GroovePass& p3 = moves->passes[2];
    EXPECT_EQ(p3.r27, 19);
    EXPECT_EQ(p3.r28, 18);
    EXPECT_NEAR(p3.bz, 167.6951, 5e-5);
    EXPECT_NEAR(p3.bx, 37.1912, 5e-5);
    EXPECT_NEAR(p3.rpz, 119.8436, 5e-5);
    EXPECT_NEAR(p3.rpx, 19.1912, 5e-5);
}

// The records around the moves (GrooveOp.h): section, feed per revolution, G96 spindle, coolant.
TEST(GrooveOracle, SectionRecordsAndParameters)
{
    GrooveParams params;
    params.name = "Kod 1";
    auto computed = computeGroove(params, grooveTool(), 3);
    ASSERT_TRUE(computed.ok());
    const toolpath::Toolpath& path = computed->toolpath;
    ASSERT_GE(path.size(), 6u);
    const auto& begin = std::get<toolpath::SectionBegin>(path.record(0));
    EXPECT_EQ(begin.operationName, "Kod 1");
    EXPECT_EQ(begin.strategy, "groove-roughing");
    EXPECT_EQ(begin.toolNumber, 5);
    EXPECT_DOUBLE_EQ(begin.feeds.cuttingMmPerMin, 0.2);
    std::vector<std::string> names;
    for (const auto& [name, value] : begin.strategyParameters)
        names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"R0", "R1", "R2", "R3", "R4", "R5", "R6", "R7", "R8", "R9", "R10", "R11",
                                               "R30", "fallback"}));
    EXPECT_DOUBLE_EQ(begin.strategyParameters[9].second, 3);
    EXPECT_DOUBLE_EQ(begin.strategyParameters.back().second, 0);
    EXPECT_EQ(std::get<toolpath::FeedModeChange>(path.record(1)).mode, toolpath::FeedMode::PerRevolution);
    const auto& spindle = std::get<toolpath::Spindle>(path.record(2));
    EXPECT_DOUBLE_EQ(spindle.rpm, 3000);
    EXPECT_DOUBLE_EQ(spindle.surfaceSpeedMPerMin, 300);
    EXPECT_TRUE(spindle.clockwise);
    EXPECT_EQ(std::get<toolpath::Coolant>(path.record(3)).mode, toolpath::CoolantMode::Flood);
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionEnd>(path.record(path.size() - 1)));
    const auto& last = std::get<toolpath::Rapid>(path.record(path.size() - 2));
    EXPECT_DOUBLE_EQ(last.to.x, 280);
    for (std::size_t i = 0; i < path.size(); ++i) {
        EXPECT_EQ(path.source(i).operationIndex, 3);
        EXPECT_EQ(path.source(i).recordIndex, static_cast<int>(i));
        if (const auto* l = std::get_if<toolpath::Linear>(&path.record(i))) {
            EXPECT_EQ(l->axes, toolpath::AxisMask{toolpath::AxisMask::kX | toolpath::AxisMask::kZ});
            EXPECT_DOUBLE_EQ(l->feedMmPerMin, 0.2);
            EXPECT_EQ(l->feedKind, toolpath::FeedKind::Cutting);
        }
    }
    params.coolant = false;
    auto dry = computeGroove(params, grooveTool(), 3);
    ASSERT_TRUE(dry.ok());
    EXPECT_FALSE(std::holds_alternative<toolpath::Coolant>(dry->toolpath.record(3)));
}

// The path is the sharp insert's (REQ-07): a corner radius only warns that fillets stay for the
// finishing; one wider than half the insert is an error; a sharp insert gets no warning.
TEST(GrooveOracle, CornerRadiusWarnsAndIsBoundedByTheWidth)
{
    GrooveParams params;
    auto sharp = computeGroove(params, grooveTool(), 0);
    ASSERT_TRUE(sharp.ok());
    EXPECT_TRUE(sharp->warnings.empty());
    ToolController rounded = grooveTool();
    rounded.tool.cornerRadiusMm = 0.4;
    auto withRadius = computeGroove(params, rounded, 0);
    ASSERT_TRUE(withRadius.ok());
    ASSERT_EQ(withRadius->warnings.size(), 1u);
    EXPECT_NE(withRadius->warnings[0].message.find("corner radius of 0.4 mm leaves fillets"), std::string::npos)
        << withRadius->warnings[0].message;
    EXPECT_EQ(withRadius->toolpath.size(), sharp->toolpath.size());
    rounded.tool.cornerRadiusMm = 1.6;
    auto tooLarge = computeGroove(params, rounded, 0);
    ASSERT_FALSE(tooLarge.ok());
    EXPECT_NE(tooLarge.error().message.find("corner radius must be between 0 and half its width (1.5 mm)"),
              std::string::npos)
        << tooLarge.error().message;
}

// REQ-25: a strategy that runs past its iteration limit stops with an error, not a hang (Kod 1
// needs a few hundred turns of its loops; 50 cannot finish it).
TEST(GrooveOracle, IterationLimitStopsWithAnError)
{
    turning::GrooveSetup setup = kod1Setup();
    setup.iterationLimit = 50;
    auto moves = turning::grooveMoves(setup, "groove \"K\"", {});
    ASSERT_FALSE(moves.ok());
    EXPECT_EQ(moves.error().message, "groove \"K\": the groove strategy did not finish within 50 steps (seed REQ-25); "
                                     "please report the parameters");
    setup.iterationLimit = 1000;
    EXPECT_TRUE(turning::grooveMoves(setup, "groove", {}).ok());
}

TEST(GrooveOracle, CancelledProducesNothing)
{
    std::atomic<bool> cancel{true};
    Progress progress;
    progress.cancel = &cancel;
    auto computed = computeGroove({}, grooveTool(), 0, progress);
    ASSERT_FALSE(computed.ok());
    EXPECT_EQ(computed.error().message, "groove \"Groove\": cancelled");
}

}  // namespace
}  // namespace camwb::ops::test
