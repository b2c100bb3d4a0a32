// The trace reader reads back exactly what the trace writer writes, for every CL record type, and
// says where a hand-written trace is wrong.
#include "toolpath/TraceReader.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

using namespace camwb;
using namespace camwb::toolpath;

namespace {

Toolpath everyRecord()
{
    Toolpath t;
    Cycle cycle{CycleKind::ChipBreak, 25, 2, 0, -12.5, 3, 0.25, 120, {{10, 10, 0}, {20, -5.5, 0}}};
    cycle.returnToClearance = false;
    const Record records[] = {
        WorkOffset{2},
        SectionBegin{"Contour \"A\" 1", "profile", 3, {600, 150, 0, 0, 0}},
        ToolChange{Tool{3, "Flat D6, 3 flutes", "flat", 6, 0.5, 20, 45, 3, true, 0, "SK40 \"ER32\""}},
        Spindle{4000, true},
        Spindle{0, false},
        Coolant{CoolantMode::Mist},
        FeedModeChange{FeedMode::PerRevolution},
        CutterComp{CutterCompSide::Right},
        Rapid{{1, 2, 3}},
        Linear{{-1.25, 0, 3}, 0.15},
        Arc{{5, 5, -1}, {0, 5, 0}, {0, 0, -1}, true, 2, 300},
        Linear{{0, 0, -2}, 80, {}, FeedKind::Plunge},  // moves that say which feed they use
        Arc{{2, 0, -2}, {1, 0, -2}, {0, 0, 1}, false, 0, 90, FeedKind::Entry},
        Linear{{9, 0, -2}, 600, {}, FeedKind::Cutting},
        Arc{{9, 2, -2}, {9, 1, -2}, {0, 0, 1}, false, 0, 600, FeedKind::Finishing},
        Linear{{9, 5, -2}, 600, {}, FeedKind::Exit},
        ToolChange{Tool{4}},
        Dwell{1.5},
        cycle,
        ToolAxisMove{{1, 2, 3}, {0, 0.6, 0.8}, 250},
        Comment{"a comment with \"quotes\" and ; semicolons"},
        ProgramStop{},
        ProgramStop{true},
        PassThrough{"G64 P0.01"},
        SectionEnd{},
        Rapid{{0, 0, 50}},
        Rapid{{0, 0, 20}, AxisMask{AxisMask::kZ}},  // moves that give only some axes
        Linear{{4, -2, 0}, 300, AxisMask{AxisMask::kX | AxisMask::kY}},
        WorkingPlane{{10, 0, 5}, {0.8, 0, -0.6}, {0.6, 0, 0.8}},  // 3+2, then back
        Linear{{1, 1, 0}, 200},
        WorkingPlane{},
        UnknownAxes{AxisMask{AxisMask::kZ}},  // an untraced retract, a move in machine coordinates
        UnknownAxes{},
    };
    for (const Record& record : records)
        t.add(record);
    return t;
}

base::Error failure(const std::string& text)
{
    auto read = readTrace(text, "in.trace");
    EXPECT_FALSE(read.ok()) << text;
    return read.ok() ? base::Error{} : read.error();
}

}  // namespace

TEST(TraceReader, ReadsBackEveryRecordTheWriterWrites)
{
    const std::string trace = traceOf(everyRecord());
    auto read = readTrace(trace, "in.trace");
    ASSERT_TRUE(read.ok()) << read.error().toString() << "\n" << trace;
    EXPECT_EQ(traceOf(read->toolpath), trace);
    EXPECT_TRUE(read->warnings.empty());
    ASSERT_EQ(read->toolpath.size(), everyRecord().size());
    // Sections and lines as the CL importers number them.
    EXPECT_EQ(read->toolpath.source(0).operationIndex, -1);
    EXPECT_EQ(read->toolpath.source(1).operationIndex, 0);
    EXPECT_EQ(read->toolpath.source(1).recordIndex, 2);
    EXPECT_EQ(read->toolpath.source(24).operationIndex, 0);  // the SectionEnd closes section 0
    EXPECT_EQ(read->toolpath.source(25).operationIndex, -1);
    EXPECT_EQ(read->toolpath.source(25).recordIndex, 28);  // after the cycle's two hole lines
}

TEST(TraceReader, FeedKindsAndHoldersReadBackIntoTheRecords)
{
    auto read = readTrace("tool 2 flat d 6 r 0 flute 20 len 45 \"D6\" holder \"SK40 ER32\"\n"
                          "tool 3 drill d 5 r 0 flute 30 len 45 \"D5\"\n"
                          "linear 1 2 3 f 500 plunge\n"
                          "linear 1 2 3 f 500\n"
                          "arc cw 2 0 0 c 1 0 0 n 0 0 1 turns 0 f 100 exit\n"
                          "linear x 4 f 500 finishing\n",
                          "t");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    const Toolpath& t = read->toolpath;
    EXPECT_EQ(std::get<ToolChange>(t.record(0)).tool.holder, "SK40 ER32");
    EXPECT_EQ(std::get<ToolChange>(t.record(1)).tool.holder, "");
    EXPECT_EQ(std::get<Linear>(t.record(2)).feedKind, FeedKind::Plunge);
    EXPECT_EQ(std::get<Linear>(t.record(3)).feedKind, FeedKind::Unspecified);
    EXPECT_EQ(std::get<Arc>(t.record(4)).feedKind, FeedKind::Exit);
    EXPECT_EQ(std::get<Linear>(t.record(5)).feedKind, FeedKind::Finishing);
    EXPECT_EQ(std::get<Linear>(t.record(5)).axes, AxisMask{AxisMask::kX});
    EXPECT_EQ(traceOf(t), "tool 2 flat d 6.0000 r 0.0000 flute 20.0000 len 45.0000 \"D6\" holder \"SK40 ER32\"\n"
                          "tool 3 drill d 5.0000 r 0.0000 flute 30.0000 len 45.0000 \"D5\"\n"
                          "linear 1.0000 2.0000 3.0000 f 500.0000 plunge\n"
                          "linear 1.0000 2.0000 3.0000 f 500.0000\n"
                          "arc cw 2.0000 0.0000 0.0000 c 1.0000 0.0000 0.0000 n 0.0000 0.0000 1.0000 turns 0 f "
                          "100.0000 exit\n"
                          "linear x 4.0000 f 500.0000 finishing\n");

    EXPECT_EQ(failure("linear 1 2 3 f 500 rapid\n").toString(),
              "in.trace:1:20: unknown feed kind 'rapid' (cutting, plunge, entry, exit or finishing)");
    EXPECT_EQ(failure("rapid 0 0 0\narc cw 2 0 0 c 1 0 0 n 0 0 1 turns 0 f 100 \"entry\"\n").toString(),
              "in.trace:2:44: unknown feed kind 'entry' (cutting, plunge, entry, exit or finishing)");
    EXPECT_EQ(failure("linear 1 2 3 f 500 plunge plunge\n").toString(),
              "in.trace:1:27: unexpected 'plunge' at the end of the line");
    EXPECT_EQ(failure("tool 1 flat d 6 r 0 flute 20 len 45 \"D6\" holds \"x\"\n").toString(),
              "in.trace:1:42: unexpected 'holds' (after a tool's name: flutes N, angle A, holder \"...\")");
    EXPECT_EQ(failure("tool 1 flat d 6 r 0 flute 20 len 45 \"D6\" holder\n").toString(),
              "in.trace:1:48: expected a quoted text at the end of the line");
}

TEST(TraceReader, NotesAndBlankLinesAreSkipped)
{
    auto read = readTrace("# a hand-written input\n\nrapid 1 2 3\n   # indented note\nlinear 1 2 0 f 100\n", "t");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(traceOf(read->toolpath), "rapid 1.0000 2.0000 3.0000\nlinear 1.0000 2.0000 0.0000 f 100.0000\n");
    EXPECT_EQ(read->toolpath.source(1).recordIndex, 5);
}

TEST(TraceReader, ErrorsNameLineAndColumn)
{
    EXPECT_EQ(failure("rapid 1 2 3\nteleport 1 2 3\n").toString(), "in.trace:2:1: unknown trace record 'teleport'");
    EXPECT_EQ(failure("rapid 1 2\n").toString(), "in.trace:1:10: expected a number at the end of the line");
    EXPECT_EQ(failure("linear 1 2 x f 100\n").toString(), "in.trace:1:12: expected a number, found 'x'");
    EXPECT_EQ(failure("linear 1 2 3 g 100\n").toString(), "in.trace:1:14: expected 'f', found 'g'");
    EXPECT_EQ(failure("rapid 1 2 3 4\n").toString(), "in.trace:1:13: unexpected '4' at the end of the line");
    EXPECT_EQ(failure("coolant lots\n").toString(), "in.trace:1:9: unknown name 'lots'");
    EXPECT_EQ(failure("comment \"open\n").toString(), "in.trace:1:9: unterminated quoted text");
    EXPECT_EQ(failure("workoffset 1.5\n").toString(), "in.trace:1:12: expected an integer, found '1.5'");
    // Beyond int: an error, not an undefined conversion (found by fuzz.trace).
    EXPECT_EQ(failure("workoffset 88888888888888888882\n").toString(),
              "in.trace:1:12: expected an integer, found '88888888888888888882'");
    EXPECT_EQ(failure("cycle drill clear 5 retract 2 top 0 bottom -5 peck 0 dwell 0 f 100 return clear holes 2\n"
                      "  hole 1 1 0\n")
                  .toString(),
              "in.trace:1:1: the cycle announces 2 holes but the file ends");
    EXPECT_EQ(failure("cycle drill clear 5 retract 2 top 0 bottom -5 peck 0 dwell 0 f 100 return clear holes 1\n"
                      "  hole 1 1\n")
                  .toString(),
              "in.trace:2:11: expected a number at the end of the line");
    EXPECT_EQ(failure("plane 0 0 0 x 1 0 0 z 0.6 0 0.8\n").toString(),
              "in.trace:1:1: plane: the x and z axes must be unit vectors at right angles");
}

TEST(TraceReader, MovesThatGiveOnlySomeAxesNameThem)
{
    // A move that gives every axis keeps the plain form; one that gives fewer names its axes, and
    // the axes it leaves out are not written at all (nothing to read back as a coordinate).
    auto read = readTrace("rapid z 20\nrapid x 6 y -20\nlinear y 5 z -1 f 60\nrapid x 1 y 2 z 3\n", "t");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(traceOf(read->toolpath), "rapid z 20.0000\nrapid x 6.0000 y -20.0000\nlinear y 5.0000 z -1.0000 f "
                                       "60.0000\nrapid 1.0000 2.0000 3.0000\n");
    EXPECT_EQ(std::get<Rapid>(read->toolpath.record(0)).axes, AxisMask{AxisMask::kZ});
    EXPECT_EQ(std::get<Linear>(read->toolpath.record(2)).axes, (AxisMask{AxisMask::kY | AxisMask::kZ}));
    EXPECT_TRUE(std::get<Rapid>(read->toolpath.record(3)).axes.all());

    EXPECT_EQ(failure("rapid z 1 x 2\n").toString(), "in.trace:1:11: axis 'x' out of order or given twice (x, y, z)");
    EXPECT_EQ(failure("rapid x 1 x 2\n").toString(), "in.trace:1:11: axis 'x' out of order or given twice (x, y, z)");
    EXPECT_EQ(failure("rapid x\n").toString(), "in.trace:1:8: expected a number at the end of the line");
    EXPECT_EQ(failure("linear x 1 q 2 f 10\n").toString(), "in.trace:1:12: expected 'f', found 'q'");
}

// An untraced move (M140 MB MAX, SUPA) makes axes unknown: "unknown" and their names, in order.
TEST(TraceReader, UnknownAxesAreNamed)
{
    auto read = readTrace("rapid 1 2 3\nunknown z\nrapid x 5 y 6\nunknown x y z\n", "t");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    ASSERT_EQ(read->toolpath.size(), 4u);
    EXPECT_EQ(std::get<UnknownAxes>(read->toolpath.record(1)).axes, AxisMask{AxisMask::kZ});
    EXPECT_TRUE(std::get<UnknownAxes>(read->toolpath.record(3)).axes.all());
    EXPECT_EQ(traceOf(read->toolpath),
              "rapid 1.0000 2.0000 3.0000\nunknown z\nrapid x 5.0000 y 6.0000\nunknown x y z\n");

    EXPECT_EQ(failure("unknown\n").toString(), "in.trace:1:8: expected the axes made unknown (x, y, z)");
    EXPECT_EQ(failure("unknown 3\n").toString(), "in.trace:1:9: expected the axes made unknown (x, y, z)");
    EXPECT_EQ(failure("unknown z x\n").toString(), "in.trace:1:11: axis 'x' out of order or given twice (x, y, z)");
    EXPECT_EQ(failure("unknown z 5\n").toString(), "in.trace:1:11: unexpected '5' at the end of the line");
}

// A tool's flutes and point angle and a section's other feeds are fields a trace must keep: a
// post writes them (Klartext's tool box and list, its parametric feeds); only non-defaults appear.
TEST(TraceReader, ToolDataAndSectionFeedsRoundTrip)
{
    const std::string text = "section \"Holes\" drilling tool 2 cut 900.0000 plunge 300.0000 entry 450.0000 exit "
                             "600.0000 finish 1500.0000\n"
                             "tool 2 drill d 3.0000 r 0.0000 flute 20.0000 len 40.0000 \"D3\" flutes 3 angle 118.0000 "
                             "holder \"BT40\"\n"
                             "endsection\n";
    auto read = camwb::toolpath::readTrace(text, "in.trace");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    const auto& tool = std::get<camwb::toolpath::ToolChange>(read->toolpath.record(1)).tool;
    EXPECT_EQ(tool.flutes, 3);
    EXPECT_EQ(tool.pointAngleDeg, 118);
    const auto& section = std::get<camwb::toolpath::SectionBegin>(read->toolpath.record(0));
    EXPECT_EQ(section.feeds.finishingMmPerMin, 1500);
    EXPECT_EQ(section.feeds.entryMmPerMin, 450);
    EXPECT_EQ(section.feeds.exitMmPerMin, 600);
    EXPECT_EQ(camwb::toolpath::traceOf(read->toolpath), text);
}

TEST(TraceReader, FiveAxisMovesCarryTheMachinesKnownRotaryAxes)
{
    ToolAxisMove move{{1, 2, 3}, {0, 0.6, 0.8}, 250};
    move.machine.bDeg = -36.8699;
    move.machine.cDeg = 365;
    move.machine.known = RotaryAxes::kB | RotaryAxes::kC;
    Toolpath t;
    t.add(move);
    t.add(ToolAxisMove{{1, 2, 4}, {0, 0, 1}, 0});
    const std::string trace = traceOf(t);
    EXPECT_EQ(trace,
              "move5 1.0000 2.0000 3.0000 axis 0.000000000 0.600000000 0.800000000 f 250.0000 b -36.8699 c 365.0000\n"
              "move5 1.0000 2.0000 4.0000 axis 0.000000000 0.000000000 1.000000000 f 0.0000\n");
    auto read = readTrace(trace, "in.trace");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(traceOf(read->toolpath), trace);
    const auto& back = std::get<ToolAxisMove>(read->toolpath.record(0));
    EXPECT_EQ(back.machine.known, RotaryAxes::kB | RotaryAxes::kC);
    EXPECT_EQ(back.machine.cDeg, 365);
    EXPECT_EQ(std::get<ToolAxisMove>(read->toolpath.record(1)).machine.known, 0);
    // In the order a b c, each once.
    EXPECT_EQ(failure("move5 1 2 3 axis 0 0 1 f 0 c 5 b 3\n").toString(),
              "in.trace:1:32: unexpected 'b' (after a five-axis move's feed: a A, b B, c C, joint)");
    EXPECT_EQ(failure("move5 1 2 3 axis 0 0 1 f 0 b\n").toString(),
              "in.trace:1:29: expected a number at the end of the line");
}

// NC read back without tool-tip control: the move is the machine's (joint interpolated), and an
// operation's own post property values ride on its section; both read back as written.
TEST(TraceReader, JointMovesAndSectionPropertiesReadBack)
{
    Toolpath t;
    SectionBegin section{"Ring", "swarf", 1, {600, 200, 0, 0, 0}};
    section.postProperties = {{"tcpm", "off"}, {"rotaryFeed", "m116"}};
    t.add(section);
    ToolAxisMove joint{{1, 2, 3}, {0, 0, 1}, 100};
    joint.machine.bDeg = 0;
    joint.machine.known = RotaryAxes::kB;
    joint.jointInterpolated = true;
    t.add(joint);
    const std::string trace = traceOf(t);
    EXPECT_EQ(
        trace,
        "section \"Ring\" swarf tool 1 cut 600.0000 plunge 200.0000 set tcpm \"off\" set rotaryFeed "
        "\"m116\"\nmove5 1.0000 2.0000 3.0000 axis 0.000000000 0.000000000 1.000000000 f 100.0000 b 0.0000 joint\n");
    auto read = readTrace(trace, "in.trace");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(traceOf(read->toolpath), trace);
    EXPECT_EQ(std::get<SectionBegin>(read->toolpath.record(0)).postProperties, section.postProperties);
    EXPECT_TRUE(std::get<ToolAxisMove>(read->toolpath.record(1)).jointInterpolated);
    EXPECT_EQ(failure("section \"A\" - tool 1 cut 1 plunge 1 set tcpm\n").toString().find("in.trace:1:"), 0u);
}
