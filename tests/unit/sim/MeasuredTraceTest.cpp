// Measured traces: a TNCscope-style CSV with decimal commas, configurable columns and units,
// errors at file:line:column, nominal and actual carried onto the workpiece through the chain,
// their deviation, and each sample's distance to the programmed path (checked against a brute
// force search on a long zig-zag).
#include "sim/MeasuredTrace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace camwb;

namespace {

const std::string kDir = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/sim/";

std::string messageOf(const std::string& text, const sim::TraceColumns& columns = {})
{
    auto trace = sim::readMeasuredTrace(text, "trace.csv", columns);
    EXPECT_FALSE(trace.ok());
    return trace.ok() ? std::string() : trace.error().toString();
}

kinematics::KinematicChain seed003Chain()
{
    kinematics::KinematicChain chain;
    chain.type = kinematics::ChainType::TableTable;
    chain.joints = {{"A", true, {-1, 0, 0}, {}}, {"C", true, {0, 0, -1}, {}}};
    return chain;
}

}  // namespace

TEST(MeasuredTrace, ReadsTheThesisLayoutWithDecimalCommas)
{
    auto trace = sim::loadMeasuredTrace(kDir + "tncscope-trace.csv");
    ASSERT_TRUE(trace.ok()) << trace.error().toString();
    ASSERT_EQ(trace->time.size(), 4u);
    EXPECT_DOUBLE_EQ(trace->time[3], 0.009);
    EXPECT_DOUBLE_EQ(trace->actual[0][1], 2.311);
    EXPECT_DOUBLE_EQ(trace->nominal[0][1], 2.312);
    EXPECT_DOUBLE_EQ(trace->deviation[0][1], 0.001);
    // The thesis' sample vector, read from the file, through the (three-axis) chain.
    const sim::Trace actual = sim::workpieceTrace(trace.value(), true, kinematics::KinematicChain{});
    const sim::PathAnalysis a = sim::analysePath(actual, false);
    EXPECT_NEAR(a.linearVelocity[0].value[0], 3.000, 1e-3);
    EXPECT_NEAR(a.linearVelocity[0].value[2], 1.3333, 1e-3);
    EXPECT_NEAR(a.linearAcceleration[0].value[1], -444.44, 1e-2);
    const sim::Trace nominal = sim::workpieceTrace(trace.value(), false, kinematics::KinematicChain{});
    const auto d = sim::deviationDistance(nominal, actual);
    EXPECT_NEAR(d[1], 0.001, 1e-12);
    EXPECT_NEAR(d[3], 0, 1e-12);
}

TEST(MeasuredTrace, ColumnsAndUnitsAreConfigurable)
{
    sim::TraceColumns columns;
    columns.headerLines = 0;
    columns.time = 2;  // ms in the third column, X in µm in the first; nothing else
    columns.nominal = {0, -1, -1, -1, -1};
    columns.actual = {-1, -1, -1, -1, -1};
    columns.deviation = {-1, -1, -1, -1, -1};
    columns.timeScale = 0.001;
    columns.linearScale = 0.001;
    auto trace = sim::readMeasuredTrace("2302\tignored\t0\n2311\tignored\t3\n", "t.csv", columns);
    ASSERT_TRUE(trace.ok()) << trace.error().toString();
    EXPECT_DOUBLE_EQ(trace->time[1], 0.003);
    EXPECT_DOUBLE_EQ(trace->nominal[0][1], 2.311);
    EXPECT_TRUE(trace->actual[0].empty());
}

TEST(MeasuredTrace, BadLinesNameFileLineAndColumn)
{
    sim::TraceColumns xOnly;
    xOnly.nominal = {1, -1, -1, -1, -1};
    xOnly.actual = {2, -1, -1, -1, -1};
    xOnly.deviation = {-1, -1, -1, -1, -1};
    EXPECT_EQ(messageOf("t;x;x\n0;1;1\n0,003;1,5;x1\n", xOnly), "trace.csv:3:11: expected a number, found \"x1\"");
    EXPECT_EQ(messageOf("t;x;x\n0;1;1\n0,003;1,5\n", xOnly), "trace.csv:3:10: column 3 is missing (the line has 2)");
    EXPECT_EQ(messageOf("t;x;x\n0;1;1\n0;1;1\n", xOnly), "trace.csv:3:1: time does not increase");
    EXPECT_EQ(messageOf("t;x;x\n", xOnly), "trace.csv: no samples (a time column and one line of data at least)");
    // With commas between fields a comma cannot be a decimal one.
    EXPECT_EQ(messageOf("t,x,x\n0,1,1\n0.003,1;5,1\n", xOnly), "trace.csv:3:7: expected a number, found \"1;5\"");
}

// Seed 003's turning case in miniature: C turns the part under a tool at X 50; the actual C lags
// 1°, so the actual tip lies 2·50·sin(0.5°) from the nominal one on the workpiece.
TEST(MeasuredTrace, NominalAndActualThroughTheChainAndTheirDeviation)
{
    auto trace = sim::loadMeasuredTrace(kDir + "tncscope-turning.csv");
    ASSERT_TRUE(trace.ok()) << trace.error().toString();
    const sim::Trace nominal = sim::workpieceTrace(trace.value(), false, seed003Chain());
    const sim::Trace actual = sim::workpieceTrace(trace.value(), true, seed003Chain());
    EXPECT_NEAR(nominal[1].tip.x, 0, 1e-9);  // C 90° about −Z brings X 50 of the machine to Y 50
    EXPECT_NEAR(nominal[1].tip.y, 50, 1e-9);
    const auto d = sim::deviationDistance(nominal, actual);
    EXPECT_NEAR(d[0], 0, 1e-12);
    EXPECT_NEAR(d[2], 2 * 50 * std::sin(0.5 * 3.14159265358979323846 / 180), 1e-9);
    // The Z recorded at the spindle face: the tip lies the tool's length below.
    EXPECT_NEAR(sim::workpieceTrace(trace.value(), false, seed003Chain(), 80)[0].tip.z, -80, 1e-9);
}

TEST(MeasuredTrace, DistanceToTheProgrammedPath)
{
    sim::MoveList program;
    sim::Move m;
    m.from = {0, 0, 0};
    m.to = {10, 0, 0};
    program.moves.push_back(m);
    sim::Trace trace(2);
    trace[0].tip = {5, 1, 0};
    trace[1].tip = {12, 0, 0};
    auto d = sim::distanceToPath(trace, program);
    EXPECT_NEAR(d[0], 1, 1e-12);
    EXPECT_NEAR(d[1], 2, 1e-12);

    // A long zig-zag and points around and far outside it: the grid finds what a full search does.
    program.moves.clear();
    for (int i = 0; i < 2000; ++i) {
        m.from = {double(i % 2) * 40, i * 0.1, -0.001 * i};
        m.to = {double((i + 1) % 2) * 40, (i + 1) * 0.1, -0.001 * (i + 1)};
        m.kind = i % 7 == 0 ? sim::MoveKind::Rapid : sim::MoveKind::Feed;
        program.moves.push_back(m);
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> x(-60, 100), y(-50, 260), z(-30, 30);
    trace.resize(300);
    for (auto& s : trace)
        s.tip = {x(random), y(random), z(random)};
    d = sim::distanceToPath(trace, program);
    for (std::size_t k = 0; k < trace.size(); ++k) {
        double brute = 1e300;
        for (const sim::Move& move : program.moves) {
            const base::Vec3 dir = move.to - move.from;
            const double u = std::clamp((trace[k].tip - move.from).dot(dir) / dir.dot(dir), 0.0, 1.0);
            brute = std::min(brute, base::distance(trace[k].tip, move.from + dir * u));
        }
        ASSERT_NEAR(d[k], brute, 1e-12) << k;
    }
}
