// FreeCAD path dump import: the seed-004 dump, a drilling and helix job, every command, arc
// planes, canned cycles, and malformed dumps reported with line and column.
#include "ClImportTestSupport.h"

using namespace camwb;
using namespace camwb::toolpath;

namespace {

ClImport import(std::string_view text) { return test::importAs(ClFormat::FreeCadDump, text); }
std::string trace(std::string_view text) { return traceOf(import(text).toolpath); }
base::Error failure(std::string_view text) { return test::failureAs(ClFormat::FreeCadDump, text); }
std::string warnings(const ClImport& imported) { return test::warningsText(imported); }
std::string sources(const Toolpath& toolpath) { return test::sourcesText(toolpath); }
std::string dataPath(const std::string& name) { return test::clDataPath(name); }

// A dump whose position is known: the start of most tests.
const std::string kAt = "Command G0 [ X:0 Y:0 Z:10 ]\n";
const std::string kAtTrace = "rapid 0.0000 0.0000 10.0000\n";

}  // namespace

// ---- Whole files ------------------------------------------------------------------------------

TEST(FreeCadDumpReader, Seed004Obr30Imports)
{
    // seed-004 §2.9 Obr. 30 without the Czech annotations and the "..." line.
    auto result = readClFile(dataPath("seed004_obr30.dump"), ClFormat::FreeCadDump);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_EQ(traceOf(result->toolpath),
              "comment \"This output produced with the dump post processor\"\n"
              "comment \"Dump is useful for inspecting the raw commands in your paths\"\n"
              "comment \"but is not useful for driving machines.\"\n"
              "comment \"Consider setting a default postprocessor in your project or\"\n"
              "comment \"exporting your paths using a specific post that matches your machine\"\n"
              "section \"T1: D16\" - tool 1 cut 0.0000 plunge 0.0000\n"
              "tool 1 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 2000.0000 cw\n"
              "endsection\n"
              "section \"Pocket_Shape\" - tool 1 cut 0.0000 plunge 0.0000\n"
              // The first move names Z only: a retract in Z alone, X and Y unknown until line 14.
              "rapid z 20.0000\n"
              "rapid x 83.0000 y 67.0000\n"
              "rapid z 18.0000\n"
              "linear 83.0000 67.0000 12.5000 f 199.9980\n"
              "linear 7.0000 67.0000 12.5000 f 199.9980\n"
              "arc cw 8.5073 29.2680 12.5000 c 6.2655 103.4900 12.5000 n 0.0000 0.0000 1.0000 turns 0 f 199.9980\n"
              "endsection\n");
    const std::string file = dataPath("seed004_obr30.dump");
    EXPECT_EQ(warnings(result.value()),
              // The "..." line held the moves that bring the tool onto this arc's circle.
              file + ":18: the arc's start and end radii differ by 37.7585 mm (36.4974 and 74.2558)\n");
    EXPECT_EQ(sources(result->toolpath),
              "-1:1 -1:2 -1:3 -1:4 -1:5 0:7 0:9 0:10 0:11 1:11 1:13 1:14 1:15 1:16 1:17 1:18 1:19 ");
    // 3.3333 mm/s is 199.998 mm/min, from the file's own digits.
    EXPECT_EQ(std::get<Linear>(result->toolpath.record(14)).feedMmPerMin, 3.3333 * 60);
}

TEST(FreeCadDumpReader, DrillingAndHelixFile)
{
    auto result = readClFile(dataPath("freecad_drill_helix.dump"), ClFormat::FreeCadDump);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    EXPECT_EQ(traceOf(result->toolpath),
              "comment \"This output produced with the dump post processor\"\n"
              "comment \"Dump is useful for inspecting the raw commands in your paths\"\n"
              "comment \"but is not useful for driving machines.\"\n"
              "comment \"Consider setting a default postprocessor in your project or\"\n"
              "comment \"exporting your paths using a specific post that matches your machine\"\n"
              "section \"Fixture\" - tool 0 cut 0.0000 plunge 0.0000\n"
              "workoffset 1\n"
              "endsection\n"
              "section \"TC: 6.8mm Drill\" - tool 4 cut 0.0000 plunge 0.0000\n"
              "tool 4 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 1800.0000 cw\n"
              "endsection\n"
              "section \"Drilling\" - tool 4 cut 0.0000 plunge 0.0000\n"
              "comment \"Begin Drilling\"\n"
              "rapid z 15.0000\n"
              // G98: back to the Z before the cycle; the hole top is taken as R.
              "cycle peck clear 15.0000 retract 3.0000 top 3.0000 bottom -12.0000 peck 3.0000 dwell 0.0000 f "
              "120.0000 return clear holes 2\n"
              "  hole 10.0000 10.0000 3.0000\n"
              "  hole 30.0000 10.0000 3.0000\n"
              "cycle peck clear 15.0000 retract 3.0000 top 3.0000 bottom -15.0000 peck 3.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 30.0000 30.0000 3.0000\n"
              "rapid z 15.0000\n"
              "endsection\n"
              "section \"Spot\" - tool 4 cut 0.0000 plunge 0.0000\n"
              "rapid z 15.0000\n"
              // The second G82 names only X and Y: R, Z, P and F are modal.
              "cycle drillDwell clear 15.0000 retract 2.0000 top 2.0000 bottom -1.0000 peck 0.0000 dwell 0.5000 f "
              "90.0000 return retract holes 2\n"
              "  hole 10.0000 10.0000 2.0000\n"
              "  hole 30.0000 10.0000 2.0000\n"
              // G99 left the tool at R: that is the Z before the next run.
              "cycle drill clear 2.0000 retract 2.0000 top 2.0000 bottom -4.0000 peck 0.0000 dwell 0.0000 f 90.0000 "
              "return retract holes 1\n"
              "  hole 30.0000 30.0000 2.0000\n"
              "rapid z 15.0000\n"
              "endsection\n"
              "section \"TC: 8mm Endmill\" - tool 2 cut 0.0000 plunge 0.0000\n"
              "tool 2 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 5000.0000 cw\n"
              "endsection\n"
              "section \"Helix\" - tool 2 cut 0.0000 plunge 0.0000\n"
              "rapid z 20.0000\n"
              "rapid x 49.0000 y 30.0000\n"
              "rapid z 15.0000\n"
              "linear z 15.0000 f 199.9980\n"
              "arc cw 41.0000 30.0000 14.5830 c 45.0000 30.0000 15.0000 n 0.0000 0.0000 1.0000 turns 0 f 199.9980\n"
              "arc cw 49.0000 30.0000 14.1670 c 45.0000 30.0000 14.5830 n 0.0000 0.0000 1.0000 turns 0 f 199.9980\n"
              "arc cw 49.0000 30.0000 14.1670 c 45.0000 30.0000 14.1670 n 0.0000 0.0000 1.0000 turns 0 f 199.9980\n"
              "arc ccw 39.0000 30.0000 14.1670 c 44.0000 30.0000 14.1670 n 0.0000 1.0000 0.0000 turns 0 f 120.0000\n"
              "rapid z 20.0000\n"
              "spindle 0.0000 cw\n"
              "coolant off\n"
              "endsection\n");
    EXPECT_EQ(result->warnings.size(), 0u) << warnings(result.value());
}

TEST(FreeCadDumpReader, EmptyDump)
{
    const ClImport imported = import("");
    EXPECT_TRUE(imported.toolpath.empty());
    EXPECT_TRUE(imported.warnings.empty());
    EXPECT_TRUE(import("\n  \n").toolpath.empty());
}

TEST(FreeCadDumpReader, MalformedFile)
{
    auto result = readClFile(dataPath("malformed_bracket.dump"), ClFormat::FreeCadDump);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().toString(), dataPath("malformed_bracket.dump") + ":3:12: '[' without ']'");
}

// ---- Motion -----------------------------------------------------------------------------------

TEST(FreeCadDumpReader, MovesKeepMissingAxesAndFeeds)
{
    EXPECT_EQ(trace(kAt + "Command G00 [ Z:2 ]\n"
                          "Command G1 [ F:10 Z:-1 ]\n"
                          "Command G01 [ X:5 ]\n"            // no F: the last feed
                          "Command G0 [ F:0 Y:7 ]\n"         // F on a rapid is no feed
                          "Command G1 [ X:6 Y:8 Z:-1.5 ]\n"  // still 600 mm/min
                          "Command G1 [ F:25 ]\n"            // a feed alone
                          "Command G1 [ X:7 ]\n"),
              kAtTrace + "rapid z 2.0000\nlinear z -1.0000 f 600.0000\n"
                         "linear x 5.0000 f 600.0000\nrapid y 7.0000\n"
                         "linear 6.0000 8.0000 -1.5000 f 600.0000\nlinear x 7.0000 f 1500.0000\n");
}

TEST(FreeCadDumpReader, FeedsAreMillimetresPerSecond)
{
    const ClImport imported = import(kAt + "Command G1 [ F:3.3333 X:1 ]\nCommand G1 [ F:0.016667 X:2 ]\n");
    EXPECT_EQ(std::get<Linear>(imported.toolpath.record(1)).feedMmPerMin, 3.3333 * 60);
    EXPECT_EQ(std::get<Linear>(imported.toolpath.record(2)).feedMmPerMin, 0.016667 * 60);
    EXPECT_EQ(traceOf(imported.toolpath), kAtTrace + "linear x 1.0000 f 199.9980\n"
                                                     "linear x 2.0000 f 1.0000\n");
}

TEST(FreeCadDumpReader, UnknownStartAxes)
{
    // A move gives the axes it names and no others: nothing is taken from later lines or guessed.
    const ClImport imported = import("Command G0 [ Z:20 ]\nCommand G1 [ F:1 X:5 Z:3 ]\n");
    EXPECT_EQ(traceOf(imported.toolpath), "rapid z 20.0000\nlinear x 5.0000 z 3.0000 f 60.0000\n");
    EXPECT_EQ(warnings(imported), "");
    EXPECT_EQ(failure("Command G2 [ I:1 X:2 Y:0 Z:0 ]\n").message,
              "arc from an unknown position (no move with X, Y and Z before it)");
}

TEST(FreeCadDumpReader, ArcsInEachPlane)
{
    // G17 (default): G2 clockwise seen from +Z.
    EXPECT_EQ(trace(kAt + "Command G2 [ F:1 I:5 J:0 K:0 X:10 Y:0 Z:10 ]\n"),
              kAtTrace + "arc cw 10.0000 0.0000 10.0000 c 5.0000 0.0000 10.0000 n 0.0000 0.0000 1.0000 turns 0 f "
                         "60.0000\n");
    EXPECT_EQ(trace(kAt + "Command G3 [ F:1 I:5 J:0 X:10 Y:0 ]\n"),
              kAtTrace + "arc ccw 10.0000 0.0000 10.0000 c 5.0000 0.0000 10.0000 n 0.0000 0.0000 1.0000 turns 0 f "
                         "60.0000\n");
    // G18 is the ZX plane, seen from +Y (ISO): the normal is +Y and I, K give the centre.
    EXPECT_EQ(trace(kAt + "Command G18 [ ]\nCommand G2 [ F:1 I:5 J:7 K:0 X:10 Z:10 ]\n"),
              kAtTrace + "arc cw 10.0000 0.0000 10.0000 c 5.0000 0.0000 10.0000 n 0.0000 1.0000 0.0000 turns 0 f "
                         "60.0000\n");
    // G19: the YZ plane, normal +X.
    EXPECT_EQ(trace(kAt + "Command G19 [ ]\nCommand G3 [ F:1 J:0 K:-5 Y:0 Z:0 ]\n"),
              kAtTrace + "arc ccw 0.0000 0.0000 0.0000 c 0.0000 0.0000 5.0000 n 1.0000 0.0000 0.0000 turns 0 f "
                         "60.0000\n");
    // A helix: Z moves; P counts the laps.
    EXPECT_EQ(trace(kAt + "Command G3 [ F:1 I:5 J:0 P:3 X:0 Y:0 Z:4 ]\n"),
              kAtTrace + "arc ccw 0.0000 0.0000 4.0000 c 5.0000 0.0000 10.0000 n 0.0000 0.0000 1.0000 turns 2 f "
                         "60.0000\n");
}

TEST(FreeCadDumpReader, ArcChecks)
{
    const ClImport off = import(kAt + "Command G2 [ F:1 I:5 J:0 X:10.5 Y:0 ]\n");
    EXPECT_EQ(warnings(off), "t.dump:2: the arc's start and end radii differ by 0.5 mm (5 and 5.5)\n");
    // Within the dumper's rounding (5 significant digits): no warning.
    EXPECT_TRUE(import(kAt + "Command G2 [ F:1 I:-0.73447 J:36.49 X:-1.4689 Y:0 ]\n").warnings.empty());
    const base::Error r = failure(kAt + "Command G2 [ F:1 R:5 X:10 Y:0 ]\n");
    EXPECT_EQ(r.message, "arcs with R are not supported (FreeCAD writes I, J, K)");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 18);
    EXPECT_EQ(failure(kAt + "Command G2 [ F:1 K:5 X:10 Y:0 ]\n").message,
              "arc without a centre: I, J, K are 0 in the arc's plane");
    EXPECT_EQ(failure(kAt + "Command G2 [ F:1 I:5 P:1.5 X:10 ]\n").message, "P (turns) must be a whole number >= 1");
}

TEST(FreeCadDumpReader, RotaryAxesAreErrors)
{
    const base::Error error = failure(kAt + "Command G1 [ A:30 F:1 X:1 ]\n");
    EXPECT_EQ(error.message, "rotary axis A is not supported (it needs the machine's kinematics)");
    EXPECT_EQ(error.line, 2);
    EXPECT_EQ(error.column, 14);
}

TEST(FreeCadDumpReader, WrappedCommandKeepsItsFirstLine)
{
    const ClImport imported = import(kAt + "Command G1 [ F:1\n  X:4 Y:5\n Z:6 ]\nCommand G0 [ Z:20 ]\n");
    EXPECT_EQ(traceOf(imported.toolpath), kAtTrace + "linear 4.0000 5.0000 6.0000 f 60.0000\n"
                                                     "rapid z 20.0000\n");
    EXPECT_EQ(sources(imported.toolpath), "-1:1 -1:2 -1:5 ");
    const base::Error bad = failure(kAt + "Command G1 [ F:1\n  X:4 Y:five ]\n");
    EXPECT_EQ(bad.message, "malformed number 'five'");
    EXPECT_EQ(bad.line, 3);
    EXPECT_EQ(bad.column, 9);
}

// ---- Machine state ----------------------------------------------------------------------------

TEST(FreeCadDumpReader, MachineCommands)
{
    const ClImport imported = import("Command M6 [ T:3 ]\n"
                                     "Command M3 [ S:2500 ]\n"
                                     "Command M4 [ ]\n"  // the last speed, reversed
                                     "Command M5 [ ]\n"
                                     "Command M7 [ ]\nCommand M8 [ ]\nCommand M9 [ ]\n"
                                     "Command G55 [ ]\nCommand G59 [ ]\n"
                                     "Command G41 [ D:1 ]\nCommand G42 [ ]\nCommand G40 [ ]\n"
                                     "Command G4 [ P:1.5 ]\n"
                                     "Command M0 [ ]\nCommand M1 [ ]\n"
                                     "Command G90 [ ]\nCommand G21 [ ]\nCommand G17 [ ]\n"
                                     "Command M30 [ ]\n");
    EXPECT_EQ(traceOf(imported.toolpath), "tool 3 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
                                          "spindle 2500.0000 cw\nspindle 2500.0000 ccw\nspindle 0.0000 ccw\n"
                                          "coolant mist\ncoolant flood\ncoolant off\n"
                                          "workoffset 2\nworkoffset 6\n"
                                          "comp left\ncomp right\ncomp off\n"
                                          "dwell 1.5000\n"
                                          "stop\nstop optional\n");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
    EXPECT_EQ(failure("Command M6 [ ]\n").message, "M6 needs T (a whole tool number >= 0)");
    EXPECT_EQ(failure("Command M3 [ ]\n").message, "M3 without S and no speed before it");
    EXPECT_EQ(failure("Command G4 [ ]\n").message, "G4 needs P (the dwell in seconds, >= 0)");
}

TEST(FreeCadDumpReader, ParametersWithoutBlanksInsideTheBrackets)
{
    // seed-004 Obr. 29 writes "Command G0 [X:-55 Y:-30]"; Python prints floats as 1e-05.
    EXPECT_EQ(trace("Command G0 [X:-55 Y:-30 Z:5]\nCommand G1[F:1 Z:1e-05]\n"),
              "rapid -55.0000 -30.0000 5.0000\nlinear z 0.0000 f 60.0000\n");
}

TEST(FreeCadDumpReader, CommentsAndSections)
{
    const ClImport imported = import("(Header remark)\n"
                                     "(Path: Profile)\n"
                                     "Command (Profile) [ ]\n"
                                     "Command (a (nested) remark) [ ]\n"
                                     "(Path: Second)\n"
                                     "Command G0 [ X:1 Y:2 Z:3 ]\n");
    EXPECT_EQ(traceOf(imported.toolpath), "comment \"Header remark\"\n"
                                          "section \"Profile\" - tool 0 cut 0.0000 plunge 0.0000\n"
                                          "comment \"a (nested) remark\"\n"
                                          "endsection\n"
                                          "section \"Second\" - tool 0 cut 0.0000 plunge 0.0000\n"
                                          "rapid 1.0000 2.0000 3.0000\n"
                                          "endsection\n");
    // "Command (Profile) [ ]" repeats the label of the section it opens: not a comment of its own.
    EXPECT_EQ(sources(imported.toolpath), "-1:1 0:2 0:4 0:5 1:5 1:6 1:6 ");
}

TEST(FreeCadDumpReader, UnknownCommandsAreWarnings)
{
    const ClImport imported = import(kAt + "Command G64 [ P:0.01 ]\nCommand M50 [ ]\nCommand [ ]\n"
                                           "Command T1 [ ]\nCommand G0 [ F:0 ]\n");
    EXPECT_EQ(traceOf(imported.toolpath), kAtTrace);
    EXPECT_EQ(warnings(imported), "t.dump:2:9: unknown command G64 ignored\n"
                                  "t.dump:3:9: unknown command M50 ignored\n"
                                  "t.dump:4:9: Command without a name ignored\n"
                                  "t.dump:5:9: unknown command T1 ignored\n"
                                  "t.dump:6:9: G0 without X, Y or Z ignored\n");
}

TEST(FreeCadDumpReader, IncrementalAndInchAreErrors)
{
    const base::Error g91 = failure(kAt + "Command G91 [ ]\n");
    EXPECT_EQ(g91.message, "incremental CL (G91) is not supported");
    EXPECT_EQ(g91.line, 2);
    EXPECT_EQ(g91.column, 9);
    EXPECT_EQ(failure("  Command G20 [ ]\n").column, 11);
}

// ---- Canned cycles ----------------------------------------------------------------------------

TEST(FreeCadDumpReader, CyclesOfEveryKind)
{
    const std::string start = "Command G0 [ X:0 Y:0 Z:25 ]\n";
    const std::string rapid = "rapid 0.0000 0.0000 25.0000\n";
    auto cycle = [&](const std::string& command) {
        return trace(start + "Command " + command + " [ F:2 P:0.5 Q:2.5 R:3 X:5 Y:5 Z:-10 ]\nCommand " + command +
                     " [ X:15 Y:5 ]\nCommand G80 [ ]\n");
    };
    const std::string holes = "  hole 5.0000 5.0000 3.0000\n  hole 15.0000 5.0000 3.0000\n";
    auto expected = [&](const std::string& kind, double peck, double dwell) {
        return rapid + "cycle " + kind + " clear 25.0000 retract 3.0000 top 3.0000 bottom -10.0000 peck " +
               (peck > 0 ? "2.5000" : "0.0000") + " dwell " + (dwell > 0 ? "0.5000" : "0.0000") +
               " f 120.0000 return clear holes 2\n" + holes;
    };
    EXPECT_EQ(cycle("G82"), expected("drillDwell", 0, 0.5));
    EXPECT_EQ(cycle("G83"), expected("peck", 2.5, 0));
    EXPECT_EQ(cycle("G73"), expected("chipBreak", 2.5, 0));
    EXPECT_EQ(cycle("G84"), expected("tap", 0, 0));
    EXPECT_EQ(cycle("G85"), expected("bore", 0, 0));
    const ClImport drill = import(start + "Command G81 [ F:2 R:3 X:5 Y:5 Z:-10 P:1 ]\nCommand G80 [ ]\n");
    EXPECT_EQ(traceOf(drill.toolpath), rapid +
                                           "cycle drill clear 25.0000 retract 3.0000 top 3.0000 bottom -10.0000 peck "
                                           "0.0000 dwell 0.0000 f 120.0000 return clear holes 1\n"
                                           "  hole 5.0000 5.0000 3.0000\n");
    EXPECT_EQ(warnings(drill), "t.dump:2:37: P ignored on G81\n");
}

TEST(FreeCadDumpReader, CycleRunsAndReturnPlanes)
{
    const ClImport imported = import("Command G0 [ X:0 Y:0 Z:25 ]\n"
                                     "Command G99 [ ]\n"
                                     "Command G81 [ F:2 R:3 X:5 Y:5 Z:-10 ]\n"
                                     "Command G81 [ F:2 R:3 X:10 Y:5 Z:-10 ]\n"
                                     "Command G81 [ F:2 R:3 X:15 Y:5 Z:-12 ]\n"  // deeper: a new run
                                     "Command G98 [ ]\n"
                                     "Command G81 [ F:2 R:3 X:20 Y:5 Z:-12 ]\n"  // G98: a new run
                                     "Command (between) [ ]\n"
                                     "Command G81 [ X:25 ]\n"
                                     "Command G80 [ ]\n");
    EXPECT_EQ(traceOf(imported.toolpath),
              "rapid 0.0000 0.0000 25.0000\n"
              "cycle drill clear 25.0000 retract 3.0000 top 3.0000 bottom -10.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return retract holes 2\n"
              "  hole 5.0000 5.0000 3.0000\n  hole 10.0000 5.0000 3.0000\n"
              "cycle drill clear 3.0000 retract 3.0000 top 3.0000 bottom -12.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return retract holes 1\n"
              "  hole 15.0000 5.0000 3.0000\n"
              "cycle drill clear 3.0000 retract 3.0000 top 3.0000 bottom -12.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 20.0000 5.0000 3.0000\n"
              "comment \"between\"\n"
              "cycle drill clear 3.0000 retract 3.0000 top 3.0000 bottom -12.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 25.0000 5.0000 3.0000\n");
    EXPECT_EQ(sources(imported.toolpath), "-1:1 -1:3 -1:5 -1:7 -1:8 -1:9 ");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
}

TEST(FreeCadDumpReader, CycleProblems)
{
    const std::string start = "Command G0 [ X:0 Y:0 Z:25 ]\n";
    const base::Error q = failure(start + "Command G83 [ F:2 R:3 X:5 Y:5 Z:-10 ]\n");
    EXPECT_EQ(q.message, "G83 needs Q (the peck depth)");
    EXPECT_EQ(q.line, 2);
    EXPECT_EQ(q.column, 9);
    EXPECT_EQ(failure(start + "Command G81 [ F:2 R:3 X:5 Y:5 ]\n").message, "G81 needs Z (the hole bottom)");
    EXPECT_EQ(failure(start + "Command G82 [ F:2 R:3 X:5 Y:5 Z:-1 ]\n").message, "G82 needs P (the dwell in seconds)");
    EXPECT_EQ(failure(start + "Command G73 [ F:2 Q:0 R:3 X:5 Y:5 Z:-1 ]\n").message, "G73: Q must be > 0");
    // G80 ends the modal Z and R.
    EXPECT_EQ(failure(start + "Command G81 [ F:2 R:3 X:5 Y:5 Z:-1 ]\nCommand G80 [ ]\nCommand G81 [ X:6 ]\n").message,
              "G81 needs Z (the hole bottom)");
    const ClImport noZ = import("Command G81 [ F:2 R:3 X:5 Y:5 Z:-1 ]\n");
    EXPECT_EQ(warnings(noZ), "t.dump:1:9: no Z before the cycle: its clearance plane is taken as the R plane\n"
                             "t.dump:1: canned cycle still active at the end of the dump (no G80)\n");
}

// ---- Malformed dumps --------------------------------------------------------------------------

TEST(FreeCadDumpReader, MalformedDumpsGiveLineAndColumn)
{
    struct Case {
        std::string text;
        std::string message;
        int line, column;
    };
    const std::vector<Case> cases = {
        {"Command G1 [ F:1 X:1\n", "'[' without ']'", 1, 12},
        {"Command G0 [ X:1 ]\nCommand G1 [ F:1 X:1\n(Path: B)\n", "'[' without ']'", 2, 12},
        {"Command G0 [ X10 ]\n", "malformed parameter 'X10' (expected a letter, ':' and a number)", 1, 14},
        {"Command G0 [ X:1.2.3 ]\n", "malformed number '1.2.3'", 1, 16},
        {"Command G0 [ X:1 X:2 ]\n", "parameter X given twice", 1, 18},
        {"Command G0 [ XY:1 ]\n", "malformed parameter 'XY:1' (expected a letter, ':' and a number)", 1, 14},
        {"Command G0 X:1\n", "expected '[' after the command name", 1, 12},
        {"Command G0 [ X:1 ] extra\n", "unexpected text after ']'", 1, 20},
        {"G0 X1 Y2\n", "expected a 'Command' or a '(' line", 1, 1},
        {"(Path: unterminated\nCommand G0 [ X:1 ]\n", "'(' without ')'", 1, 1},
        {"Command (comment [ ]\n", "'(' without ')'", 1, 9},
    };
    for (const Case& c : cases) {
        const base::Error error = failure(c.text);
        EXPECT_EQ(error.message, c.message) << c.text;
        EXPECT_EQ(error.file, "t.dump") << c.text;
        EXPECT_EQ(error.line, c.line) << c.text;
        EXPECT_EQ(error.column, c.column) << c.text;
    }
}

TEST(FreeCadDumpReader, AFileIsReadInChunksAsTheTextIs)
{
    // More than two 1 MiB chunks, with wrapped commands and notes and CRLF lines, so that some of
    // them fall on a chunk boundary.
    std::string dump = "(Path: Long)\r\n" + kAt;
    for (int i = 0; dump.size() < 2500000; ++i) {
        const std::string x = std::to_string(i % 97), y = std::to_string(i % 89);
        if (i % 50 == 0)
            dump += "(a remark that wraps\n  onto the next line)\n";
        if (i % 7 == 0)
            dump += "Command G1 [ F:5 X:" + x + "\n   Y:" + y + "\r\n Z:-1 ]\n";
        else
            dump += "Command G1 [ X:" + x + " Y:" + y + " ]\r\n";
        if (i % 1000 == 0)
            dump += "Command G64 [ P:0.01 ]\n";  // a warning, repeated: one message listing lines
    }
    const std::string trace = test::sameFromFileAndText(ClFormat::FreeCadDump, dump);
    EXPECT_GT(std::count(trace.begin(), trace.end(), '\n'), 50000);
}
