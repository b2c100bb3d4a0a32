#include "toolpath/Toolpath.h"
#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

using namespace camwb::toolpath;

namespace {

std::string traceOne(Record r)
{
    Toolpath tp;
    tp.add(std::move(r));
    return traceOf(tp);
}

}  // namespace

TEST(TraceWriter, Moves)
{
    EXPECT_EQ(traceOne(Rapid{{1, 2.5, -3}}), "rapid 1.0000 2.5000 -3.0000\n");
    EXPECT_EQ(traceOne(Linear{{0.12345, -0.00004, 100}, 250}), "linear 0.1235 0.0000 100.0000 f 250.0000\n");
    Arc arc;
    arc.to = {10, 0, -1};
    arc.center = {5, 0, -1};
    arc.clockwise = true;
    arc.turns = 2;
    arc.feedMmPerMin = 800;
    EXPECT_EQ(traceOne(arc),
              "arc cw 10.0000 0.0000 -1.0000 c 5.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 2 f 800.0000\n");
    arc.clockwise = false;
    arc.turns = 0;
    EXPECT_EQ(traceOne(arc),
              "arc ccw 10.0000 0.0000 -1.0000 c 5.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 0 f 800.0000\n");
    EXPECT_EQ(traceOne(ToolAxisMove{{1, 2, 3}, {0, 0.6, 0.8}, 0}),
              "move5 1.0000 2.0000 3.0000 axis 0.000000000 0.600000000 0.800000000 f 0.0000\n");
}

TEST(TraceWriter, AMoveNamesItsFeedKindAfterTheFeedOnlyWhenItHasOne)
{
    EXPECT_EQ(traceOne(Linear{{1, 2, 3}, 500, {}, FeedKind::Plunge}),
              "linear 1.0000 2.0000 3.0000 f 500.0000 plunge\n");
    EXPECT_EQ(traceOne(Linear{{1, 2, 3}, 500, AxisMask{AxisMask::kZ}, FeedKind::Entry}),
              "linear z 3.0000 f 500.0000 entry\n");
    EXPECT_EQ(traceOne(Linear{{1, 2, 3}, 500}), "linear 1.0000 2.0000 3.0000 f 500.0000\n");  // as before kinds
    EXPECT_EQ(traceOne(Arc{{10, 0, -1}, {5, 0, -1}, {0, 0, 1}, true, 0, 800, FeedKind::Finishing}),
              "arc cw 10.0000 0.0000 -1.0000 c 5.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 0 f 800.0000 "
              "finishing\n");
    for (FeedKind kind : {FeedKind::Cutting, FeedKind::Exit})
        EXPECT_EQ(traceOne(Linear{{0, 0, 0}, 1, {}, kind}), std::string("linear 0.0000 0.0000 0.0000 f 1.0000 ") +
                                                                (kind == FeedKind::Cutting ? "cutting\n" : "exit\n"));
}

TEST(TraceWriter, NegativeZeroIsNormalised)
{
    EXPECT_EQ(traceOne(Rapid{{-0.0, -0.00001, -0.00005}}), "rapid 0.0000 0.0000 -0.0001\n");
    EXPECT_EQ(traceOne(Rapid{{-0.00004999, 0, -0.0}}), "rapid 0.0000 0.0000 0.0000\n");
    EXPECT_EQ(traceOne(Dwell{-0.0}), "dwell 0.0000\n");
}

TEST(TraceWriter, MachineStateRecords)
{
    Tool tool;
    tool.number = 3;
    tool.name = "Flat 10";
    tool.kind = "flat";
    tool.diameterMm = 10;
    tool.cornerRadiusMm = 0.5;
    tool.fluteLengthMm = 22;
    tool.lengthMm = 75;
    EXPECT_EQ(traceOne(ToolChange{tool}), "tool 3 flat d 10.0000 r 0.5000 flute 22.0000 len 75.0000 \"Flat 10\"\n");
    tool.holder = "SK40 \"ER32\"";  // after the name, only when there is one
    EXPECT_EQ(traceOne(ToolChange{tool}),
              "tool 3 flat d 10.0000 r 0.5000 flute 22.0000 len 75.0000 \"Flat 10\" holder \"SK40 \\\"ER32\\\"\"\n");
    EXPECT_EQ(traceOne(Spindle{12000, true}), "spindle 12000.0000 cw\n");
    EXPECT_EQ(traceOne(Spindle{0, false}), "spindle 0.0000 ccw\n");
    EXPECT_EQ(traceOne(Coolant{CoolantMode::Off}), "coolant off\n");
    EXPECT_EQ(traceOne(Coolant{CoolantMode::Flood}), "coolant flood\n");
    EXPECT_EQ(traceOne(Coolant{CoolantMode::Mist}), "coolant mist\n");
    EXPECT_EQ(traceOne(Coolant{CoolantMode::ThroughTool}), "coolant throughTool\n");
    EXPECT_EQ(traceOne(FeedModeChange{FeedMode::PerMinute}), "feedmode perMinute\n");
    EXPECT_EQ(traceOne(FeedModeChange{FeedMode::PerRevolution}), "feedmode perRevolution\n");
    EXPECT_EQ(traceOne(FeedModeChange{FeedMode::InverseTime}), "feedmode inverseTime\n");
    EXPECT_EQ(traceOne(WorkOffset{2}), "workoffset 2\n");
    EXPECT_EQ(traceOne(Dwell{1.5}), "dwell 1.5000\n");
    EXPECT_EQ(traceOne(CutterComp{CutterCompSide::Left}), "comp left\n");
    EXPECT_EQ(traceOne(CutterComp{CutterCompSide::Right}), "comp right\n");
    EXPECT_EQ(traceOne(CutterComp{CutterCompSide::Off}), "comp off\n");
    EXPECT_EQ(traceOne(Comment{"roughing"}), "comment \"roughing\"\n");
}

TEST(TraceWriter, CycleListsItsHoles)
{
    Cycle c;
    c.kind = CycleKind::Peck;
    c.clearanceZ = 20;
    c.retractZ = 2;
    c.topZ = 0;
    c.bottomZ = -15;
    c.peckMm = 3;
    c.dwellSeconds = 0.25;
    c.feedMmPerMin = 120;
    c.holes = {{10, 10, 0}, {20, -0.0, 0}};
    EXPECT_EQ(traceOne(c),
              "cycle peck clear 20.0000 retract 2.0000 top 0.0000 bottom -15.0000 peck 3.0000 dwell 0.2500 "
              "f 120.0000 return clear holes 2\n"
              "  hole 10.0000 10.0000 0.0000\n"
              "  hole 20.0000 0.0000 0.0000\n");
    c.returnToClearance = false;
    c.holes.clear();
    EXPECT_NE(traceOne(c).find(" return retract holes 0\n"), std::string::npos);
    const std::pair<CycleKind, const char*> names[] = {{CycleKind::Drill, "drill"},
                                                       {CycleKind::DrillDwell, "drillDwell"},
                                                       {CycleKind::ChipBreak, "chipBreak"},
                                                       {CycleKind::Tap, "tap"},
                                                       {CycleKind::Bore, "bore"}};
    for (const auto& [kind, name] : names) {
        Cycle k;
        k.kind = kind;
        EXPECT_EQ(traceOne(k).rfind(std::string("cycle ") + name + " clear", 0), 0u) << name;
    }
}

TEST(TraceWriter, Sections)
{
    SectionBegin s;
    s.operationName = "Contour 1";
    s.strategy = "profile";
    s.toolNumber = 4;
    s.feeds.cuttingMmPerMin = 1200;
    s.feeds.plungeMmPerMin = 300;
    EXPECT_EQ(traceOne(s), "section \"Contour 1\" profile tool 4 cut 1200.0000 plunge 300.0000\n");
    EXPECT_EQ(traceOne(SectionEnd{}), "endsection\n");
}

TEST(TraceWriter, StopsAndPassThrough)
{
    EXPECT_EQ(traceOne(ProgramStop{}), "stop\n");
    EXPECT_EQ(traceOne(ProgramStop{true}), "stop optional\n");
    EXPECT_EQ(traceOne(PassThrough{"M110"}), "passthrough \"M110\"\n");
}

TEST(TraceWriter, WholeToolpathIsOneLinePerRecord)
{
    Toolpath tp;
    tp.add(Rapid{{0, 0, 5}});
    tp.add(Linear{{0, 0, -1}, 100});
    tp.add(SectionEnd{});
    EXPECT_EQ(traceOf(tp), "rapid 0.0000 0.0000 5.0000\nlinear 0.0000 0.0000 -1.0000 f 100.0000\nendsection\n");
    EXPECT_EQ(traceOf(Toolpath{}), "");
}
