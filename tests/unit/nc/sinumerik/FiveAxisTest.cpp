// Five-axis SINUMERIK read back through a machine's kinematics: TRAORI with the tool vector
// A3= B3= C3= and with rotary positions, TRAFOOF with machine axes (seed 000's B/C table: B about
// +Y, C about +Z through the workpiece zero), DC/ACP/ACN on the endless C, G93 inverse time, and
// the errors of words the machine cannot read.
#include "TestSupport.h"

#include "kinematics/Machine.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::sinumerik::test {
namespace {

using namespace camwb::toolpath;

// A B/C table-table machine with intersecting axes (the MAS MCVL 1000's chain).
kinematics::Machine bcTable()
{
    kinematics::Machine m;
    m.id = "bc-table";
    m.name = "B/C table";
    m.control = "sinumerik-840d";
    m.axes = {{"X", false, -500, 500},
              {"Y", false, -500, 500},
              {"Z", false, -500, 500},
              {"B", true, -120, 30},
              {"C", true, -INFINITY, INFINITY, true}};
    m.kinematics.type = kinematics::ChainType::TableTable;
    m.kinematics.joints = {{"B", true, {0, 1, 0}, {}}, {"C", true, {0, 0, 1}, {}}};
    return m;
}

NcRun runOn(const kinematics::Machine& machine, const std::string& text)
{
    InterpretOptions options = fromOrigin();
    options.machine = &machine;
    return run(text, {}, options);
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

const double kDeg = std::numbers::pi / 180;
const Vec3 kAxis3040{-std::cos(40 * kDeg) * 0.5, std::sin(40 * kDeg) * 0.5, std::sqrt(3.0) / 2};

TEST(SinumerikFiveAxis, TraoriWithAToolVectorSolvesTheRotaryAxes)
{
    const kinematics::Machine m = bcTable();
    // Seed 000 §3.4: K = (-0.3830, 0.3214, 0.8660) is B = 30, C = 40; written twice as long.
    const NcRun r = runOn(m, "TRAORI\nG1 X10 Y20 Z5 A3=-0.76604 B3=0.64279 C3=1.73205 F500\nG1 X12\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    expectNear(moves[0].tip, {10, 20, 5});
    expectNear(moves[0].axis, kAxis3040, 1e-5);
    EXPECT_NEAR(moves[0].axis.length(), 1, 1e-12);
    EXPECT_EQ(moves[0].machine.known, RotaryAxes::kB | RotaryAxes::kC);
    EXPECT_NEAR(moves[0].machine.bDeg, 30, 1e-3);
    EXPECT_NEAR(moves[0].machine.cDeg, 40, 1e-3);
    expectNear(moves[1].tip, {12, 20, 5});
    expectNear(moves[1].axis, moves[0].axis, 1e-12);
}

TEST(SinumerikFiveAxis, TraoriWithRotaryPositionsAndTrafoofWithMachineAxes)
{
    const kinematics::Machine m = bcTable();
    const NcRun on = runOn(m, "TRAORI\nG0 X10 Y0 Z0 B30 C40\nM30\n");
    EXPECT_EQ(on.errors(), 0) << on.diagnostics();
    ASSERT_EQ(on.all<ToolAxisMove>().size(), 1u);
    expectNear(on.all<ToolAxisMove>()[0].tip, {10, 0, 0});
    expectNear(on.all<ToolAxisMove>()[0].axis, kAxis3040, 1e-12);

    const NcRun off = runOn(m, "G0 X10 Y0 Z0 B30 C40\nM30\n");
    EXPECT_EQ(off.errors(), 0) << off.diagnostics();
    ASSERT_EQ(off.all<ToolAxisMove>().size(), 1u);
    // Seed 000 eq. 20: Q = X·P, P = (10, 0, 0).
    expectNear(off.all<ToolAxisMove>()[0].tip,
               {std::cos(40 * kDeg) * std::cos(30 * kDeg) * 10, -std::sin(40 * kDeg) * std::cos(30 * kDeg) * 10, 5});
    EXPECT_EQ(off.all<ToolAxisMove>()[0].feedMmPerMin, 0);
}

TEST(SinumerikFiveAxis, TrafoofConvertsThePositionToTheMachineAxes)
{
    const kinematics::Machine m = bcTable();
    // B-90: the tip at workpiece X10 is machine Z10 (the table tilted the part up).
    const NcRun r = runOn(m, "TRAORI\nG0 X10 Y0 Z0 B-90 C0\nTRAFOOF\nG91 G0 Z1\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    expectNear(moves[0].axis, {1, 0, 0}, 1e-12);
    expectNear(moves[1].tip, {11, 0, 0});  // machine Z+1 is along the tool, +X of the part
}

TEST(SinumerikFiveAxis, DirectedPositionsOfTheEndlessAxis)
{
    const kinematics::Machine m = bcTable();
    const NcRun r = runOn(m, "TRAORI\nG0 X0 Y0 Z50 B0 C355\nC=DC(5)\nC=ACN(10)\nC=ACP(0)\nC=IC(-20)\nC=5\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 6u);
    EXPECT_EQ(moves[1].machine.cDeg, 365);  // DC: +10 the shorter way
    EXPECT_EQ(moves[2].machine.cDeg, 10);   // ACN from 365 to 10: -355
    EXPECT_EQ(moves[3].machine.cDeg, 360);  // ACP from 10 to 0: +350
    EXPECT_EQ(moves[4].machine.cDeg, 340);
    EXPECT_EQ(moves[5].machine.cDeg, 5);  // absolute: as written
    for (const ToolAxisMove& move : moves)
        expectNear(move.tip, {0, 0, 50});
}

TEST(SinumerikFiveAxis, InverseTimeFeedOnFiveAxisMoves)
{
    const kinematics::Machine m = bcTable();
    const NcRun r = runOn(m, "TRAORI\nG0 X0 Y0 Z50 B0 C10\nG93 G1 C20 F2\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    ASSERT_EQ(r.all<ToolAxisMove>().size(), 2u);
    EXPECT_EQ(r.all<ToolAxisMove>()[1].feedMmPerMin, 2);
    EXPECT_NE(r.trace().find("3 linear5 0.0000 0.0000 50.0000 axis 0.0000 0.0000 1.0000 b 0.0000 c 20.0000 fi 2.0000"),
              std::string::npos)
        << r.trace();
}

TEST(SinumerikFiveAxis, WordsTheMachineCannotReadAreErrors)
{
    const kinematics::Machine m = bcTable();
    const NcRun r = runOn(m, "G0 X0 Y0 Z0 A10\nG1 X1 A3=0 B3=0 C3=1 F100\nTRAORI\nG1 X1 B3=0 B10 F100\n"
                             "G1 X2 C3=0 F100\nC10\nG0 X3\nM30\n");
    const Diagnostic* noA = r.find("has no A axis");
    ASSERT_NE(noA, nullptr) << r.diagnostics();
    EXPECT_EQ(noA->line, 1);
    EXPECT_EQ(noA->column, 13);
    EXPECT_EQ(noA->severity, Severity::Error);
    ASSERT_NE(r.find("need TRAORI"), nullptr);
    EXPECT_EQ(r.find("need TRAORI")->line, 2);
    ASSERT_NE(r.find("rotary axis positions in one block"), nullptr);
    EXPECT_EQ(r.find("rotary axis positions in one block")->line, 4);
    ASSERT_NE(r.find("is zero"), nullptr);
    EXPECT_EQ(r.find("is zero")->line, 5);
    ASSERT_NE(r.find("B is unknown here"), nullptr);  // C turned, B never given
    EXPECT_EQ(r.find("B is unknown here")->line, 6);
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());
    ASSERT_EQ(r.all<Rapid>().size(), 1u);  // only G0 X3: the other blocks are left out
    EXPECT_EQ(r.all<Rapid>()[0].to.x, 3);
}

TEST(SinumerikFiveAxis, TheTableTurnsUntracedWhileTheTipIsUnknown)
{
    const kinematics::Machine m = bcTable();
    InterpretOptions options;  // nothing known at the start, as on the control
    options.machine = &m;
    const NcRun r = run("G0 B30 C40\nG0 X10\nTRAORI\nG0 X10 Y20 Z50\nG0 Z5\nM30\n", {}, options);
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_NE(r.find("while X, Y or Z is unknown is not traced"), nullptr);
    const auto moves = r.all<ToolAxisMove>();
    ASSERT_EQ(moves.size(), 2u);
    expectNear(moves[0].tip, {10, 20, 50});
    expectNear(moves[0].axis, kAxis3040, 1e-12);
    expectNear(moves[1].tip, {10, 20, 5});
}

TEST(SinumerikFiveAxis, WithoutAMachineTheFiveAxisWordsWarn)
{
    const NcRun r = run("TRAORI\nG1 X1 Y0 Z0 A3=0 B3=0 C3=1 F100\nG0 B30\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    EXPECT_NE(r.find("TRAORI (five-axis transformation) needs a five-axis machine"), nullptr);
    EXPECT_NE(r.find("A3= B3= C3= (tool vector) need a five-axis machine"), nullptr);
    EXPECT_NE(r.find("rotary axes A B C need a five-axis machine"), nullptr);
    EXPECT_TRUE(r.all<ToolAxisMove>().empty());
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
