// Diagnostics of the Klartext interpreter (file, line, column, severity) and its robustness:
// whatever the input (NUL bytes, lone CR, huge numbers, deep nesting, random bytes), it returns
// with diagnostics instead of crashing or hanging.
#include "TestSupport.h"

#include <random>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

const Diagnostic* find(const Traced& r, std::string_view text)
{
    for (const Diagnostic& d : r.result.diagnostics) {
        if (d.message.find(text) != std::string::npos)
            return &d;
    }
    return nullptr;
}

TEST(HeidenhainDiagnostics, UnknownWordsWithTheirColumn)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 L X+10 QQ+5 FMAX\n2 FOO X+1\n3 L X+1 FMAX\n4 END PGM T MM\n");
    ASSERT_EQ(r.result.diagnostics.size(), 2u) << r.diagnostics()[0];
    const Diagnostic& first = r.result.diagnostics[0];
    EXPECT_EQ(first.file, "test.h");
    EXPECT_EQ(first.line, 2);
    EXPECT_EQ(first.column, 10);
    EXPECT_EQ(first.severity, Severity::Error);
    EXPECT_EQ(first.message, "unknown word 'QQ+5'");
    EXPECT_EQ(r.result.diagnostics[1].line, 3);
    EXPECT_EQ(r.result.diagnostics[1].column, 3);
    // The block with the unknown word is left out (no axis moves on a guess); the program runs on.
    ASSERT_EQ(r.all<Rapid>().size(), 1u);
    EXPECT_EQ(r.all<Rapid>()[0].to.x, 1);
    EXPECT_EQ(r.lines<Rapid>(), std::vector<int>{4});
    EXPECT_TRUE(r.result.completed);
}

TEST(HeidenhainDiagnostics, ExpressionErrors)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 Q1 = (2 + 3\n"
                         "2 Q2 5\n"
                         "3 Q3 = 5 / (Q9 - Q9)\n"
                         "4 Q4 = SQRT -1\n"
                         "5 Q2000 = 1\n"
                         "6 Q5 = 2 +\n"
                         "7 Q6 = ((((((((((((((((((((((((((((((((((((1))))))))))))))))))))))))))))))))))))\n"
                         "8 END PGM T MM\n");
    const Diagnostic* paren = find(r, "unbalanced parentheses");
    ASSERT_NE(paren, nullptr);
    EXPECT_EQ(paren->line, 2);
    EXPECT_EQ(paren->column, 8);
    const Diagnostic* missing = find(r, "missing '='");
    ASSERT_NE(missing, nullptr);
    EXPECT_EQ(missing->line, 3);
    EXPECT_EQ(missing->column, 6);
    const Diagnostic* division = find(r, "division by zero");
    ASSERT_NE(division, nullptr);
    EXPECT_EQ(division->line, 4);
    EXPECT_EQ(division->column, 10);
    EXPECT_TRUE(r.has(Severity::Error, 5, "square root of a negative"));
    EXPECT_TRUE(r.has(Severity::Error, 6, "parameter number out of range"));
    EXPECT_TRUE(r.has(Severity::Error, 7, "missing operand"));
    EXPECT_TRUE(r.has(Severity::Error, 8, "nested too deeply"));
    EXPECT_TRUE(r.result.completed);
}

TEST(HeidenhainDiagnostics, LabelsAndPrograms)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 CALL LBL 7\n2 FN 9: IF +0 EQU +0 GOTO LBL \"NOWHERE\"\n"
                         "3 CALL PGM SUB\n4 LBL 3\n5 LBL 3\n6 END PGM T MM\n");
    EXPECT_TRUE(r.has(Severity::Error, 2, "undefined label 7"));
    EXPECT_TRUE(r.has(Severity::Error, 3, "undefined label NOWHERE"));
    EXPECT_TRUE(r.has(Severity::Error, 4, "undefined program SUB"));
    EXPECT_TRUE(r.has(Severity::Error, 6, "defined twice"));
}

TEST(HeidenhainDiagnostics, ArcRadiusMismatchAboutCc)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 L X+10 Y+0 FMAX\n2 CC X+0 Y+0\n3 C X+0 Y+10.5 DR+ F100\n"
                         "4 C X-10.505 Y+0 DR+\n5 END PGM T MM\n");
    const Diagnostic* d = find(r, "arc start radius");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->line, 4);
    EXPECT_EQ(d->message, "arc start radius 10.0000 and end radius 10.5000 about CC differ by 0.5000 mm "
                          "(tolerance 0.0100)");
    EXPECT_EQ(r.count(Severity::Error), 1u);  // 0.005 is within the tolerance
    EXPECT_EQ(r.all<Arc>().size(), 2u);       // traced as programmed
}

TEST(HeidenhainDiagnostics, RangeAndOrder)
{
    const Traced r = run("0 BEGIN PGM T MM\n5 L X+100000 FMAX\n4 L Y+99999999999999999999999999999999999999999999"
                         "99999999999999999999999999999999 FMAX\n6 C X+1 Y+1 DR+\n7 L X+1 F-5\n"
                         "8 L Z+1e5 FMAX\n9 END PGM T MM\n");
    EXPECT_TRUE(r.has(Severity::Error, 2, "out of the control's range"));
    EXPECT_TRUE(r.has(Severity::Error, 3, "number out of range"));
    EXPECT_TRUE(r.has(Severity::Warning, 3, "block number 4 out of order"));
    EXPECT_TRUE(r.has(Severity::Error, 4, "no circle centre CC"));
    EXPECT_TRUE(r.has(Severity::Error, 5, "negative feed"));
    EXPECT_TRUE(r.has(Severity::Error, 6, "unknown word 'e5'"));

    // A tool number is whole in TOOL DEF as in TOOL CALL: TOOL DEF 2.5 defines no tool 2.
    const Traced tools = run("0 BEGIN PGM T MM\n1 TOOL DEF 2.5 L+40 R+3\n2 TOOL CALL 2.5 Z S1000\n3 END PGM T MM\n");
    EXPECT_TRUE(tools.has(Severity::Error, 2, "tool number out of range"));
    EXPECT_TRUE(tools.has(Severity::Error, 3, "tool number out of range"));
}

TEST(HeidenhainDiagnostics, DiagnosticsAreCappedAndCounted)
{
    std::string text = "0 BEGIN PGM T MM\n";
    for (int i = 1; i <= 50; ++i)
        text += std::to_string(i) + " BAD\n";
    InterpretOptions options;
    options.maxDiagnostics = 10;
    const Traced r = run(text, options);
    EXPECT_EQ(r.result.diagnostics.size(), 10u);
    EXPECT_EQ(r.result.diagnosticsDropped, 40u);
}

TEST(HeidenhainDiagnostics, HostileTextNeverCrashes)
{
    const std::string cases[] = {
        std::string("0 BEGIN PGM T MM\n1 L X+1\0 FMAX\n2 END PGM", 36),
        "1 L X+1\r2 L X+2\r\r\n3 L ~",
        "~~~~\n~\n",
        "1 CYCL DEF 200\n Q200=\n Q201=(((\n",
        "1 Q1 = " + std::string(5000, '(') + "1" + std::string(5000, ')') + "\n",
        "1 Q1 = 1" +
            [] {
                std::string s;
                for (int i = 0; i < 5000; ++i)
                    s += "+1";
                return s;
            }() +
            "\n",
        "1 LBL 1\n2 CALL LBL 1\n",
        "1 LBL 1\n2 CALL LBL 2\n3 LBL 2\n4 CALL LBL 1\n",
        "1 CP IPA+99999999 DR+\n",
        "1 CC X+0 Y+0\n2 L X+1 FMAX\n3 CP IPA+5400 IZ-1 DR+ F100\n",
        "1 FN 9: IF\n2 FN 4: Q1 = 1 DIV 0\n3 FN 99:\n4 FN\n",
        "1 TOOL CALL \"unterminated\n2 LBL \"x\n3 CALL PGM\n",
        "1 RND R5\n2 CHF 1\n3 L X+1 F1\n4 RND\n5 CHF\n",
        "1 L X+1 M1 M2 M3 M4 M5 M6 M7 M8 M9 M10 M11\n",
        std::string(1000, '9') + " L X+1\n",
        "1 CYCL DEF 208 Q335=1e9 Q334=0.0000001 Q201=-99999\n2 CYCL CALL\n",
    };
    InterpretOptions options;
    options.maxBlocks = 10000;
    for (const std::string& text : cases) {
        const Traced r = run(text, options);
        EXPECT_LE(r.result.blocksExecuted, 10001);
    }
    // Random bytes drawn from the language's alphabet.
    const std::string alphabet = "0123456789+-*/^().,;:=~\"\n\r\t LCRTPNDFMQXYZIABSKEGOV#";
    std::mt19937 random(12345);
    for (int i = 0; i < 300; ++i) {
        std::string text;
        const int length = static_cast<int>(random() % 400);
        for (int k = 0; k < length; ++k)
            text += alphabet[random() % alphabet.size()];
        const Traced r = run(text, options);
        (void)r;
    }
}

TEST(HeidenhainDiagnostics, MalformedNumbersAreErrorsAndTheBlockDoesNotMove)
{
    // X+ZZ used to vanish silently, leaving a move in Y alone: every malformed value is an error
    // with its column, and its block moves no axis.
    const Traced r = run("0 BEGIN PGM T MM\n1 L X+0 Y+0 FMAX\n2 L X+ZZ Y+10\n3 L X+1.2.3 Y+20\n4 L X+-3 Y+30\n"
                         "5 L X+7 Y\n6 L X+8 Y+8 FMAX\n7 END PGM T MM\n");
    ASSERT_EQ(r.result.diagnostics.size(), 4u) << r.diagnostics()[0];
    const char* expected[] = {"malformed number '+ZZ' after 'X'", "malformed number '+1.2.3' after 'X'",
                              "malformed number '+-3' after 'X'", "missing value after 'Y'"};
    const int columns[] = {6, 6, 6, 9};
    for (std::size_t i = 0; i < 4; ++i) {
        const Diagnostic& d = r.result.diagnostics[i];
        EXPECT_EQ(d.severity, Severity::Error);
        EXPECT_EQ(d.line, static_cast<int>(i) + 3);
        EXPECT_EQ(d.column, columns[i]);
        EXPECT_EQ(d.message, expected[i]);
    }
    ASSERT_EQ(r.all<Rapid>().size(), 2u);
    EXPECT_EQ(r.lines<Rapid>(), (std::vector<int>{2, 7}));
    EXPECT_TRUE(r.all<Linear>().empty());
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
