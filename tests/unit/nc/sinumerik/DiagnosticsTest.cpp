// Diagnostics with file, line, column and severity, the interpreter carrying on after them, and
// hostile input: deep nesting, huge numbers, NUL bytes, random bytes, CR/LF mixes, runaway loops.
#include "TestSupport.h"

#include <random>

namespace camwb::nc::sinumerik::test {
namespace {

void expectAt(const NcRun& r, const std::string& text, int line, int column, Severity severity = Severity::Error)
{
    const Diagnostic* d = r.find(text);
    ASSERT_NE(d, nullptr) << text << '\n' << r.diagnostics();
    EXPECT_EQ(d->line, line) << text;
    EXPECT_EQ(d->column, column) << text;
    EXPECT_EQ(d->severity, severity) << text;
    EXPECT_EQ(d->file, "MAIN.MPF");
}

TEST(SinumerikDiagnostics, ParseErrorsWithColumns)
{
    const NcRun r = run("N10 GO X10\n"           // 1: unknown word
                        "N20 G1 X=(R1+2 F100\n"  // 2: unbalanced
                        "N30 G1 Z(R1+2)\n"       // 3: missing =
                        "N40 R1=2*)\n"           // 4: ')' without '('
                        "N50 G1 X=\n"            // 5: value missing
                        "N60 R1000=1\n"          // 6: R out of range
                        "N70 G1 X=FOO\n"         // 7: unknown name
                        "N80 G0 X10 ; fine\n"
                        "N90 G1.5 X1\n"        // 9: invalid G
                        "N95 Q5\n"             // 10: unknown word / call with a number? an unknown word
                        "N100 G0 X1 $Y\n"      // 11: unexpected
                        "N110 M99999999999\n"  // 12: beyond int (converting it was undefined)
                        "M30\n");
    expectAt(r, "unknown word GO", 1, 5);
    expectAt(r, "unbalanced parentheses: '(' at column 10 is not closed", 2, 16);
    expectAt(r, "'=' missing before the expression of Z", 3, 9);
    expectAt(r, "unbalanced parentheses: ')' without '('", 4, 10);
    expectAt(r, "a value is missing after X=", 5, 10);
    expectAt(r, "R parameter R1000 out of range", 6, 5);
    expectAt(r, "unknown name FOO in an expression", 7, 10);
    expectAt(r, "invalid G code G1.5", 9, 5);
    expectAt(r, "invalid M code M99999999999", 12, 6);
    EXPECT_EQ(r.all<toolpath::Rapid>().size(), 1u);  // N80 runs; the broken blocks are left out
    EXPECT_TRUE(r.result.completed);
}

TEST(SinumerikDiagnostics, RuntimeErrorsReportedOncePerPlace)
{
    const NcRun r = run("FOR R1=1 TO 50\nR2=1/(R1-R1)\nG0 X=99999.9991\nENDFOR\nM30\n");
    EXPECT_EQ(r.errors(), 2) << r.diagnostics();
    expectAt(r, "division by zero", 2, 5);
    expectAt(r, "outside the control's range", 3, 4);
    EXPECT_TRUE(r.all<toolpath::Rapid>().empty());
}

TEST(SinumerikDiagnostics, WarningsForWhatIsNotTraced)
{
    const NcRun r = run("TRAORI\nG0 A10\nTRANS X10\nG53 G0 Z0\nG33 Z-10 K1\nTRAFOOF\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    expectAt(r, "TRAORI (five-axis transformation) needs a five-axis machine", 1, 1, Severity::Warning);
    expectAt(r, "rotary axes A B C", 2, 4, Severity::Warning);
    expectAt(r, "programmable frame TRANS X10 is not applied", 3, 1, Severity::Warning);
    expectAt(r, "G53/G153", 4, 0, Severity::Warning);
    expectAt(r, "G33 is not interpreted", 5, 1, Severity::Warning);
    ASSERT_EQ(r.all<toolpath::PassThrough>().size(), 1u);
    EXPECT_EQ(r.all<toolpath::PassThrough>()[0].text, "TRANS X10");
}

// SUPA (G53 and more) positions in machine coordinates: Z0 there is the top of the travel, not
// the work offset's Z0, so the trace must not draw a rapid to Z0 (into the part); Z is unknown
// until a block gives it, and the next move moves only the known axes.
TEST(SinumerikDiagnostics, SupaLeavesTheAxesItMovesUnknown)
{
    const NcRun r = run("G0 X10 Y10 Z5\nG0 SUPA Z0 D0\nG0 X20\nG1 Z-1 F100\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    expectAt(r, "G53/G153/SUPA: a move in machine coordinates is not traced", 2, 0, Severity::Warning);
    const auto rapids = r.all<toolpath::Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[1].to.x, 20);
    EXPECT_FALSE(rapids[1].axes.has(2)) << "Z after SUPA is not known";
    EXPECT_EQ(rapids[1].axes.bits, toolpath::AxisMask::kX | toolpath::AxisMask::kY) << "SUPA gave Z alone";
    // The sinks forget Z too, at the SUPA block, so nothing is drawn or cut from Z 5.
    ASSERT_EQ(r.all<toolpath::UnknownAxes>().size(), 1u);
    EXPECT_EQ(r.all<toolpath::UnknownAxes>()[0].axes.bits, toolpath::AxisMask::kZ);
    EXPECT_NE(r.trace().find("2 unknown z\n3 rapid x 20.0000 y 10.0000 "), std::string::npos) << r.trace();
    ASSERT_EQ(r.all<toolpath::Linear>().size(), 1u);
    EXPECT_EQ(r.all<toolpath::Linear>()[0].to.z, -1);
}

// G75 FP=1 Z1=0 (to the tool change position) and G74 X1=0 Y1=0 (the reference point) send machine
// axes to places the trace cannot place in the work offset's frame: those axes become unknown, as
// after SUPA. Machine axis words without G74/G75, or G74/G75 without one, are errors at their block.
TEST(SinumerikDiagnostics, ReferenceAndFixedPointApproachLeaveTheirAxesUnknown)
{
    const NcRun r = run("G0 X10 Y10 Z5\nG75 FP=1 Z1=0\nG0 X20\nG0 Z2\nG74 X1=0 Y1=0\nG0 Z3\nM30\n");
    EXPECT_EQ(r.errors(), 0) << r.diagnostics();
    expectAt(r, "G75 (fixed point approach) is not traced", 2, 0, Severity::Warning);
    const auto unknown = r.all<toolpath::UnknownAxes>();
    ASSERT_EQ(unknown.size(), 2u);
    EXPECT_EQ(unknown[0].axes.bits, toolpath::AxisMask::kZ);
    EXPECT_EQ(unknown[1].axes.bits, toolpath::AxisMask::kX | toolpath::AxisMask::kY);
    const auto rapids = r.all<toolpath::Rapid>();
    ASSERT_EQ(rapids.size(), 4u);
    EXPECT_EQ(rapids[1].axes.bits, toolpath::AxisMask::kX | toolpath::AxisMask::kY);  // not at Z5
    EXPECT_TRUE(rapids[2].axes.all());
    EXPECT_EQ(rapids[3].axes.bits, toolpath::AxisMask::kZ);

    const NcRun bad = run("G0 X1=5\nG74\nM30\n");
    expectAt(bad, "machine axes (X1=, Y1=, Z1=) are read with G74 or G75 only", 1, 4, Severity::Error);
    expectAt(bad, "G74 names no machine axis", 2, 0, Severity::Error);
}

TEST(SinumerikDiagnostics, DiagnosticsAreCapped)
{
    InterpretOptions options;
    options.maxDiagnostics = 5;
    std::string text;
    for (int i = 0; i < 50; ++i)
        text += "GO X" + std::to_string(i) + "\n";
    const NcRun r = run(text, {}, options);
    EXPECT_EQ(r.result.diagnostics.size(), 5u);
    EXPECT_EQ(r.result.diagnosticsDropped, 45u);
}

TEST(SinumerikDiagnostics, HostileInputNeverCrashesOrHangs)
{
    InterpretOptions options;
    options.maxBlocks = 20000;
    const std::string cases[] = {
        std::string("G1 X") + std::string(400, '9') + "\n",
        std::string("G1 X=1") + std::string(300, '0') + "\n",
        std::string("R1=") + std::string(2000, '(') + "\n",
        std::string("\0\0G0\0X1\r\r\nG1 X2\rG1 X3\n\r", 24),
        "IF\nELSE\nELSE\nENDIF\nENDIF\nWHILE\nUNTIL\nFOR\nFOR X=1\nFOR R1=1 TO\nGOTOF\nGOTOB 5\nPROC\nPROC "
        "A(\nDEF\nDEF "
        "REAL\nDEF REAL V[0]\nDEF REAL W[99999999]\nMCALL 5\nMCALL X\nMSG(\nCYCLE81(\nCYCLE81(1,,,,,,,,,,,,,,,,,,,)\n",
        "SELF\n",
        "R1=SQRT(-1)+LN(0)+ACOS(3)+1/0+5 MOD 0+5 DIV 0.1+TAN(90)+POT(1EX300)\n",
        "G2 X10\nG2 CR=0\nG3 AR=400 X1\nG2 X0 Y0 CR=5\nG2 I0 J0\nG2 X1 I=AC(0) J=AC(0) TURN=-1\n",
        "L1 P0\nL2 P100000\nA(1,2,3)\n",
        "R[5000]=1\nR[-1]=2\nDEF REAL Q[3]\nQ[7]=1\nR1=Q[-1]\n",
        "+\n-\n*(\n+1\n",
    };
    for (const std::string& text : cases) {
        const NcRun r = run(text, {{"SELF", "SELF\nSELF\n"}, {"A", "PROC A(REAL B)\nM17\n"}}, options);
        EXPECT_LE(r.result.blocksExecuted, 20001);
    }
    // Random token soup and random bytes.
    std::mt19937 random(12345);
    const char* pieces[] = {"G0 ",     "G1 ",    "G2 ",        "X",          "Y=",     "Z=(",
                            ")",       "R1",     "=",          "+",          "-",      "*",
                            "/",       "1",      ".5",         "\n",         "IF ",    "ELSE\n",
                            "ENDIF\n", "WHILE ", "ENDWHILE\n", "REPEAT\n",   "UNTIL ", "GOTOB L\n",
                            "L:",      "CR=",    "AR=",        "I",          "J",      "MCALL CYCLE81(",
                            ",",       "SUB",    "(",          "DEF REAL V", "[",      "]",
                            "AND ",    "TURN=",  "DIAMON ",    "G18 ",       "G91 ",   ";x",
                            "\r",      "\"",     "M17\n",      "M30\n"};
    for (int round = 0; round < 300; ++round) {
        std::string text;
        const int count = static_cast<int>(random() % 200);
        for (int i = 0; i < count; ++i) {
            if (random() % 10 == 0)
                text += static_cast<char>(random() % 256);
            else
                text += pieces[random() % (sizeof pieces / sizeof pieces[0])];
        }
        const NcRun r = run(text, {{"SUB", text.substr(0, text.size() / 2)}}, options);
        EXPECT_LE(r.result.blocksExecuted, 20001);
    }
}

TEST(SinumerikDiagnostics, MalformedNumbersAreErrorsAndTheBlockDoesNotMove)
{
    const NcRun r = run("G0 X0 Y0\nG0 X+ZZ Y10\nG0 X1.2.3 Y20\nG0 X1..2 Y30\nG0 Y\nG0 X=1.2.3 Y40\nG0 X8 Y8\nM30\n");
    EXPECT_EQ(r.diagnostics(), "MAIN.MPF:2:4: error: X needs a value (X10 or X=expression)\n"
                               "MAIN.MPF:3:4: error: malformed number X1.2.3\n"
                               "MAIN.MPF:4:4: error: malformed number X1..2\n"
                               "MAIN.MPF:5:4: error: Y needs a value (Y10 or Y=expression)\n"
                               "MAIN.MPF:6:6: error: malformed number 1.2.3\n");
    const auto rapids = r.all<toolpath::Rapid>();
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[1].to.x, 8);
    EXPECT_EQ(rapids[1].to.y, 8);
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
