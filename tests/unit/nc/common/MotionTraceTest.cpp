// The canonical motion trace: one entry per motion with its source line and running state,
// the same fields in text and JSONL, subprogram lines named with their file.
#include "nc/MotionTrace.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc {
namespace {

using namespace camwb::toolpath;

SourceRef at(int line, int file = 0) { return SourceRef{-1, -1, line, file}; }

Toolpath sample()
{
    Toolpath p;
    p.add(ToolChange{Tool{3}}, at(2));
    p.add(Spindle{1200, false}, at(3));
    p.add(Rapid{{10, 0, 5}}, at(4));
    p.add(Linear{{10, 0, -1}, 150}, at(5));
    p.add(Arc{{0, 10, -1}, {0, 0, -1}, {0, 0, 1}, false, 0, 300}, at(6));
    p.add(Arc{{0, 10, -3}, {0, 0, -1}, {0, 0, 1}, true, 1, 300}, at(7, 1));
    p.add(FeedModeChange{FeedMode::PerRevolution}, at(8));
    p.add(Dwell{0.5}, at(9));
    Cycle c;
    c.kind = CycleKind::Peck;
    c.clearanceZ = 20;
    c.retractZ = 2;
    c.bottomZ = -12;
    c.peckMm = 4;
    c.feedMmPerMin = 0.1;
    c.holes = {{5, 5, 0}, {15, 5, 0}};
    p.add(c, at(10));
    return p;
}

TEST(MotionTrace, TextHasOneLinePerMotionWithState)
{
    const std::string text = motionTrace(sample(), {"main.mpf", "/x/SUB.SPF"}, TraceFormat::Text);
    EXPECT_EQ(text,
              "4 rapid 10.0000 0.0000 5.0000 s 1200.0000 ccw t 3\n"
              "5 linear 10.0000 0.0000 -1.0000 f 150.0000 s 1200.0000 ccw t 3\n"
              "6 arc ccw 0.0000 10.0000 -1.0000 c 0.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 0 f 300.0000 "
              "s 1200.0000 ccw t 3\n"
              "SUB.SPF:7 helix cw 0.0000 10.0000 -3.0000 c 0.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 1 f "
              "300.0000 s 1200.0000 ccw t 3\n"
              "9 dwell 0.5000\n"
              "10 cycle peck 5.0000 5.0000 0.0000 bottom -12.0000 top 0.0000 r 2.0000 clear 20.0000 peck 4.0000 "
              "return clear fr 0.1000 s 1200.0000 ccw t 3\n"
              "10 cycle peck 15.0000 5.0000 0.0000 bottom -12.0000 top 0.0000 r 2.0000 clear 20.0000 peck 4.0000 "
              "return clear fr 0.1000 s 1200.0000 ccw t 3\n");
}

TEST(MotionTrace, JsonlCarriesTheSameFields)
{
    const std::string json = motionTrace(sample(), {"main.mpf", "SUB.SPF"}, TraceFormat::Jsonl);
    const auto firstLine = json.substr(0, json.find('\n'));
    EXPECT_EQ(firstLine, "{\"file\":\"main.mpf\",\"line\":4,\"kind\":\"rapid\",\"to\":[10.0000,0.0000,5.0000],"
                         "\"spindle\":1200.0000,\"spindleCw\":false,\"tool\":3}");
    EXPECT_NE(json.find("{\"file\":\"SUB.SPF\",\"line\":7,\"kind\":\"helix\""), std::string::npos);
    EXPECT_NE(json.find("\"feed\":0.1000,\"feedMode\":\"perRevolution\""), std::string::npos);
    EXPECT_EQ(std::count(json.begin(), json.end(), '\n'), 7);
}

TEST(MotionTrace, MovesWhileAnAxisIsUnknownNameTheKnownAxes)
{
    Toolpath p;
    p.add(Rapid{{0, 0, 20}, AxisMask{AxisMask::kZ}}, at(2));
    p.add(Linear{{5, 0, 20}, 100, AxisMask{AxisMask::kX | AxisMask::kZ}}, at(3));
    p.add(Rapid{{5, 7, 20}, AxisMask{AxisMask::kY}}, at(4));  // the last unknown axis: a full entry
    EXPECT_EQ(motionTrace(p, {"a.nc"}, TraceFormat::Text), "2 rapid z 20.0000 s 0.0000 t 0\n"
                                                           "3 linear x 5.0000 z 20.0000 f 100.0000 s 0.0000 t 0\n"
                                                           "4 rapid 5.0000 7.0000 20.0000 s 0.0000 t 0\n");
    const std::string json = motionTrace(p, {"a.nc"}, TraceFormat::Jsonl);
    EXPECT_EQ(json.substr(0, json.find('\n')), "{\"file\":\"a.nc\",\"line\":2,\"kind\":\"rapid\",\"to\":[null,null,"
                                               "20.0000],\"spindle\":0.0000,\"spindleCw\":true,\"tool\":0}");
}

// An untraced move (M140 MB MAX, SUPA) is an entry of its own; the moves after it name the known
// axes until every one is given again, instead of carrying the old value on.
TEST(MotionTrace, UnknownAxesAreAnEntryAndTheOldValuesAreNotShownAgain)
{
    Toolpath p;
    p.add(Rapid{{10, 10, 5}}, at(2));
    p.add(UnknownAxes{AxisMask{AxisMask::kZ}}, at(3));
    p.add(Rapid{{90, 90, 0}, AxisMask{AxisMask::kX | AxisMask::kY}}, at(4));
    p.add(UnknownAxes{}, at(5));
    p.add(Rapid{{1, 2, 3}}, at(6));
    EXPECT_EQ(motionTrace(p, {"a.h"}, TraceFormat::Text), "2 rapid 10.0000 10.0000 5.0000 s 0.0000 t 0\n"
                                                          "3 unknown z\n"
                                                          "4 rapid x 90.0000 y 90.0000 s 0.0000 t 0\n"
                                                          "5 unknown x y z\n"
                                                          "6 rapid 1.0000 2.0000 3.0000 s 0.0000 t 0\n");
    const std::string json = motionTrace(p, {"a.h"}, TraceFormat::Jsonl);
    EXPECT_NE(json.find("{\"file\":\"a.h\",\"line\":3,\"kind\":\"unknown\",\"axes\":[\"z\"]}\n"
                        "{\"file\":\"a.h\",\"line\":4,\"kind\":\"rapid\",\"to\":[90.0000,90.0000,null]"),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"kind\":\"unknown\",\"axes\":[\"x\",\"y\",\"z\"]}"), std::string::npos) << json;
}

TEST(MotionTrace, FiveAxisMovesCarryTheToolVectorAndTheKnownRotaryAxes)
{
    Toolpath p;
    ToolAxisMove move{{10, 20, 5}, {-0.383022, 0.321394, 0.866025}, 500};
    move.machine.bDeg = 30;
    move.machine.cDeg = 40;
    move.machine.known = RotaryAxes::kB | RotaryAxes::kC;
    p.add(move, at(3));
    p.add(ToolAxisMove{{10, 20, 50}, {0, 0, 1}, 0}, at(4));  // no machine angles known: none written
    EXPECT_EQ(
        motionTrace(p, {"a.h"}, TraceFormat::Text),
        "3 linear5 10.0000 20.0000 5.0000 axis -0.3830 0.3214 0.8660 b 30.0000 c 40.0000 f 500.0000 s 0.0000 t 0\n"
        "4 rapid5 10.0000 20.0000 50.0000 axis 0.0000 0.0000 1.0000 s 0.0000 t 0\n");
    const std::string json = motionTrace(p, {"a.h"}, TraceFormat::Jsonl);
    EXPECT_EQ(json.substr(0, json.find('\n')),
              "{\"file\":\"a.h\",\"line\":3,\"kind\":\"linear5\",\"to\":[10.0000,20.0000,5.0000],\"i\":-0.3830,"
              "\"j\":0.3214,\"k\":0.8660,\"b\":30.0000,\"c\":40.0000,\"feed\":500.0000,\"feedMode\":\"perMinute\","
              "\"spindle\":0.0000,\"spindleCw\":true,\"tool\":0}");
}

TEST(MotionTrace, EmptyProgramTracesNothing) { EXPECT_EQ(motionTrace(Toolpath{}, {"a.nc"}, TraceFormat::Text), ""); }

// What MotionTraceWriter hands over, piece by piece.
struct Chunks {
    std::vector<std::string> pieces;
    bool accept = true;
    MotionTraceWriter::Write write()
    {
        return [this](std::string_view text) {
            pieces.emplace_back(text);
            return accept;
        };
    }
    std::string all() const
    {
        std::string out;
        for (const std::string& piece : pieces)
            out += piece;
        return out;
    }
};

TEST(MotionTraceWriter, StreamsTheSameTextAsTheRecordedTrace)
{
    const std::vector<std::string> files{"/x/main.mpf", "/x/SUB.SPF"};
    for (const TraceFormat format : {TraceFormat::Text, TraceFormat::Jsonl}) {
        Chunks chunks;
        MotionTraceWriter writer(files[0], format, chunks.write(), 64);
        play(sample(), writer);
        EXPECT_TRUE(writer.finish(files));
        EXPECT_EQ(chunks.all(), motionTrace(sample(), files, format));
        EXPECT_GT(chunks.pieces.size(), 2u);  // in chunks of about 64 bytes, not at the end
    }
}

TEST(MotionTraceWriter, WritesWhileTheProgramRunsAndHoldsBackCalledProgramsUntilTheirNamesAreKnown)
{
    Toolpath p = sample();
    Chunks chunks;
    MotionTraceWriter writer("main.mpf", TraceFormat::Text, chunks.write(), 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
        writer.setSource(p.source(i));
        dispatch(p.record(i), writer);
        if (i == 4)  // the arc of line 6, before the first record of SUB.SPF
            EXPECT_EQ(chunks.all(), motionTrace(p, {"main.mpf"}, TraceFormat::Text).substr(0, chunks.all().size()));
    }
    // Line 4, 5 and 6 went out as they came; SUB.SPF:7 and what follows wait for the file names.
    EXPECT_EQ(chunks.pieces.size(), 3u);
    EXPECT_TRUE(writer.finish({"main.mpf", "SUB.SPF"}));
    EXPECT_EQ(chunks.all(), motionTrace(p, {"main.mpf", "SUB.SPF"}, TraceFormat::Text));
    EXPECT_NE(chunks.all().find("\nSUB.SPF:7 helix"), std::string::npos);
}

TEST(MotionTraceWriter, AFailedWriteIsReported)
{
    Chunks chunks;
    chunks.accept = false;
    MotionTraceWriter writer("main.mpf", TraceFormat::Text, chunks.write(), 16);
    play(sample(), writer);
    EXPECT_FALSE(writer.finish({"main.mpf", "SUB.SPF"}));
    EXPECT_EQ(chunks.pieces.size(), 1u);  // nothing more is offered after the failure
}

}  // namespace
}  // namespace camwb::nc
