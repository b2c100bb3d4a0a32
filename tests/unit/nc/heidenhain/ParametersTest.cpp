// Q parameters, FN functions, formulas, conditional jumps, LBL repeats and subprograms, CALL PGM.
#include "TestSupport.h"

#include <cmath>
#include <map>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

// Runs `body` and returns the X of each rapid: a simple probe for computed values.
std::vector<double> probe(std::string_view body, Traced* out = nullptr)
{
    Traced r = run("0 BEGIN PGM T MM\n" + std::string(body) + "\n999 END PGM T MM\n");
    std::vector<double> xs;
    for (const Rapid& rapid : r.all<Rapid>())
        xs.push_back(rapid.to.x);
    if (out)
        *out = std::move(r);
    return xs;
}

TEST(HeidenhainParameters, FnArithmetic)
{
    Traced r;
    const auto xs = probe("1 FN 0: Q1 = +60\n"
                          "2 FN 1: Q2 = -Q1 + -5\n"
                          "3 FN 2: Q3 = +10 - +5\n"
                          "4 FN 3: Q4 = +3 * +3\n"
                          "5 FN 4: Q5 = +8 DIV +Q4\n"
                          "6 FN 5: Q6 = SQRT 16\n"
                          "7 FN 6: Q7 = SIN +30\n"
                          "8 FN 7: Q8 = COS +60\n"
                          "9 FN 8: Q9 = +3 LEN +4\n"
                          "10 FN 13: Q10 = +10 ANG -10\n"
                          "11 L X+Q1 FMAX\n12 L X+Q2 FMAX\n13 L X+Q3 FMAX\n14 L X+Q4 FMAX\n15 L X+Q5 FMAX\n"
                          "16 L X+Q6 FMAX\n17 L X+Q7 FMAX\n18 L X+Q8 FMAX\n19 L X+Q9 FMAX\n20 L X+Q10 FMAX\n"
                          "21 L X-Q1 FMAX",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const std::vector<double> expected{60, -65, 5, 9, 8.0 / 9, 4, 0.5, 0.5, 5, 315, -60};
    ASSERT_EQ(xs.size(), expected.size());
    for (std::size_t i = 0; i < xs.size(); ++i)
        EXPECT_NEAR(xs[i], expected[i], 1e-12) << i;
}

TEST(HeidenhainParameters, Formulas)
{
    Traced r;
    const auto xs = probe("1 Q1 = 2 + 3 * 4\n"
                          "2 Q2 = (2 + 3) * 4\n"
                          "3 Q3 = 2 ^ 3 ^ 2\n"
                          "4 Q4 = -2 ^ 2\n"
                          "5 Q5 = SIN(30) + COS 60 + TAN(45)\n"
                          "6 Q6 = ASIN 0.5 + ACOS(0.5) + ATAN 1\n"
                          "7 Q7 = SQRT(Q2 - 4) + ABS -3 + INT 2.7 + FRAC 2.75 + SGN -9\n"
                          "8 QL1 = 7\n"
                          "9 QR2 = QL1 * 2\n"
                          "10 Q8 = PI\n"
                          "11 Q9 = SQ 3 + LN 1 + LOG 100\n"
                          "12 L X+Q1 FMAX\n13 L X+Q2 FMAX\n14 L X+Q3 FMAX\n15 L X+Q4 FMAX\n16 L X+Q5 FMAX\n"
                          "17 L X+Q6 FMAX\n18 L X+Q7 FMAX\n19 L X+QR2 FMAX\n20 L X+Q8 FMAX\n21 L X+Q9 FMAX\n"
                          "22 L X+((Q1 - 4) / 2) FMAX",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const std::vector<double> expected{14, 20, 512, 4, 2, 135, 4 + 3 + 2 + 0.75 - 1, 14, M_PI, 11, 5};
    ASSERT_EQ(xs.size(), expected.size());
    for (std::size_t i = 0; i < xs.size(); ++i)
        EXPECT_NEAR(xs[i], expected[i], 1e-12) << i;
}

TEST(HeidenhainParameters, ParametricFeedOfTheThesis)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 Q601=900 ;hrubovaci\n2 Q602=1500 ;dokoncovaci\n"
                         "3 L X+1 F+Q602\n4 L Z+1 F+Q601\n5 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty());
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].feedMmPerMin, 1500);
    EXPECT_EQ(lines[1].feedMmPerMin, 900);
    const auto comments = r.all<Comment>();
    ASSERT_EQ(comments.size(), 2u);
    EXPECT_EQ(comments[0].text, "hrubovaci");
}

TEST(HeidenhainParameters, ParametricFeedWithoutSign)
{
    // FQ601 is F+Q601 as the control writes it; QL and QR parameters likewise.
    const Traced r = run("0 BEGIN PGM T MM\n1 Q601=900\n2 QL3=450\n3 L X+1 FQ601\n4 L X+2 F+Q601\n"
                         "5 L X+3 FQL3\n6 L X+4 F\n7 END PGM T MM\n");
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 3u) << r.trace();
    EXPECT_EQ(lines[0].feedMmPerMin, 900);
    EXPECT_EQ(lines[1].feedMmPerMin, 900);
    EXPECT_EQ(lines[2].feedMmPerMin, 450);
    ASSERT_EQ(r.result.diagnostics.size(), 1u);
    EXPECT_TRUE(r.has(Severity::Error, 7, "missing value after 'F'")) << r.diagnostics()[0];
}

TEST(HeidenhainParameters, ConditionalJumpsMakeALoop)
{
    // Five holes along X with FN 12 (less than) and FN 9 (equal) exits.
    Traced r;
    const auto xs = probe("1 Q1 = 0\n"
                          "2 LBL 1\n"
                          "3 L X+Q1 FMAX\n"
                          "4 Q1 = Q1 + 10\n"
                          "5 FN 12: IF +Q1 LT +50 GOTO LBL 1\n"
                          "6 FN 9: IF +Q1 EQU +50 GOTO LBL \"DONE\"\n"
                          "7 L X+999 FMAX\n"
                          "8 LBL \"DONE\"\n"
                          "9 FN 10: IF +Q1 NE +50 GOTO LBL 1\n"
                          "10 FN 11: IF+Q1 GT+100 GOTO LBL 1\n",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    EXPECT_EQ(xs, (std::vector<double>{0, 10, 20, 30, 40}));
}

TEST(HeidenhainParameters, SectionRepeat)
{
    // REP 2: the section runs three times in all.
    Traced r;
    const auto xs = probe("1 Q1 = 0\n"
                          "2 LBL 1\n"
                          "3 Q1 = Q1 + 1\n"
                          "4 L X+Q1 FMAX\n"
                          "5 CALL LBL 1 REP2\n"
                          "6 L X+100 FMAX\n",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    EXPECT_EQ(xs, (std::vector<double>{1, 2, 3, 100}));
}

TEST(HeidenhainParameters, SubprogramsAfterTheProgramEnd)
{
    Traced r;
    const auto xs = probe("1 L X+1 FMAX\n"
                          "2 CALL LBL 5\n"
                          "3 L X+2 FMAX\n"
                          "4 CALL LBL \"POLOHA-1\"\n"
                          "5 CALL LBL 5 REP 1\n"
                          "6 L M30\n"
                          "7 LBL 5\n"
                          "8 L X+50 FMAX\n"
                          "9 LBL 0\n"
                          "10 LBL \"POLOHA-1\"\n"
                          "11 L X+60 FMAX\n"
                          "12 CALL LBL 5\n"
                          "13 LBL 0\n",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    EXPECT_EQ(xs, (std::vector<double>{1, 50, 2, 60, 50, 50}));
    EXPECT_TRUE(r.result.completed);
}

TEST(HeidenhainParameters, NestedRepeats)
{
    Traced r;
    const auto xs = probe("1 Q1 = 0\n"
                          "2 LBL 1\n"
                          "3 LBL 2\n"
                          "4 Q1 = Q1 + 1\n"
                          "5 L X+Q1 FMAX\n"
                          "6 CALL LBL 2 REP 1\n"
                          "7 CALL LBL 1 REP 2\n",
                          &r);
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    EXPECT_EQ(xs.size(), 6u);
}

TEST(HeidenhainParameters, CallProgramThroughTheResolverSharesQParameters)
{
    std::map<std::string, std::string> files{
        {"SUB", "0 BEGIN PGM SUB MM\n1 L X+Q1 FMAX\n2 Q1 = Q1 + 1\n3 END PGM SUB MM\n"},
    };
    InterpretOptions options;
    options.resolveProgram = [&](std::string_view name) -> std::optional<ProgramSource> {
        auto it = files.find(std::string(name));
        if (it == files.end())
            return std::nullopt;
        return ProgramSource{"/progs/" + it->first + ".h", it->second};
    };
    const Traced r = run("0 BEGIN PGM MAIN MM\n1 Q1 = 5\n2 CALL PGM SUB\n3 CALL PGM TNC:\\DIR\\SUB\n"
                         "4 L X+Q1 FMAX\n5 CALL PGM MISSING\n6 END PGM MAIN MM\n",
                         options);
    const auto rapids = r.all<Rapid>();
    ASSERT_EQ(rapids.size(), 3u);
    EXPECT_EQ(rapids[0].to.x, 5);
    EXPECT_EQ(rapids[1].to.x, 6);
    EXPECT_EQ(rapids[2].to.x, 7);
    ASSERT_EQ(r.result.files.size(), 2u);
    EXPECT_EQ(r.result.files[1], "/progs/SUB.h");
    EXPECT_EQ(r.path.source(0).file, 1);
    EXPECT_EQ(r.path.source(0).line, 2);
    EXPECT_EQ(r.path.source(2).file, 0);
    EXPECT_TRUE(r.has(Severity::Error, 6, "undefined program MISSING"));
    EXPECT_TRUE(r.result.completed);
    EXPECT_NE(r.trace().find("SUB.h:2 rapid"), std::string::npos) << r.trace();
}

TEST(HeidenhainParameters, RecursiveCallProgramStopsAtTheNestingLimit)
{
    InterpretOptions options = fromOrigin();
    options.resolveProgram = [](std::string_view) -> std::optional<ProgramSource> {
        return ProgramSource{"SELF.h", "0 BEGIN PGM SELF MM\n1 L IX+1 FMAX\n2 CALL PGM SELF\n3 END PGM SELF MM\n"};
    };
    const Traced r = run("0 BEGIN PGM MAIN MM\n1 CALL PGM SELF\n2 END PGM MAIN MM\n", options);
    EXPECT_EQ(r.all<Rapid>().size(), 16u);
    EXPECT_TRUE(r.has(Severity::Error, 3, "nested deeper than 16")) << r.diagnostics()[0];
}

TEST(HeidenhainParameters, RunawayLoopStopsWithOneError)
{
    InterpretOptions options = fromOrigin();
    options.maxBlocks = 1000;
    const Traced r = run("0 BEGIN PGM T MM\n1 LBL 1\n2 L IX+1 F100\n3 FN 9: IF +0 EQU +0 GOTO LBL 1\n"
                         "4 END PGM T MM\n",
                         options);
    ASSERT_EQ(r.result.diagnostics.size(), 1u);
    EXPECT_NE(r.result.diagnostics[0].message.find("runaway"), std::string::npos);
    EXPECT_GT(r.result.diagnostics[0].line, 0);
    EXPECT_FALSE(r.result.completed);
    EXPECT_EQ(r.result.blocksExecuted, 1001);
}

TEST(HeidenhainParameters, Fn14StopsTheProgram)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 FN 14: ERROR = 254\n2 L X+1 FMAX\n3 END PGM T MM\n");
    EXPECT_TRUE(r.has(Severity::Error, 2, "ERROR = 254"));
    EXPECT_TRUE(r.all<Rapid>().empty());
    EXPECT_FALSE(r.result.completed);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
