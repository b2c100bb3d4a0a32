// APT CL source import of motion: GOTO and its relatives, NX CIRCLE + GOTO (both directions,
// helices), CATIA INDIRV + TLON,GOFWD circles, and canned cycles of every kind.
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

}  // namespace

// ---- Motion -----------------------------------------------------------------------------------

TEST(AptMotion, RapidAppliesToTheNextMotionOnly)
{
    EXPECT_EQ(traceFini("FEDRAT/500\nRAPID\nGOTO/0,0,50\nGOTO/0,0,5\nRAPID\nGOTO/10,0,5\nGOTO/10,10,5\n"),
              "rapid 0.0000 0.0000 50.0000\nlinear 0.0000 0.0000 5.0000 f 500.0000\n"
              "rapid 10.0000 0.0000 5.0000\nlinear 10.0000 10.0000 5.0000 f 500.0000\n");
}

TEST(AptMotion, ToolAxisMoves)
{
    // Six values with an axis other than +Z: a five-axis move; the axis stays for three-value
    // GOTOs until a GOTO (or TLAXIS) brings it back to +Z.
    EXPECT_EQ(traceFini("FEDRAT/800\n"
                        "GOTO/0,0,10,0,0,1\n"
                        "GOTO/5,0,10,0,0.6,0.8\n"
                        "RAPID\n"
                        "GOTO/5,0,20\n"
                        "GOTO/6,0,20,0,0,2\n"
                        "TLAXIS/1,0,0\n"
                        "GOTO/7,0,20\n"),
              "linear 0.0000 0.0000 10.0000 f 800.0000\n"
              "move5 5.0000 0.0000 10.0000 axis 0.000000000 0.600000000 0.800000000 f 800.0000\n"
              "move5 5.0000 0.0000 20.0000 axis 0.000000000 0.600000000 0.800000000 f 0.0000\n"
              "linear 6.0000 0.0000 20.0000 f 800.0000\n"
              "move5 7.0000 0.0000 20.0000 axis 1.000000000 0.000000000 0.000000000 f 800.0000\n");
    EXPECT_EQ(failure("GOTO/1,2,3,0,0,0\n").column, 12);
    EXPECT_EQ(failure("TLAXIS/0,0\n").message, "TLAXIS expects i,j,k");
}

TEST(AptMotion, FromSetsThePositionWithoutARecord)
{
    // FROM declares where the tool is: the arc starts there; GOHOME goes back to it at rapid.
    EXPECT_EQ(traceFini("FROM/10,0,0\nFEDRAT/100\nCIRCLE/0,0,0,0,0,1,10\nGOTO/0,10,0\nGOHOME\n"),
              "arc ccw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n"
              "rapid 10.0000 0.0000 0.0000\n");
    EXPECT_EQ(failure("GOHOME\n").message, "GOHOME without a FROM point to go back to");
    EXPECT_EQ(failure("FROM/1,2\n").message, "FROM needs 3 values (x,y,z) or 6 (x,y,z,i,j,k), found 2");
}

TEST(AptMotion, RelativeMoves)
{
    EXPECT_EQ(traceFini("FEDRAT/100\nGOTO/1,1,1\nGODLTA/1,2,3\nGODLTA/-5\nGODLTA/0,0,1,0,1,0\n"),
              "linear 1.0000 1.0000 1.0000 f 100.0000\nlinear 2.0000 3.0000 4.0000 f 100.0000\n"
              "linear 2.0000 3.0000 -1.0000 f 100.0000\nmove5 2.0000 3.0000 0.0000 axis 0.000000000 1.000000000 "
              "0.000000000 f "
              "100.0000\n");
    EXPECT_EQ(failure("GODLTA/1,2,3\n").message, "GODLTA needs a known position (a GOTO or FROM before it)");
}

TEST(AptMotion, FeedMoveBeforeAnyFeedIsWarnedOnce)
{
    const ClImport imported = import("GOTO/1,0,0\nGOTO/2,0,0\nFINI\n");
    EXPECT_EQ(traceOf(imported.toolpath),
              "linear 1.0000 0.0000 0.0000 f 0.0000\nlinear 2.0000 0.0000 0.0000 f 0.0000\n");
    EXPECT_EQ(warnings(imported), "t.apt:1:1: feed motion before any FEDRAT: its feed is 0\n");
}

TEST(AptMotion, PointLinesInACycleAreHoles)
{
    EXPECT_EQ(traceFini("RAPID\nGOTO/0,0,30\nCYCLE/DRILL,DEPTH,5,MMPM,90,CLEAR,2\nGOTO/10,0,0\n20,0,0\n30,0,0\n"
                        "CYCLE/OFF\n"),
              "rapid 0.0000 0.0000 30.0000\n"
              "cycle drill clear 30.0000 retract 2.0000 top 0.0000 bottom -5.0000 peck 0.0000 dwell 0.0000 f "
              "90.0000 return retract holes 3\n"
              "  hole 10.0000 0.0000 0.0000\n  hole 20.0000 0.0000 0.0000\n  hole 30.0000 0.0000 0.0000\n");
}

TEST(AptMotion, PointLinesContinueTheGoto)
{
    EXPECT_EQ(traceFini("RAPID\nGOTO/0,0,10\n5,0,10\n5,5,10\nFEDRAT/100\nGOTO/5,5,0\n5,6,0,0,0,1\n"),
              "rapid 0.0000 0.0000 10.0000\nrapid 5.0000 0.0000 10.0000\nrapid 5.0000 5.0000 10.0000\n"
              "linear 5.0000 5.0000 0.0000 f 100.0000\nlinear 5.0000 6.0000 0.0000 f 100.0000\n");
    EXPECT_EQ(failure("FEDRAT/1\n1,2,3\n").message, "a line of values without a GOTO before it");
    const base::Error count = failure("GOTO/0,0,0\n1,2\n");
    EXPECT_EQ(count.line, 2);
    EXPECT_EQ(count.column, 1);
}

// ---- NX CIRCLE --------------------------------------------------------------------------------

TEST(AptMotion, NxCircleBothDirectionsAndHelix)
{
    const std::string start = "FEDRAT/MMPM,600\nGOTO/10,0,0\n";
    EXPECT_EQ(traceFini(start + "CIRCLE/0,0,0,0,0,1,10,0.06,0.5,10,0\nGOTO/0,10,0\n"),
              "linear 10.0000 0.0000 0.0000 f 600.0000\n"
              "arc ccw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 600.0000\n");
    EXPECT_EQ(traceFini(start + "CIRCLE/0,0,0,0,0,-1,10,0.06,0.5,10,0\nGOTO/0,10,0\n"),
              "linear 10.0000 0.0000 0.0000 f 600.0000\n"
              "arc cw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 600.0000\n");
    // An arc in the ZX plane, seen from -Y.
    EXPECT_EQ(traceFini(start + "CIRCLE/0,0,0,0,-1,0,10\nGOTO/0,0,10\n"),
              "linear 10.0000 0.0000 0.0000 f 600.0000\n"
              "arc cw 0.0000 0.0000 10.0000 c 0.0000 0.0000 0.0000 n 0.0000 1.0000 0.0000 turns 0 f 600.0000\n");
    // Helix: the GOTO leaves the plane; three laps in all.
    EXPECT_EQ(traceFini(start + "CIRCLE/0,0,-6,0,0,1,10,0.06,0.5,10,0,TIMES,3\nGOTO/10,0,-6\n"),
              "linear 10.0000 0.0000 0.0000 f 600.0000\n"
              "arc ccw 10.0000 0.0000 -6.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 2 f 600.0000\n");
    // A tilted plane keeps its normal.
    const ClImport tilted = import(start + "CIRCLE/0,0,0,0,0.6,0.8,10\nGOTO/-10,0,0\nFINI\n");
    const Arc& arc = std::get<Arc>(tilted.toolpath.record(1));
    EXPECT_NEAR(arc.normal.y, 0.6, 1e-12);
    EXPECT_NEAR(arc.normal.z, 0.8, 1e-12);
    EXPECT_FALSE(arc.clockwise);
}

TEST(AptMotion, NxCircleChecks)
{
    const ClImport off = import("FEDRAT/100\nGOTO/10.5,0,0\nCIRCLE/0,0,0,0,0,1,10\nGOTO/0,10,0\nFINI\n");
    EXPECT_EQ(warnings(off), "t.apt:3: the arc starts 0.5 mm off its circle (radius 10)\n");
    EXPECT_EQ(std::get<Arc>(off.toolpath.record(1)).to, (Vec3{0, 10, 0}));

    const base::Error open = failure("GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nLOADTL/2\n");
    EXPECT_EQ(open.message, "CIRCLE at line 2 is not followed by the GOTO that ends it");
    EXPECT_EQ(open.line, 3);
    EXPECT_EQ(open.column, 1);
    const base::Error fini = failure("GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nFINI\n");
    EXPECT_EQ(fini.message, "CIRCLE at line 2 is not followed by the GOTO that ends it");
    EXPECT_EQ(fini.line, 3);
    const base::Error atEnd = failure("GOTO/10,0,0\n   CIRCLE/0,0,0,0,0,1,10\n");
    EXPECT_EQ(atEnd.message, "CIRCLE is not followed by the GOTO that ends it");
    EXPECT_EQ(atEnd.line, 2);
    EXPECT_EQ(atEnd.column, 4);
    const base::Error insert = failure("GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\n  INSERT/M8\n");
    EXPECT_EQ(insert.message, "INSERT between CIRCLE and the GOTO that ends it");
    EXPECT_EQ(insert.column, 3);
    EXPECT_EQ(failure("GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nRAPID\nGOTO/0,10,0\n").line, 3);
    EXPECT_EQ(failure("CIRCLE/0,0,0,0,0,1,10\n").message,
              "CIRCLE needs a known start position (a GOTO or FROM before it)");
    EXPECT_EQ(failure("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,1\n").message, "CIRCLE needs cx,cy,cz,i,j,k,r");
    EXPECT_EQ(failure("GOTO/1,0,0\nCIRCLE/0,0,0,0,0,0,1\n").column, 14);
    // FEDRAT and PAINT may stand between the CIRCLE and its GOTO.
    const ClImport between =
        import("GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nFEDRAT/50\nPAINT/COLOR,3\nGOTO/-10,0,0\nFINI\n");
    EXPECT_EQ(std::get<Arc>(between.toolpath.record(1)).feedMmPerMin, 50);
}

// ---- CATIA TLON,GOFWD circles -----------------------------------------------------------------

TEST(AptMotion, CatiaCircleDirectionComesFromIndirv)
{
    const std::string start = "FEDRAT/100\nGOTO/10,0,0\n";
    const std::string circle = "TLON,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,10,0)\n";
    EXPECT_EQ(traceFini(start + "INDIRV/0,1,0\n" + circle),
              "linear 10.0000 0.0000 0.0000 f 100.0000\n"
              "arc ccw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n");
    // Going -Y at (10,0): clockwise, and the first crossing of the line x = 0 is (0,-10).
    EXPECT_EQ(traceFini(start + "INDIRV/0,-1,0\n" + circle),
              "linear 10.0000 0.0000 0.0000 f 100.0000\n"
              "arc cw 0.0000 -10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n");
    // ON,2,INTOF: the second crossing, (0,10) after three quarters.
    EXPECT_EQ(traceFini(start + "INDIRV/0,-1,0\nTLON,GOFWD/(CIRCLE/0,0,0,10),ON,2,INTOF,(LINE/0,0,0,0,10,0)\n"),
              "linear 10.0000 0.0000 0.0000 f 100.0000\n"
              "arc cw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n");
    // ON,4,INTOF on a line through the start: two whole laps.
    EXPECT_EQ(traceFini(start + "INDIRV/0,1,0\nTLON,GOFWD/(CIRCLE/0,0,0,10),ON,4,INTOF,(LINE/0,0,0,10,0,0)\n"),
              "linear 10.0000 0.0000 0.0000 f 100.0000\n"
              "arc ccw 10.0000 0.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 1 f 100.0000\n");
    // Without INDIRV the previous move's direction decides: arriving along +Y, counter-clockwise.
    EXPECT_EQ(traceFini("FEDRAT/100\nGOTO/10,-5,0\nGOTO/10,0,0\n" + circle),
              "linear 10.0000 -5.0000 0.0000 f 100.0000\nlinear 10.0000 0.0000 0.0000 f 100.0000\n"
              "arc ccw 0.0000 10.0000 0.0000 c 0.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n");
    // INDIRP points at a point; CIRCLE/CANON with an axis (the YZ plane here).
    EXPECT_EQ(
        traceFini(
            "FEDRAT/100\nGOTO/0,10,0\nINDIRP/0,10,5\nGOFWD/(CIRCLE/CANON,0,0,0,1,0,0,10),ON,(LINE/0,0,0,0,0,10)\n"),
        "linear 0.0000 10.0000 0.0000 f 100.0000\n"
        "arc ccw 0.0000 0.0000 10.0000 c 0.0000 0.0000 0.0000 n 1.0000 0.0000 0.0000 turns 0 f 100.0000\n");
}

TEST(AptMotion, CatiaCircleEndIsExactlyTheFilePoint)
{
    const ClImport imported =
        import("FEDRAT/100\nGOTO/13.3,7.7,0\nINDIRV/-0.5,0.8,0\n"
               "TLON,GOFWD/(CIRCLE/3.3,7.7,0,10),ON,(LINE/3.3,7.7,0,-3.77106781,14.77106781,0)\nFINI\n");
    const Arc& arc = std::get<Arc>(imported.toolpath.record(1));
    EXPECT_EQ(arc.to, (Vec3{-3.77106781, 14.77106781, 0}));
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
}

TEST(AptMotion, CatiaCircleErrors)
{
    const std::string start = "FEDRAT/100\nGOTO/10,0,0\nINDIRV/0,1,0\n";
    const base::Error miss = failure(start + "TLON,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/20,0,0,20,5,0)\n");
    EXPECT_EQ(miss.message, "the LINE does not meet the CIRCLE");
    EXPECT_EQ(miss.line, 4);
    EXPECT_EQ(miss.column, 34);
    EXPECT_EQ(failure(start + "TLON,GOFWD/(CIRCLE/0,0,0,10),TO,(LINE/0,0,0,0,10,0)\n").message,
              "expected ON after the CIRCLE (TO, PAST and TANTO are not supported)");
    EXPECT_EQ(failure(start + "TLLFT,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,10,0)\n").message,
              "TLLFT (tool offset from the drive circle) is not supported; only TLON");
    EXPECT_EQ(failure(start + "TLON,GOFWD/(CIRCLE/0,0,0),ON,(LINE/0,0,0,0,10,0)\n").message,
              "CIRCLE needs cx,cy,cz,r or cx,cy,cz,i,j,k,r");
    EXPECT_EQ(
        failure("FEDRAT/1\nGOTO/10,0,0\nINDIRV/1,0,0\nTLON,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,1,0)\n").message,
        "the start direction (INDIRV) does not say which way round the circle to go");
    EXPECT_EQ(failure("FEDRAT/1\nGOTO/10,0,0\nTLON,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,1,0)\n").message,
              "circular move without a start direction (INDIRV) or a previous move");
    EXPECT_EQ(failure(start + "RAPID\nTLON,GOFWD/(CIRCLE/0,0,0,10),ON,(LINE/0,0,0,0,1,0)\n").message,
              "RAPID before a circular move: an arc cannot be a rapid");
    EXPECT_EQ(failure("GOLFT/L1,PAST,L2\n").message, "GOLFT needs an APT geometry processor and is not supported");
}

// ---- Canned cycles ----------------------------------------------------------------------------

TEST(AptMotion, CyclesOfEveryKind)
{
    const std::string start = "FEDRAT/200\nRAPID\nGOTO/0,0,50\n";
    auto cycle = [&](const std::string& statement) {
        return traceFini(start + statement + "\nGOTO/10,0,0\nGOTO/20,0,0\nCYCLE/OFF\n");
    };
    const std::string rapid = "rapid 0.0000 0.0000 50.0000\n";
    const std::string holes = "  hole 10.0000 0.0000 0.0000\n  hole 20.0000 0.0000 0.0000\n";
    EXPECT_EQ(cycle("CYCLE/DRILL,DEPTH,12,MMPM,150,CLEAR,2"),
              rapid +
                  "cycle drill clear 50.0000 retract 2.0000 top 0.0000 bottom -12.0000 peck 0.0000 dwell 0.0000 "
                  "f 150.0000 return retract holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/DRILL,DEPTH,12,MMPM,150,CLEAR,2,DWELL,1.5"),
              rapid +
                  "cycle drillDwell clear 50.0000 retract 2.0000 top 0.0000 bottom -12.0000 peck 0.0000 dwell "
                  "1.5000 f 150.0000 return retract holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/DEEP,DEPTH,30,STEP,5,MMPM,100,CLEAR,3,RAPTO,1"),
              rapid +
                  "cycle peck clear 50.0000 retract 1.0000 top 0.0000 bottom -30.0000 peck 5.0000 dwell 0.0000 "
                  "f 100.0000 return retract holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/BRKCHP,DEPTH,30,STEP,4,MMPM,100,CLEAR,3"),
              rapid +
                  "cycle chipBreak clear 50.0000 retract 3.0000 top 0.0000 bottom -30.0000 peck 4.0000 dwell "
                  "0.0000 f 100.0000 return retract holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/DRILL,BRKCHP,FEDTO,-30,INCR,4,CLEAR,3"),
              rapid +
                  "cycle chipBreak clear 50.0000 retract 3.0000 top 0.0000 bottom -30.0000 peck 4.0000 dwell "
                  "0.0000 f 200.0000 return retract holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/TAP,DEPTH,15,MMPR,1.25,CLEAR,5"),
              rapid +
                  "feedmode perRevolution\ncycle tap clear 50.0000 retract 5.0000 top 0.0000 bottom -15.0000 peck "
                  "0.0000 dwell 0.0000 f 1.2500 return retract holes 2\n" +
                  holes + "feedmode perMinute\n");
    EXPECT_EQ(cycle("CYCLE/BORE,DEPTH,20,MMPM,80,CLEAR,2,DWELL,0.5,RTRCTO,AUTO"),
              rapid +
                  "cycle bore clear 50.0000 retract 2.0000 top 0.0000 bottom -20.0000 peck 0.0000 dwell 0.5000 "
                  "f 80.0000 return clear holes 2\n" +
                  holes);
    EXPECT_EQ(cycle("CYCLE/REAM,DEPTH,20,MMPM,80,CLEAR,2,RETURN,0"),
              rapid +
                  "cycle bore clear 50.0000 retract 2.0000 top 0.0000 bottom -20.0000 peck 0.0000 dwell 0.0000 "
                  "f 80.0000 return clear holes 2\n" +
                  holes);
}

TEST(AptMotion, CycleRunsSplitOnParameterChanges)
{
    const ClImport imported = import("FEDRAT/200\n"
                                     "RAPID\n"
                                     "GOTO/0,0,40\n"
                                     "CYCLE/DRILL,FEDTO,-10,CLEAR,2,RTRCTO,AUTO,MMPM,120\n"
                                     "GOTO/0,0,0\n"
                                     "GOTO/10,0,0\n"
                                     "GOTO/20,0,-4\n"  // another top
                                     "GOTO/30,0,-4\n"
                                     "CYCLE/ON,FEDTO,-14\n"  // another depth
                                     "GOTO/40,0,0\n"
                                     "PPRINT CHECK CHIPS\n"  // a record between holes ends the run
                                     "GOTO/50,0,0\n"
                                     "CYCLE/OFF\n"
                                     "FINI\n");
    EXPECT_EQ(traceOf(imported.toolpath),
              "rapid 0.0000 0.0000 40.0000\n"
              "cycle drill clear 40.0000 retract 2.0000 top 0.0000 bottom -10.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 2\n"
              "  hole 0.0000 0.0000 0.0000\n  hole 10.0000 0.0000 0.0000\n"
              "cycle drill clear 40.0000 retract -2.0000 top -4.0000 bottom -14.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 2\n"
              "  hole 20.0000 0.0000 -4.0000\n  hole 30.0000 0.0000 -4.0000\n"
              "cycle drill clear 40.0000 retract 2.0000 top 0.0000 bottom -14.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 40.0000 0.0000 0.0000\n"
              "comment \"CHECK CHIPS\"\n"
              "cycle drill clear 40.0000 retract 2.0000 top 0.0000 bottom -14.0000 peck 0.0000 dwell 0.0000 f "
              "120.0000 return clear holes 1\n"
              "  hole 50.0000 0.0000 0.0000\n");
    // A Cycle carries the line of its first hole.
    EXPECT_EQ(sources(imported.toolpath), "-1:3 -1:5 -1:7 -1:10 -1:11 -1:12 ");
    EXPECT_TRUE(imported.warnings.empty()) << warnings(imported);
}

TEST(AptMotion, CycleReturnPlanes)
{
    const std::string start = "FEDRAT/200\nRAPID\nGOTO/0,0,50\n";
    auto firstCycle = [&](const std::string& statement) {
        const ClImport imported = import(start + statement + "\nGOTO/10,0,5\nCYCLE/OFF\nFINI\n");
        return std::get<Cycle>(imported.toolpath.record(1));
    };
    Cycle c = firstCycle("CYCLE/DRILL,FEDTO,-10,CLEAR,2,RTRCTO,12");
    EXPECT_TRUE(c.returnToClearance);  // 12 above the top: a plane of its own
    EXPECT_EQ(c.clearanceZ, 17);
    EXPECT_EQ(c.retractZ, 7);
    c = firstCycle("CYCLE/DRILL,FEDTO,-10,CLEAR,2,RTRCTO,2");
    EXPECT_FALSE(c.returnToClearance);  // the R plane itself
    EXPECT_EQ(c.clearanceZ, 50);
    c = firstCycle("CYCLE/DRILL,FEDTO,-10,CLEAR,2,RTRCTO,0");
    EXPECT_TRUE(c.returnToClearance);
    EXPECT_EQ(c.clearanceZ, 50);
    c = firstCycle("CYCLE/DRILL,FEDTO,-10,RAPTO,1,CLEAR,4");
    EXPECT_EQ(c.retractZ, 6);  // RAPTO wins over CLEAR
    c = firstCycle("CYCLE/DRILL,FEDTO,-10");
    EXPECT_EQ(c.retractZ, 5);  // neither: feeding starts at the top
    EXPECT_EQ(c.feedMmPerMin, 200);
}

TEST(AptMotion, CyclePositionalForms)
{
    const std::string start = "FEDRAT/200\nRAPID\nGOTO/0,0,50\n";
    auto firstCycle = [&](const std::string& statement) {
        const ClImport imported = import(start + statement + "\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n");
        return std::get<Cycle>(imported.toolpath.record(1));
    };
    Cycle c = firstCycle("CYCLE/DRILL,12,MMPM,150,3");  // depth, unit, feed, clearance
    EXPECT_EQ(c.bottomZ, -12);
    EXPECT_EQ(c.feedMmPerMin, 150);
    EXPECT_EQ(c.retractZ, 3);
    c = firstCycle("CYCLE/DRILL,12,150,MMPM");  // depth, feed, unit
    EXPECT_EQ(c.bottomZ, -12);
    EXPECT_EQ(c.feedMmPerMin, 150);
    const base::Error ambiguous = failure(start + "CYCLE/DRILL,12,3,MMPM,150\n");
    EXPECT_EQ(ambiguous.message, "CYCLE: ambiguous values around MMPM: write the depth and distances as couplets "
                                 "(DEPTH, CLEAR, RAPTO)");
    EXPECT_EQ(ambiguous.line, 4);
    EXPECT_EQ(ambiguous.column, 18);
}

TEST(AptMotion, CycleProblems)
{
    const std::string start = "FEDRAT/200\nRAPID\nGOTO/0,0,50\n";
    EXPECT_EQ(failure(start + "CYCLE/DRILL,MMPM,100\n").message, "CYCLE needs a depth (DEPTH or FEDTO)");
    EXPECT_EQ(failure(start + "CYCLE/DEEP,DEPTH,10\n").message, "CYCLE/DEEP needs a peck depth (STEP or INCR)");
    EXPECT_EQ(failure(start + "CYCLE/THRU,DEPTH,10\n").message, "CYCLE/THRU is not supported");
    EXPECT_EQ(failure(start + "CYCLE/DRILL,DEPTH,10,RTRCTO,MANUAL\n").message,
              "CYCLE: RTRCTO expects a distance or AUTO");
    const base::Error tilted = failure(start + "CYCLE/DRILL,DEPTH,10\nGOTO/1,0,0,0,1,0\n");
    EXPECT_EQ(tilted.message, "CYCLE holes along a tool axis other than +Z are not supported");
    EXPECT_EQ(tilted.line, 5);
    EXPECT_EQ(failure(start + "CYCLE/ON\n").message, "CYCLE/ON without an earlier cycle to resume");

    const ClImport warned = import(start + "CYCLE/OFF\nCYCLE/BRKCHP,DEPTH,10,STEP,2,BACK,0.5\nGOTO/5,5,0\nFINI\n");
    EXPECT_EQ(warnings(warned), "t.apt:4:1: CYCLE/OFF without an active cycle\n"
                                "t.apt:5:30: CYCLE: BACK ignored\n"
                                "t.apt:7: CYCLE is still on (no CYCLE/OFF): it ends here\n");
    EXPECT_EQ(std::get<Cycle>(warned.toolpath.record(1)).holes.size(), 1u);

    const ClImport unplaced = import("CYCLE/DRILL,DEPTH,10,MMPM,100\nGOTO/5,5,0\nCYCLE/OFF\nFINI\n");
    EXPECT_EQ(warnings(unplaced),
              "t.apt:1: no tool position before the CYCLE: its clearance plane is taken as the R plane\n");
}
