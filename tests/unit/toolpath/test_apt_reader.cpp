// APT CL source import: whole files compared as traces, the lexical rules (continuation, remarks,
// numbers), machine state statements, inch units, sections, and malformed input reported with line
// and column. Motion, circles and cycles are in test_apt_motion.cpp.
#include "ClImportTestSupport.h"

using namespace camwb;
using namespace camwb::toolpath;

namespace {

ClImport import(std::string_view text) { return test::importAs(ClFormat::Apt, text); }
std::string trace(std::string_view text) { return traceOf(import(text).toolpath); }
// The trace of `text` with "FINI" appended, so that the missing-FINI warning stays out of the way.
std::string traceFini(std::string text) { return trace(text + "FINI\n"); }
base::Error failure(std::string_view text) { return test::failureAs(ClFormat::Apt, text); }
std::string warnings(const ClImport& imported) { return test::warningsText(imported); }
std::string sources(const Toolpath& toolpath) { return test::sourcesText(toolpath); }
std::string dataPath(const std::string& name) { return test::clDataPath(name); }

}  // namespace

// ---- Whole files ------------------------------------------------------------------------------

TEST(AptReader, Seed004CatiaListingImports)
{
    // seed-004 §4.6 (Obr. 31) without the "..." lines and the Czech annotations, as printed: the
    // CIRCLE/LINE statement was reflowed for print, so '$' is followed by text and a line ends in ','.
    auto result = readClFile(dataPath("seed004_catia_obr31.aptsource"), ClFormat::Apt);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_EQ(traceOf(result->toolpath),
              "section \"Profile Contouring.2\" - tool 3 cut 0.0000 plunge 0.0000\n"
              "comment \"Start generation of : Profile Contouring.2\"\n"
              "tool 3 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 70.0000 cw\n"
              "linear -62.0000 -48.0000 14.0000 f 1000.0000\n"
              "rapid -63.0000 -47.0000 14.0000\n"
              "arc cw -42.0000 29.0000 14.0000 c -42.0000 8.0000 14.0000 n 0.0000 0.0000 1.0000 turns 0 f 1000.0000\n"
              "endsection\n");
    const std::string file = dataPath("seed004_catia_obr31.aptsource");
    EXPECT_EQ(warnings(result.value()),
              file +
                  ":12:47: text after '$' is read as the continuation of the statement (APT would ignore it) (also on "
                  "line 13)\n" +
                  file + ":12:57: the statement ends with ',' and continues on the next line without '$'\n" +
                  // The "..." lines removed from the listing held the moves up to the circle.
                  file + ":12: the arc starts 37.8727 mm off its circle (radius 21)\n" + file +
                  ":13: no FINI at the end of the file: it may be truncated\n");
    EXPECT_EQ(sources(result->toolpath), "0:2 0:3 0:4 0:6 0:8 0:10 0:12 0:13 ");
}

TEST(AptReader, CatiaV5ProfileFile)
{
    auto result = readClFile(dataPath("catia_v5_profile.aptsource"), ClFormat::Apt);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const std::string expected =
        "comment \"-----------------------------------------------------------------\"\n"
        "comment \"Generated on Monday, April 08, 2024 09:12:33 AM\"\n"
        "comment \"CATIA APT VERSION 1.0\"\n"
        "comment \"-----------------------------------------------------------------\"\n"
        "comment \"Manufacturing Program.1\"\n"
        "comment \"Part Operation.1\"\n"
        "comment \"*CATIA0\"\n"
        "comment \"Manufacturing Program.1\"\n"
        "comment \"1.00000  0.00000  0.00000  0.00000\"\n"
        "comment \"0.00000  1.00000  0.00000  0.00000\"\n"
        "comment \"0.00000  0.00000  1.00000  0.00000\"\n"
        "comment \"Part Operation.1\"\n"
        "coolant flood\n"
        "comp off\n"
        "section \"Tool Change.1\" - tool 3 cut 0.0000 plunge 0.0000\n"
        "comment \"Start generation of : Tool Change.1\"\n"
        "comment \"TOOLCHANGEBEGINNING\"\n"
        "comment \"T3 End Mill D 10\"\n"
        "tool 3 flat d 10.0000 r 0.0000 flute 35.0000 len 0.0000 \"\"\n"
        "comment \"TOOLCHANGEEND\"\n"
        "comment \"End of generation of : Tool Change.1\"\n"
        "endsection\n"
        "section \"Profile Contouring.2\" - tool 3 cut 0.0000 plunge 0.0000\n"
        "comment \"Start generation of : Profile Contouring.2\"\n"
        "spindle 2400.0000 cw\n"
        "rapid -63.0000 -60.0000 50.0000\n"
        "rapid -63.0000 -60.0000 17.0000\n"
        "linear -63.0000 -60.0000 14.0000 f 300.0000\n"
        "linear -63.0000 8.0000 14.0000 f 1000.0000\n"
        // INDIRV +Y at the left of the circle: clockwise, to the first crossing of the LINE.
        "arc cw -42.0000 29.0000 14.0000 c -42.0000 8.0000 14.0000 n 0.0000 0.0000 1.0000 turns 0 f 1000.0000\n"
        "linear 40.0000 29.0000 14.0000 f 1000.0000\n"
        "arc cw 50.0000 19.0000 14.0000 c 40.0000 19.0000 14.0000 n 0.0000 0.0000 1.0000 turns 0 f 1000.0000\n"
        "linear 50.0000 -30.0000 14.0000 f 1000.0000\n"
        // ON,2,INTOF: past (30,-50) at 90 degrees to (30,-10) at 270 degrees.
        "arc cw 30.0000 -10.0000 14.0000 c 30.0000 -30.0000 14.0000 n 0.0000 0.0000 1.0000 turns 0 f 1000.0000\n"
        "linear -63.0000 -10.0000 14.0000 f 1000.0000\n"
        "linear -63.0000 -60.0000 14.0000 f 1000.0000\n"
        "rapid -63.0000 -60.0000 50.0000\n"
        "comment \"End of generation of : Profile Contouring.2\"\n"
        "endsection\n"
        "section \"Circular Milling.1\" - tool 3 cut 0.0000 plunge 0.0000\n"
        "comment \"Start generation of : Circular Milling.1\"\n"
        "rapid 12.0000 0.0000 30.0000\n"
        "rapid 12.0000 0.0000 3.0000\n"
        "linear 12.0000 0.0000 -5.0000 f 300.0000\n"
        // ON,2,INTOF on a LINE through the start: a full circle (end == start).
        "arc ccw 12.0000 0.0000 -5.0000 c 0.0000 0.0000 -5.0000 n 0.0000 0.0000 1.0000 turns 0 f 1000.0000\n"
        "rapid 12.0000 0.0000 30.0000\n"
        "comment \"End of generation of : Circular Milling.1\"\n"
        "spindle 0.0000 cw\n"
        "coolant off\n"
        "endsection\n";
    EXPECT_EQ(traceOf(result->toolpath), expected);
    ASSERT_EQ(result->warnings.size(), 1u);
    EXPECT_EQ(result->warnings[0].message, "TOOLNO ignored: the tool change is read from LOADTL");
    EXPECT_EQ(result->warnings[0].line, 20);
    // The full circle's end is exactly its start, so a post sees a whole circle.
    const Toolpath& tp = result->toolpath;
    const Arc& full = std::get<Arc>(tp.record(44));
    EXPECT_EQ(full.to, (Vec3{12, 0, -5}));
    EXPECT_EQ(tp.source(44).operationIndex, 2);
    EXPECT_EQ(tp.source(44).recordIndex, 66);
}

TEST(AptReader, NxClsfFile)
{
    auto result = readClFile(dataPath("nx_face_and_drill.cls"), ClFormat::Apt);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_EQ(traceOf(result->toolpath),
              "section \"FACE_MILLING\" - tool 2 cut 0.0000 plunge 0.0000\n"
              "comment \"centerline data\"\n"
              "tool 2 bull d 20.0000 r 1.0000 flute 0.0000 len 75.0000 \"MILL_D20R1\"\n"
              "spindle 3200.0000 cw\n"
              "coolant flood\n"
              "rapid -15.0000 -15.0000 50.0000\n"
              "rapid -15.0000 -15.0000 3.0000\n"
              "linear -15.0000 -15.0000 0.0000 f 250.0000\n"
              "linear 0.0000 -15.0000 0.0000 f 800.0000\n"
              // Axis (0,0,-1): counter-clockwise about -Z is clockwise seen from +Z.
              "arc cw -15.0000 0.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 800.0000\n"
              "linear -15.0000 20.0000 0.0000 f 800.0000\n"
              "arc ccw 5.0000 20.0000 0.0000 c -5.0000 20.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 800.0000\n"
              "rapid 5.0000 20.0000 50.0000\n"
              "rapid 30.0000 0.0000 3.0000\n"
              // Helix down from Z3 to Z-4, TIMES,2: two laps; the centre sits in the start's plane.
              "arc cw 30.0000 0.0000 -4.0000 c 25.0000 0.0000 3.0000 n 0.0000 0.0000 1.0000 turns 1 f 400.0000\n"
              "rapid 30.0000 0.0000 50.0000\n"
              "endsection\n"
              "section \"DRILLING\" - tool 7 cut 0.0000 plunge 0.0000\n"
              "comment \"centerline data\"\n"
              "tool 7 drill d 6.8000 r 0.0000 flute 0.0000 len 0.0000 \"DRILL_6_8\"\n"
              "spindle 1800.0000 cw\n"
              "rapid 20.0000 10.0000 50.0000\n"
              "cycle peck clear 50.0000 retract 3.0000 top 0.0000 bottom -18.0000 peck 4.0000 dwell 0.0000 f "
              "120.0000 return clear holes 2\n"
              "  hole 20.0000 10.0000 0.0000\n"
              "  hole 40.0000 10.0000 0.0000\n"
              // Another hole top: another R plane and bottom, so another Cycle.
              "cycle peck clear 50.0000 retract -2.0000 top -5.0000 bottom -23.0000 peck 4.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 40.0000 30.0000 -5.0000\n"
              "cycle drillDwell clear 50.0000 retract 2.0000 top 0.0000 bottom -10.0000 peck 0.0000 dwell 0.5000 f "
              "100.0000 return retract holes 2\n"
              "  hole 60.0000 10.0000 0.0000\n"
              "  hole 60.0000 30.0000 0.0000\n"
              "rapid 60.0000 30.0000 50.0000\n"
              "endsection\n"
              "spindle 0.0000 cw\n"
              "coolant off\n");
    // Eleven PAINT statements make one warning that lists their lines; the tool preselection another.
    ASSERT_EQ(result->warnings.size(), 2u);
    EXPECT_EQ(result->warnings[0].message,
              "PAINT (display statement) ignored (also on lines 6, 11, 14, 17, 20, 28, 33, 37 and 2 more)");
    EXPECT_EQ(result->warnings[0].line, 5);
    EXPECT_EQ(result->warnings[1].message, "SELECT (tool preselection) ignored: the CL model has no preselection");
    EXPECT_EQ(result->warnings[1].line, 8);
    EXPECT_EQ(sources(result->toolpath), "0:1 0:4 0:7 0:9 0:10 0:13 0:16 0:19 0:22 0:23 0:25 0:26 0:30 0:32 0:35 0:39 "
                                         "0:42 1:43 1:46 1:47 1:48 1:50 1:52 1:54 1:57 1:61 1:62 -1:63 -1:64 ");
}

TEST(AptReader, CreoInchFile)
{
    auto result = readClFile(dataPath("creo_inch_holes.apt"), ClFormat::Apt);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_EQ(traceOf(result->toolpath),
              "comment \"* Pro/CLfile Version Wildfire 5.0 - M060\"\n"
              "comment \"-> MFGNO / PLATE_HOLES\"\n"
              "comment \"PLATE_HOLES\"\n"
              "comment \"-> FEATNO / 112\"\n"
              "comment \"-> CUTCOM_GEOMETRY_TYPE / OUTPUT_ON_CENTER\"\n"
              // The CUTTER right after LOADTL describes the tool just loaded.
              "tool 4 bull d 12.7000 r 1.5875 flute 0.0000 len 0.0000 \"\"\n"
              "comment \"-> CUTTER / 0.500000\"\n"
              "comment \"-> CSYS / 1.0000000000, 0.0000000000, 0.0000000000, 0.0000000000, $\"\n"
              "comment \"->        0.0000000000, 1.0000000000, 0.0000000000, 0.0000000000, $\"\n"
              "comment \"->        0.0000000000, 0.0000000000, 1.0000000000, 0.0000000000\"\n"
              "spindle 4000.0000 cw\n"
              "rapid 25.4000 0.0000 25.4000\n"
              "linear 25.4000 0.0000 -6.3500 f 508.0000\n"
              // GOTO + four point lines round the circle: one whole lap back to the start.
              "arc ccw 25.4000 0.0000 -6.3500 c 0.0000 0.0000 -6.3500 n 0.0000 0.0000 1.0000 turns 0 f 508.0000\n"
              "rapid 25.4000 0.0000 25.4000\n"
              "comment \"-> FEATNO / 118\"\n"
              "linear 208.2292 0.0000 -15.8750 f 304.8000\n"
              "comment \"1ST ORBIT\"\n"
              "arc ccw 208.2292 0.0000 -14.8167 c 203.2000 0.0000 -15.8750 n 0.0000 0.0000 1.0000 turns 0 f 203.2000\n"
              "comment \"2ND ORBIT\"\n"
              "arc ccw 208.2292 0.0000 -13.7583 c 203.2000 0.0000 -14.8167 n 0.0000 0.0000 1.0000 turns 0 f 203.2000\n"
              "rapid 208.2292 0.0000 25.4000\n"
              "comment \"-> FEATNO / 124\"\n"
              "tool 9 flat d 7.1437 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 2500.0000 cw\n"
              "coolant flood\n"
              "rapid 50.8000 50.8000 25.4000\n"
              // RETURN 0.5 in: back to 12.7 mm above the top after each hole.
              "cycle peck clear 12.7000 retract 2.5400 top 0.0000 bottom -19.0500 peck 3.8100 dwell 0.0000 f "
              "152.4000 return clear holes 2\n"
              "  hole 50.8000 50.8000 0.0000\n"
              "  hole 76.2000 50.8000 0.0000\n"
              "tool 12 flat d 7.9375 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 600.0000 cw\n"
              "rapid 50.8000 50.8000 25.4000\n"
              // The tap's feed per revolution is wrapped so that later feeds stay per minute.
              "feedmode perRevolution\n"
              "cycle tap clear 25.4000 retract 2.5400 top 0.0000 bottom -12.7000 peck 0.0000 dwell 0.0000 f 1.4111 "
              "return retract holes 2\n"
              "  hole 50.8000 50.8000 0.0000\n"
              "  hole 76.2000 50.8000 0.0000\n"
              "feedmode perMinute\n"
              "linear 76.2000 50.8000 27.9400 f 254.0000\n"
              "coolant off\n"
              "spindle 0.0000 cw\n"
              "comment \"-> END /\"\n");
    EXPECT_TRUE(result->warnings.empty()) << warnings(result.value());
}

TEST(AptReader, EmptyFile)
{
    auto result = readClFile(dataPath("empty.apt"), ClFormat::Apt);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_TRUE(result->toolpath.empty());
    EXPECT_TRUE(result->warnings.empty());
    const ClImport blank = import("  \n\t\n\n");
    EXPECT_TRUE(blank.toolpath.empty());
    EXPECT_TRUE(blank.warnings.empty());
}

TEST(AptReader, MalformedFiles)
{
    auto number = readClFile(dataPath("malformed_number.apt"), ClFormat::Apt);
    ASSERT_FALSE(number.ok());
    EXPECT_EQ(number.error().toString(), dataPath("malformed_number.apt") + ":5:11: malformed number '2O.5'");
    auto continuation = readClFile(dataPath("malformed_continuation.aptsource"), ClFormat::Apt);
    ASSERT_FALSE(continuation.ok());
    EXPECT_EQ(continuation.error().toString(), dataPath("malformed_continuation.aptsource") +
                                                   ":5:51: the statement is continued with '$' but the file ends");
}

// ---- Lexical rules ----------------------------------------------------------------------------

TEST(AptReader, StatementsAreCaseInsensitiveWithBlanksAroundSlashAndComma)
{
    EXPECT_EQ(traceFini("fedrat / 120 , mmpm\ngoto  /  1 ,2, 3\n  Rapid\nGoTo/4,5,6\n"),
              "linear 1.0000 2.0000 3.0000 f 120.0000\nrapid 4.0000 5.0000 6.0000\n");
}

TEST(AptReader, NumberForms)
{
    EXPECT_EQ(traceFini("RAPID\nGOTO/-62.00000,1.5E+01,+5\nRAPID\nGOTO/.5,5.,-2.5e-1\n"),
              "rapid -62.0000 15.0000 5.0000\nrapid 0.5000 5.0000 -0.2500\n");
}

TEST(AptReader, NumbersRoundTripExactly)
{
    const ClImport imported = import("FEDRAT/333.3333,MMPM\nGOTO/1.23456789,-0.1,1e-7\nFINI\n");
    const Linear& move = std::get<Linear>(imported.toolpath.record(0));
    EXPECT_EQ(move.to.x, 1.23456789);
    EXPECT_EQ(move.to.y, -0.1);
    EXPECT_EQ(move.to.z, 1e-7);
    EXPECT_EQ(move.feedMmPerMin, 333.3333);
}

TEST(AptReader, ContinuationLines)
{
    // '$' at the end of a line, blank lines and a remark inside, and a remark after the statement.
    const ClImport imported = import("FEDRAT/100,MMPM\n"
                                     "GOTO/ 1.0,$\n"
                                     "\n"
                                     "$$ inside the statement\n"
                                     "   2.0, $\n"
                                     "   3.0 $$ after it\n"
                                     "FINI\n");
    EXPECT_EQ(traceOf(imported.toolpath),
              "linear 1.0000 2.0000 3.0000 f 100.0000\ncomment \"inside the statement\"\ncomment \"after it\"\n");
    EXPECT_EQ(sources(imported.toolpath), "-1:2 -1:4 -1:6 ");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
}

TEST(AptReader, ContinuationWithRemarkOnTheSameLine)
{
    // Creo writes "CIRCLE/...,$ $$ 1ST ORBIT": continued, and a remark.
    EXPECT_EQ(traceFini("FEDRAT/100,MMPM\nGOTO/10,0,0\nCIRCLE/0,0,0,$ $$ orbit\n0,0,1,10\nGOTO/-10,0,0\n"),
              "linear 10.0000 0.0000 0.0000 f 100.0000\ncomment \"orbit\"\n"
              "arc ccw -10.0000 0.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n");
}

TEST(AptReader, CrLfLineEndsAndByteOrderMark)
{
    const ClImport imported = import("\xEF\xBB\xBFRAPID\r\nGOTO/1,$\r\n2,3\r\nPPRINT/DONE\r\nFINI\r\n");
    EXPECT_EQ(traceOf(imported.toolpath), "rapid 1.0000 2.0000 3.0000\ncomment \"DONE\"\n");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
    // The byte order mark does not count as a column.
    const base::Error error = failure("\xEF\xBB\xBFGOTO/1,2,x\r\n");
    EXPECT_EQ(error.message, "GOTO expects numbers, found X");
    EXPECT_EQ(error.line, 1);
    EXPECT_EQ(error.column, 10);
}

TEST(AptReader, RemarksAndTextStatements)
{
    const ClImport imported = import("PARTNO BRACKET-17\n"
                                     "$$ a remark\n"
                                     "$$\n"
                                     "PPRINT/ CHECK CLAMPS, THEN $ START\n"
                                     "PPRINT NO SLASH\n"
                                     "REMARK  kept\n"
                                     "TPRINT/T1 End Mill D 10\n"
                                     "INSERT/G65 P9810 Z-10.\n"
                                     "INSERT M08\n"
                                     "STOP\n"
                                     "OPSTOP\n"
                                     "FINI\n");
    EXPECT_EQ(traceOf(imported.toolpath), "comment \"BRACKET-17\"\n"
                                          "comment \"a remark\"\n"
                                          "comment \"CHECK CLAMPS, THEN $ START\"\n"
                                          "comment \"NO SLASH\"\n"
                                          "comment \"kept\"\n"
                                          "comment \"T1 End Mill D 10\"\n"
                                          "passthrough \"G65 P9810 Z-10.\"\n"
                                          "passthrough \"M08\"\n"
                                          "stop\n"
                                          "stop optional\n");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
}

// ---- Machine state ----------------------------------------------------------------------------

TEST(AptReader, InchUnitsAreConverted)
{
    EXPECT_EQ(traceFini("UNITS/INCHES\n"
                        "CUTTER/0.5,0.25\n"
                        "LOADTL/1\n"
                        "FEDRAT/10,IPM\n"
                        "GOTO/1,2,-0.5\n"
                        "FEDRAT/20\n"  // no unit: the file's unit (IPM here)
                        "GOTO/2,2,-0.5\n"
                        "FEDRAT/0.004,IPR\n"
                        "GOTO/2,3,-0.5\n"
                        "FEDRAT/100,MMPM\n"  // an explicit metric unit is taken as it stands
                        "GOTO/3,3,-0.5\n"
                        "UNITS/MM\n"
                        "GOTO/3,3,1\n"),
              "tool 1 ball d 12.7000 r 6.3500 flute 0.0000 len 0.0000 \"\"\n"
              "linear 25.4000 50.8000 -12.7000 f 254.0000\n"
              "linear 50.8000 50.8000 -12.7000 f 508.0000\n"
              "feedmode perRevolution\n"
              "linear 50.8000 76.2000 -12.7000 f 0.1016\n"
              "feedmode perMinute\n"
              "linear 76.2000 76.2000 -12.7000 f 100.0000\n"
              "linear 3.0000 3.0000 1.0000 f 100.0000\n");
}

TEST(AptReader, FeedRateForms)
{
    EXPECT_EQ(traceFini("FEDRAT/ 300.0000,MMPM\nGOTO/1,0,0\n"
                        "FEDRAT/MMPM,250\nGOTO/2,0,0\n"
                        "FEDRAT/MMPR,0.1\nGOTO/3,0,0\n"
                        "FEDRAT/0.2\nGOTO/4,0,0\n"  // the mode stays per revolution
                        "FEDRAT/PERMIN,500\nGOTO/5,0,0\n"),
              "linear 1.0000 0.0000 0.0000 f 300.0000\n"
              "linear 2.0000 0.0000 0.0000 f 250.0000\n"
              "feedmode perRevolution\n"
              "linear 3.0000 0.0000 0.0000 f 0.1000\n"
              "linear 4.0000 0.0000 0.0000 f 0.2000\n"
              "feedmode perMinute\n"
              "linear 5.0000 0.0000 0.0000 f 500.0000\n");
    const base::Error two = failure("FEDRAT/100,200\n");
    EXPECT_EQ(two.message, "FEDRAT has more than one value");
    EXPECT_EQ(two.column, 12);
    const base::Error word = failure("FEDRAT/100,MMPS\n");
    EXPECT_EQ(word.message, "FEDRAT: unknown word MMPS (expected MMPM, IPM, MMPR, IPR, PERMIN or PERREV)");
    EXPECT_EQ(word.column, 12);
    EXPECT_EQ(failure("FEDRAT/-5\n").message, "FEDRAT: negative feed");
    EXPECT_EQ(failure("FEDRAT/MMPM\n").message, "FEDRAT needs a feed value");
}

TEST(AptReader, SpindleForms)
{
    const ClImport imported = import("SPINDL/ 70.0000,RPM,CLW\n"
                                     "SPINDL/RPM,1500,CCLW\n"
                                     "SPINDL/OFF\n"
                                     "SPINDL/ON\n"
                                     "SPINDL/CLW\n"
                                     "SPINDL/2000\n"
                                     "SPINDL/RPM,900,CLW,RANGE,2\n"
                                     "SPINDL/SMM,200,CLW\n"
                                     "FINI\n");
    EXPECT_EQ(traceOf(imported.toolpath), "spindle 70.0000 cw\n"
                                          "spindle 1500.0000 ccw\n"
                                          "spindle 0.0000 ccw\n"
                                          "spindle 1500.0000 ccw\n"  // ON restores the last speed
                                          "spindle 1500.0000 cw\n"
                                          "spindle 2000.0000 cw\n"
                                          "spindle 900.0000 cw\n");
    EXPECT_EQ(warnings(imported), "t.apt:7:20: SPINDL: RANGE ignored\n"
                                  "t.apt:8:8: SPINDL with surface speed (SMM) is not supported: ignored\n");
    const ClImport early = import("SPINDL/ON\nFINI\n");
    EXPECT_TRUE(early.toolpath.empty());
    EXPECT_EQ(warnings(early), "t.apt:1:1: SPINDL without a speed before any speed was set: ignored\n");
    EXPECT_EQ(failure("SPINDL/RPM\n").message, "SPINDL needs a speed, ON or OFF");
    EXPECT_EQ(failure("SPINDL/100,200\n").column, 12);
}

TEST(AptReader, CoolantAndCutterCompensation)
{
    const ClImport imported = import("COOLNT/ON\nCOOLNT/FLOOD\nCOOLNT/MIST\nCOOLNT/THRU\nCOOLNT/OFF\nCOOLNT/AIR\n"
                                     "CUTCOM/LEFT\nCUTCOM/ON,RIGHT,12\nCUTCOM/OFF\nCUTCOM/ON\nFINI\n");
    EXPECT_EQ(traceOf(imported.toolpath), "coolant flood\ncoolant flood\ncoolant mist\ncoolant throughTool\n"
                                          "coolant off\ncomp left\ncomp right\ncomp off\n");
    EXPECT_EQ(warnings(imported), "t.apt:6:8: COOLNT/AIR is not supported: ignored\n"
                                  "t.apt:10:1: CUTCOM/ON without LEFT or RIGHT ignored\n");
    EXPECT_EQ(failure("COOLNT/5\n").message, "COOLNT needs ON, FLOOD, MIST, THRU or OFF");
    EXPECT_EQ(failure("CUTCOM/XYPLAN\n").message, "CUTCOM needs LEFT, RIGHT or OFF");
}

TEST(AptReader, ToolChangesTakeTheCutterGeometry)
{
    const ClImport imported = import("TOOL PATH/ROUGH,TOOL,EM12\n"
                                     "CUTTER/12,0.5,5.5,0,0,0,30\n"  // before the load (CATIA, NX)
                                     "LOADTL/5,1,LENGTH,80\n"
                                     "FEDRAT/100\n"
                                     "GOTO/0,0,5\n"
                                     "CUTTER/8,4\n"  // after motion: for the next load
                                     "LOAD/TOOL,6,ADJUST,6\n"
                                     "LOADTL/7\n"                      // no geometry of its own ...
                                     "TLDATA/DRILL,8.5,0,70,118,40\n"  // ... until this fills it in (Creo)
                                     "LOAD/SPINDLE,1\n"
                                     "FINI\n");
    EXPECT_EQ(traceOf(imported.toolpath), "section \"ROUGH\" - tool 5 cut 0.0000 plunge 0.0000\n"
                                          "tool 5 bull d 12.0000 r 0.5000 flute 30.0000 len 80.0000 \"EM12\"\n"
                                          "linear 0.0000 0.0000 5.0000 f 100.0000\n"
                                          "tool 6 ball d 8.0000 r 4.0000 flute 0.0000 len 0.0000 \"\"\n"
                                          "tool 7 drill d 8.5000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
                                          "endsection\n");
    EXPECT_EQ(warnings(imported), "t.apt:10:1: LOAD other than LOAD/TOOL ignored\n");
    // A load without geometry never takes another tool's; a tool loaded again keeps its own.
    EXPECT_EQ(traceFini("CUTTER/10,5\nLOADTL/1\nLOADTL/2\nFEDRAT/1\nGOTO/0,0,0\nCUTTER/6\nLOADTL/1\n"),
              "tool 1 ball d 10.0000 r 5.0000 flute 0.0000 len 0.0000 \"\"\n"
              "tool 2 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "linear 0.0000 0.0000 0.0000 f 1.0000\n"
              "tool 1 flat d 6.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n");
    EXPECT_EQ(traceFini("TOOL PATH/A,TOOL,BALL10\nCUTTER/10,5\nLOADTL/1\nLOADTL/2\nLOADTL/1\n"),
              "section \"A\" - tool 1 cut 0.0000 plunge 0.0000\n"
              "tool 1 ball d 10.0000 r 5.0000 flute 0.0000 len 0.0000 \"BALL10\"\n"
              "tool 2 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "tool 1 ball d 10.0000 r 5.0000 flute 0.0000 len 0.0000 \"BALL10\"\n"
              "endsection\n");
    EXPECT_EQ(traceFini("LOADTL/3,LENGTH,90\nTLDATA/MILL,16,2,75,0,0\n"),
              "tool 3 bull d 16.0000 r 2.0000 flute 0.0000 len 75.0000 \"\"\n");
    EXPECT_EQ(traceFini("LOADTL/3,LENGTH,90\nCUTTER/16\n"),
              "tool 3 flat d 16.0000 r 0.0000 flute 0.0000 len 90.0000 \"\"\n");
    EXPECT_EQ(failure("LOADTL/2.5\n").message, "tool number must be a whole number >= 0");
    EXPECT_EQ(failure("LOADTL/ADJUST,1\n").message, "LOADTL needs a tool number");
    EXPECT_EQ(failure("CUTTER/0\n").message, "CUTTER needs a diameter > 0");
}

TEST(AptReader, DelayGivesDwell)
{
    EXPECT_EQ(traceFini("DELAY/2.5\n"), "dwell 2.5000\n");
    EXPECT_EQ(failure("DELAY/2,REV\n").message, "DELAY expects one time in seconds");
}

// ---- Sections, END and FINI -------------------------------------------------------------------

TEST(AptReader, SectionsNumberRecords)
{
    const ClImport imported = import("LOADTL/4\n"
                                     "$$ OPERATION NAME : Pocket.1\n"
                                     "FEDRAT/100\n"
                                     "GOTO/0,0,0\n"
                                     "$$ OPERATION NAME : Pocket.2\n"
                                     "LOADTL/9\n"
                                     "END-OF-PATH\n"
                                     "GOTO/1,0,0\n"
                                     "END-OF-PATH\n"
                                     "TOOL PATH/CONTOUR,TOOL,T12\n"
                                     "GOTO/2,0,0\n"
                                     "END\n"
                                     "GOTO/3,0,0\n"
                                     "FINI\n"
                                     "GOTO/4,0,0\n"
                                     "more\n");
    EXPECT_EQ(traceOf(imported.toolpath), "tool 4 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
                                          "section \"Pocket.1\" - tool 4 cut 0.0000 plunge 0.0000\n"
                                          "linear 0.0000 0.0000 0.0000 f 100.0000\n"
                                          "endsection\n"
                                          "section \"Pocket.2\" - tool 9 cut 0.0000 plunge 0.0000\n"
                                          "tool 9 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
                                          "endsection\n"
                                          "linear 1.0000 0.0000 0.0000 f 100.0000\n"
                                          "section \"CONTOUR\" - tool 9 cut 0.0000 plunge 0.0000\n"
                                          "linear 2.0000 0.0000 0.0000 f 100.0000\n"
                                          "endsection\n"
                                          "linear 3.0000 0.0000 0.0000 f 100.0000\n");
    EXPECT_EQ(sources(imported.toolpath), "-1:1 0:2 0:4 0:5 1:5 1:6 1:7 -1:8 2:10 2:11 2:12 -1:13 ");
    EXPECT_EQ(warnings(imported), "t.apt:9:1: END-OF-PATH without an open TOOL PATH\n"
                                  "t.apt:15:1: text after FINI is ignored\n");
}

TEST(AptReader, SectionsCloseAtTheEndOfInput)
{
    const ClImport imported = import("TOOL PATH/FACE,TOOL,T1\nGOTO/0,0,0\n\n");
    EXPECT_EQ(sources(imported.toolpath), "0:1 0:2 0:3 ");
    EXPECT_EQ(warnings(imported), "t.apt:2:1: feed motion before any FEDRAT: its feed is 0\n"
                                  "t.apt:3: no FINI at the end of the file: it may be truncated\n");
}

TEST(AptReader, IgnoredAndUnknownStatements)
{
    const ClImport imported = import("MACHIN/FANUC,6\n"
                                     "INTOL/0.01\n"
                                     "OUTTOL/0.01\n"
                                     "AUTOPS\n"
                                     "MULTAX/ON\n"
                                     "MSYS/0,0,0,1,0,0,0,1,0\n"
                                     "MSYS/10,0,0,1,0,0,0,1,0\n"
                                     "ORIGIN/0,0,100\n"
                                     "CHANNEL,1\n"
                                     "CATMAT/ C:\\dir\\part.CATPart\n"
                                     "  SWITCH/9\n"
                                     "ROTABL/30,CLW\n"
                                     "FINI\n");
    EXPECT_TRUE(imported.toolpath.empty());
    EXPECT_EQ(warnings(imported),
              "t.apt:7:1: MSYS (machine coordinate system) is not applied: coordinates are read as written\n"
              "t.apt:8:1: ORIGIN (NC axis system) is not applied: coordinates are read as written\n"
              "t.apt:9:1: unknown statement CHANNEL ignored\n"
              "t.apt:10:1: unknown statement CATMAT ignored\n"
              "t.apt:11:3: unknown statement SWITCH ignored\n"
              "t.apt:12:1: unknown statement ROTABL ignored\n");
}

// ---- Malformed input --------------------------------------------------------------------------

TEST(AptReader, MalformedInputGivesLineAndColumn)
{
    struct Case {
        std::string text;
        std::string message;
        int line, column;
    };
    const std::vector<Case> cases = {
        {"GOTO/1,2,3\nGOTO/1.2.3,4,5\n", "malformed number '1.2.3'", 2, 6},
        {"GOTO/1,2,3\nGOTO 4,5,6\n", "expected '/' after GOTO", 2, 6},
        {"FEDRAT 100\n", "expected '/' after FEDRAT", 1, 8},
        {"GOTO/1,2\n", "GOTO needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found 2", 1, 6},
        {"GOTO\n", "GOTO needs '/' and its values", 1, 5},
        {"GOTO/1,,3\n", "missing value", 1, 8},
        {"GOTO/1,2,3,\n", "the statement ends with ',' but the file ends", 1, 11},
        {"GOTO/1,2,$\n\n", "the statement is continued with '$' but the file ends", 1, 10},
        {"GOTO/1,2 3\n", "expected ',' between values, found '3'", 1, 10},
        {"GOTO/1,2,#\n", "unexpected character '#'", 1, 10},
        {"GOTO/1,2,MM\n", "GOTO expects numbers, found MM", 1, 10},
        {"TLON,GOFWD/(CIRCLE/0,0,0,1\n", "'(' without ')'", 1, 12},
        {"GOTO/1,2,3)\n", "')' without '('", 1, 11},
        {"UNITS/FEET\n", "UNITS expects MM or INCHES", 1, 7},
        {"/1,2,3\n", "expected a statement word", 1, 1},
        {"RAPID/1\n", "RAPID takes no values", 1, 7},
    };
    for (const Case& c : cases) {
        const base::Error error = failure(c.text);
        EXPECT_EQ(error.message, c.message) << c.text;
        EXPECT_EQ(error.file, "t.apt") << c.text;
        EXPECT_EQ(error.line, c.line) << c.text;
        EXPECT_EQ(error.column, c.column) << c.text;
    }
}

TEST(AptReader, MalformedInputGivesNoToolpath)
{
    auto result = readAptSource("FEDRAT/100\nGOTO/1,2,3\nGOTO/4,5\n", "t.apt");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().toString(), "t.apt:3:6: GOTO needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found 2");
}

// ---- The common API ---------------------------------------------------------------------------

TEST(ClImport, FormatFromExtensionAndName)
{
    EXPECT_EQ(clFormatFromExtension("part.apt"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromExtension("/jobs/Part.APTSOURCE"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromExtension("op.cl"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromExtension("op.Cls"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromExtension("pocket.DUMP"), ClFormat::FreeCadDump);
    EXPECT_EQ(clFormatFromExtension("program.nc"), std::nullopt);
    EXPECT_EQ(clFormatFromExtension("apt"), std::nullopt);
    EXPECT_EQ(clFormatFromName("apt"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromName("APT"), ClFormat::Apt);
    EXPECT_EQ(clFormatFromName("freecad-dump"), ClFormat::FreeCadDump);
    EXPECT_EQ(clFormatFromName("freecad"), std::nullopt);
    for (ClFormat format : {ClFormat::Apt, ClFormat::FreeCadDump, ClFormat::Trace})
        EXPECT_EQ(clFormatFromName(clFormatName(format)), format);
}

TEST(ClImport, UnreadableFileNamesThePath)
{
    const std::string missing = dataPath("no-such-file.apt");
    auto result = readClFile(missing, ClFormat::Apt);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().file, missing);
    EXPECT_EQ(result.error().message, "cannot open: No such file or directory");
    auto directory = readClFile(dataPath(""), ClFormat::FreeCadDump);
    ASSERT_FALSE(directory.ok());
    EXPECT_EQ(directory.error().message, "cannot read: it is a folder, not a file");
}

TEST(AptReader, AFileIsReadInChunksAsTheTextIs)
{
    // More than two 1 MiB chunks, with continued statements, remarks inside them and CRLF lines,
    // so that some of them fall on a chunk boundary.
    std::string apt = "TOOL PATH/LONG,TOOL,D6\r\nLOADTL/1\nFEDRAT/300,MMPM\nGOTO/0,0,10\n";
    for (int i = 0; apt.size() < 2500000; ++i) {
        const std::string x = std::to_string(i % 97), y = std::to_string(i % 89);
        if (i % 7 == 0)
            apt += "GOTO/" + x + ",$\n$$ between the lines\n   " + y + ",-1\r\n";
        else
            apt += "GOTO/" + x + "," + y + ",-1\r\n";
        if (i % 1000 == 0)
            apt += "PAINT/COLOR,3\n";  // a warning, repeated: one message listing lines
    }
    apt += "END-OF-PATH\nFINI\n";
    const std::string trace = test::sameFromFileAndText(ClFormat::Apt, apt);
    EXPECT_GT(std::count(trace.begin(), trace.end(), '\n'), 50000);
}
