// InterpretOptions::onBlock in every dialect: one report per executed block with the state it
// ran with, in the program's words (G90/G91, G710, G17, G41, G54; MM, TOOL CALL Z, RL, X/IX).
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace camwb::nc::test {
namespace {

// The last report of each line of the main program.
std::map<int, BlockModal> reports(std::string_view text, Dialect dialect)
{
    std::map<int, BlockModal> byLine;
    InterpretOptions options;
    options.dialect = dialect;
    options.onBlock = [&byLine](const BlockModal& m) {
        if (m.file == 0)
            byLine[m.line] = m;
    };
    toolpath::ToolpathRecorder recorder;
    interpret(text, options, recorder);
    return byLine;
}

std::string words(const BlockModal& m)
{
    return std::string(m.distanceWord) + " " + m.unitsWord + " " + m.planeWord + " " + m.compensationWord + " " +
           m.feedModeWord + " [" + m.workOffset + "]";
}

TEST(BlockModal, SinumerikReportsItsGCodes)
{
    const auto r = reports("G17 G90 G710 G54\nT1 M6\nG0 X0 Y0\nG91 G18 G95 G1 Z-1 F0.1\n"
                           "G90 G700 G500 G19 G94 G1 X1 F100\nG42 G17 G1 X10\nG40 G505 G70 X20\nM30\n",
                           Dialect::Sinumerik);
    ASSERT_EQ(r.size(), 8u);
    EXPECT_EQ(words(r.at(1)), "G90 G710 G17 G40 G94 [G54]");
    EXPECT_EQ(words(r.at(4)), "G91 G710 G18 G40 G95 [G54]");
    EXPECT_EQ(r.at(4).distance, BlockModal::Distance::Incremental);
    EXPECT_EQ(words(r.at(5)), "G90 G700 G19 G40 G94 [G500]");
    EXPECT_TRUE(r.at(5).inch);
    EXPECT_EQ(words(r.at(6)), "G90 G700 G17 G42 G94 [G500]");
    EXPECT_EQ(r.at(6).compensation, toolpath::CutterCompSide::Right);
    EXPECT_EQ(words(r.at(7)), "G90 G70 G17 G40 G94 [G505]");
}

TEST(BlockModal, IsoReportsLinuxCncWords)
{
    const auto r =
        reports("G21 G90 G17\nG91 G20 G1 X1 F10\nG90 G21 G41.1 D2 G1 X10\nG40 G59.2 G18 G95 G0 X0\nM2\n", Dialect::Iso);
    ASSERT_EQ(r.size(), 5u);
    EXPECT_EQ(words(r.at(1)), "G90 G21 G17 G40 G94 [G54]");
    EXPECT_EQ(words(r.at(2)), "G91 G20 G17 G40 G94 [G54]");
    EXPECT_EQ(words(r.at(3)), "G90 G21 G17 G41.1 G94 [G54]");
    EXPECT_EQ(words(r.at(4)), "G90 G21 G18 G40 G95 [G59.2]");
}

TEST(BlockModal, HeidenhainReportsKlartextWords)
{
    const auto r =
        reports("0 BEGIN PGM T INCH\n1 TOOL CALL 1 Y S1000\n2 L X+0 Y+0 R0 F10\n3 L IX+1 RL FU0.1\n"
                "4 L X+2 IY+1\n5 CYCL DEF 7.0 DATUM SHIFT\n6 CYCL DEF 7.1 X+1\n7 L Z+1 R0\n8 END PGM T INCH\n",
                Dialect::Heidenhain);
    EXPECT_EQ(words(r.at(3)), "X Y Z INCH TOOL CALL Y R0 F []");
    EXPECT_EQ(r.at(3).plane, 18);
    EXPECT_TRUE(r.at(3).inch);
    EXPECT_EQ(words(r.at(4)), "IX IY IZ INCH TOOL CALL Y RL FU []");
    EXPECT_EQ(r.at(5).distance, BlockModal::Distance::Mixed);
    EXPECT_EQ(r.at(2).distance, BlockModal::Distance::PerWord);
    EXPECT_EQ(words(r.at(8)), "X Y Z INCH TOOL CALL Y R0 FU [datum shift X+1 Y+0 Z+0]");
}

}  // namespace
}  // namespace camwb::nc::test
