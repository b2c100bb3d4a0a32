// posts/linuxcnc.js against LinuxCNC's own interpreter: what rs274 reads back from the posted NC
// must be the CL motion (lines, arcs in G17/G18/G19, helices, full circles, every canned cycle in
// both return modes, dwell, tool changes, offsets, feed modes) within the output precision.
#include "RoundTripFixture.h"

#include "toolpath/RecordNames.h"

#include <algorithm>
#include <ostream>

namespace camwb::external::test {
namespace {

using namespace toolpath;

Toolpath start(int tool = 1, double rpm = 3000)
{
    Toolpath path;
    path.add(SectionBegin{"Round trip", "profile", tool, {}}, {0, 0});
    path.add(ToolChange{Tool{tool, "D6", "flat", 6}}, {0, 1});
    path.add(Spindle{rpm, true}, {0, 2});
    path.add(Rapid{{0, 0, 20}}, {0, 3});
    return path;
}

TEST_F(LinuxCncRoundTrip, LinesAndRapids)
{
    Toolpath path = start();
    path.add(Rapid{{-12.3456, 7.89, 20}});
    path.add(Rapid{{-12.3456, 7.89, 2}});
    path.add(Linear{{-12.3456, 7.89, -1.25}, 150});
    path.add(Linear{{40.0004, 7.89, -1.25}, 600});
    path.add(Linear{{40.0004, -33.3333, -1.25}, 600});
    path.add(Linear{{0.0001, -0.0004, -2.5}, 333.3333});
    path.add(Linear{{0.0001, -0.0004, -2.5}, 333.3333});  // no motion: no block
    path.add(Rapid{{0, 0, 20}});
    expectRoundTrip(path);
}

TEST_F(LinuxCncRoundTrip, ArcsInEveryPlane)
{
    Toolpath path = start();
    path.add(Rapid{{10, 0, 5}});
    path.add(Linear{{10, 0, 0}, 200});
    path.add(Arc{{0, 10, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 500});  // G17 G3 quarter
    path.add(Arc{{-7.0711, -7.0711, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 500});
    path.add(Arc{{10, 0, 0}, {0, 0, 0}, {0, 0, -1}, true, 0, 500});  // about -Z: G3
    path.add(Arc{{3.3333, 6.6667, 0}, {6.6667, 3.3333, 0}, {0, 0, 1}, true, 0, 450});
    path.add(Arc{{13.3333, 6.6667, 0}, {8.3333, 6.6667, 0}, {0, 1, 0}, true, 0, 400});   // G18, ZX
    path.add(Arc{{8.3333, 6.6667, 5}, {8.3333, 6.6667, 0}, {0, -1, 0}, true, 0, 400});   // G18 seen from -Y
    path.add(Arc{{8.3333, 11.6667, 0}, {8.3333, 6.6667, 0}, {1, 0, 0}, false, 0, 400});  // G19
    path.add(Arc{{8.3333, 1.6667, 0}, {8.3333, 6.6667, 0}, {1, 0, 0}, true, 0, 400});
    path.add(Linear{{8.3333, 1.6667, 2}, 400});
    path.add(Arc{{0, 0, 2}, {4.1667, 0.8333, 2}, {0, 0, 1}, true, 0, 400});  // back to G17
    expectRoundTrip(path);
}

TEST_F(LinuxCncRoundTrip, HelicesAndFullCircles)
{
    Toolpath path = start();
    path.add(Rapid{{49, 30, 20}});
    path.add(Linear{{49, 30, 15}, 200});
    path.add(Arc{{49, 30, 15}, {45, 30, 15}, {0, 0, 1}, true, 0, 300});          // full circle
    path.add(Arc{{41, 30, 14.5833}, {45, 30, 15}, {0, 0, 1}, true, 0, 300});     // half-turn helix
    path.add(Arc{{41, 30, 12.0}, {45, 30, 14.5833}, {0, 0, 1}, false, 2, 300});  // 2 extra turns
    path.add(Arc{{41, 30, 12.0}, {45, 30, 12.0}, {0, 0, -1}, false, 1, 300});    // 2 full circles about -Z
    path.add(Linear{{41, 30, 20}, 300});
    path.add(Arc{{41, 30, 20}, {41, 30, 25}, {0, 1, 0}, false, 0, 300});  // full circle in ZX
    path.add(Arc{{51, 35, 20}, {46, 30, 20}, {0, 1, 0}, true, 1, 300});   // ZX helix along Y, 1.5 turns
    path.add(Arc{{61, 35, 20}, {51, 35, 25}, {1, 0, 0}, true, 1, 300});   // YZ helix along X, 2 turns
    expectRoundTrip(path);
}

TEST_F(LinuxCncRoundTrip, DwellToolChangesOffsetsCoolantAndStops)
{
    Toolpath path;
    path.add(WorkOffset{2});
    Toolpath first = start(3, 2500);
    path.append(first);
    path.add(Coolant{CoolantMode::Mist});
    path.add(Linear{{5, 5, 0}, 300});
    path.add(Dwell{1.25});
    path.add(Coolant{CoolantMode::Flood});  // M9 before M8: M7 and M8 add up in LinuxCNC
    path.add(ProgramStop{true});
    path.add(WorkOffset{7});
    path.add(Rapid{{5, 5, 30}});
    path.add(ToolChange{Tool{12, "Drill 4.2", "drill", 4.2}});  // spindle turning: M6 stops it
    path.add(Rapid{{0, 0, 30}});
    path.add(Spindle{1500.5, false});
    path.add(Linear{{0, 0, 10}, 120});
    path.add(Dwell{0.001});
    path.add(ProgramStop{false});
    path.add(Spindle{0, true});
    path.add(Coolant{CoolantMode::Off});
    path.add(WorkOffset{9});
    path.add(ToolChange{Tool{1, "D6", "flat", 6}});
    path.add(Spindle{8000, true});
    path.add(Coolant{CoolantMode::Flood});
    path.add(Rapid{{0, 0, 40}});
    expectRoundTrip(path);
}

TEST_F(LinuxCncRoundTrip, FeedModes)
{
    Toolpath path = start();
    path.add(Rapid{{10, 0, 0}});
    path.add(FeedModeChange{FeedMode::PerRevolution});
    path.add(Linear{{20, 0, 0}, 0.05});
    path.add(Arc{{30, 0, 0}, {25, 0, 0}, {0, 0, 1}, true, 0, 0.08});
    path.add(FeedModeChange{FeedMode::InverseTime});
    path.add(Linear{{30, 10, 0}, 12.5});
    path.add(Linear{{40, 10, -1}, 3});
    path.add(Arc{{40, 10, -3}, {35, 10, -1}, {0, 0, 1}, false, 1, 0.75});  // 2 turns: the pieces share the time
    path.add(Rapid{{40, 10, 10}});
    path.add(FeedModeChange{FeedMode::PerMinute});
    path.add(Linear{{40, 10, 5}, 800});
    expectRoundTrip(path);
}

TEST_F(LinuxCncRoundTrip, CutterCompensationWithARadiusZeroTool)
{
    // The rs274 tool table gives every tool diameter 0: the compensated path is the programmed one.
    Toolpath path = start(5);
    path.add(Rapid{{-20, -20, 5}});
    path.add(Linear{{-20, -20, -1}, 200});
    path.add(CutterComp{CutterCompSide::Left});
    path.add(Linear{{0, -10, -1}, 400});  // straight entry, longer than the tool radius (3)
    path.add(Linear{{30, -10, -1}, 400});
    path.add(Arc{{40, 0, -1}, {30, 0, -1}, {0, 0, 1}, false, 0, 400});
    path.add(Linear{{40, 20, -1}, 400});
    path.add(CutterComp{CutterCompSide::Off});
    path.add(Linear{{60, 40, -1}, 400});  // straight exit
    path.add(Rapid{{60, 40, 5}});
    path.add(CutterComp{CutterCompSide::Right});
    path.add(Rapid{{0, 60, 5}});  // rapid entry
    path.add(Linear{{0, 60, -1}, 200});
    path.add(Arc{{0, 60, -1}, {10, 60, -1}, {0, 0, 1}, true, 0, 400});
    path.add(CutterComp{CutterCompSide::Off});
    path.add(Rapid{{-10, 60, 5}});
    expectRoundTrip(path);
}

struct CycleCase {
    CycleKind kind;
    double dwell;
    bool returnToClearance;
};

void PrintTo(const CycleCase& c, std::ostream* out)
{
    *out << toolpath::name(c.kind) << " dwell " << c.dwell << (c.returnToClearance ? " G98" : " G99");
}

class LinuxCncCycles : public LinuxCncRoundTrip, public testing::WithParamInterface<CycleCase> {};

TEST_P(LinuxCncCycles, ExpandAsLinuxCncDoes)
{
    const CycleCase& c = GetParam();
    Toolpath path = start(2, 800);
    path.add(Rapid{{-5, -5, 30}});
    // A spot with dwell first: rs274 keeps P (and Q, R) from one cycle to the next unless written.
    path.add(Cycle{CycleKind::DrillDwell, 30, 2.5, 0, -1, 0, 0.9, 100, {{-5, -5, 0}}});
    Cycle cycle{c.kind, 15, 2.5, 0, -12.3, 2.7, c.dwell, 120, {{10, 10, 0}, {25.5, 10, 0}, {25.5, -7.25, 0}}};
    cycle.returnToClearance = c.returnToClearance;
    path.add(cycle);
    path.add(Rapid{{40, 40, 15}});
    // A second cycle right after the first, in the other return mode.
    Cycle next{CycleKind::Drill, 10, 1, 0, -3, 0, 0, 90, {{40, 40, 0}, {45, 40, 0}}};
    next.returnToClearance = !c.returnToClearance;
    path.add(next);
    path.add(Linear{{45, 40, 12}, 500});
    expectRoundTrip(path);
}

std::string cycleName(const testing::TestParamInfo<CycleCase>& info)
{
    const char* kinds[] = {"Drill", "DrillDwell", "Peck", "ChipBreak", "Tap", "Bore"};
    return std::string(kinds[static_cast<int>(info.param.kind)]) + (info.param.dwell > 0 ? "WithDwell" : "") +
           (info.param.returnToClearance ? "G98" : "G99");
}

INSTANTIATE_TEST_SUITE_P(EveryKindBothReturnModes, LinuxCncCycles,
                         testing::Values(CycleCase{CycleKind::Drill, 0, true}, CycleCase{CycleKind::Drill, 0, false},
                                         CycleCase{CycleKind::Drill, 0.4, true},
                                         CycleCase{CycleKind::DrillDwell, 0.75, true},
                                         CycleCase{CycleKind::DrillDwell, 0.75, false},
                                         CycleCase{CycleKind::Peck, 0, true}, CycleCase{CycleKind::Peck, 0, false},
                                         CycleCase{CycleKind::ChipBreak, 0, true},
                                         CycleCase{CycleKind::ChipBreak, 0, false}, CycleCase{CycleKind::Tap, 0, true},
                                         CycleCase{CycleKind::Tap, 0.3, false}, CycleCase{CycleKind::Bore, 0, true},
                                         CycleCase{CycleKind::Bore, 0, false}, CycleCase{CycleKind::Bore, 1.5, true},
                                         CycleCase{CycleKind::Bore, 1.5, false}),
                         cycleName);

TEST_F(LinuxCncRoundTrip, CommentsNeverBecomeActiveOrBreakLines)
{
    Toolpath path = start();
    path.add(Comment{"MSG, this must not pop up"});
    path.add(Comment{" debug , #5220"});
    path.add(Comment{"(PRINT,#<_x>)"});
    path.add(Comment{"probeopen /tmp/x.txt"});
    path.add(Comment{"nested (parentheses (twice)) and ; semicolon"});
    path.add(Comment{"line\nbreak"});
    path.add(Comment{"Grüße, ½ mm, 直径 " + std::string(300, 'x')});
    path.add(Rapid{{1, 1, 20}});
    std::optional<RoundTrip> trip = postAndRead(path);
    ASSERT_TRUE(trip);
    EXPECT_TRUE(trip->program.messages.empty());
    std::vector<std::string> comments;
    for (const Record& record : trip->program.motion.records())
        if (const auto* comment = std::get_if<Comment>(&record))
            comments.push_back(comment->text);
    const std::vector<std::string> expected = {"- MSG, this must not pop up",
                                               "- debug , #5220",
                                               "[PRINT,#<_x>]",
                                               "- probeopen /tmp/x.txt",
                                               "nested [parentheses [twice]] and ; semicolon",
                                               "line break"};
    for (const std::string& text : expected)
        EXPECT_NE(std::find(comments.begin(), comments.end(), text), comments.end()) << text;
}

}  // namespace
}  // namespace camwb::external::test
