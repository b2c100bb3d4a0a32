// The rs274 trace reader and the motion comparison on fixed texts: the round-trip tests are only as
// good as these two, so they are checked against hand-made traces (taken from LinuxCNC 2.9 runs).
#include "Rs274Trace.h"
#include "LinuxCncModel.h"
#include "MotionCompare.h"

#include "toolpath/TraceWriter.h"

#include <gtest/gtest.h>

namespace camwb::external::test {
namespace {

using namespace toolpath;

const char* kTrace = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    7 N..... COMMENT("PART1")
    8 N..... COMMENT("interpreter: feed mode set to units per minute")
   17 N..... SELECT_TOOL(1)
   18 N..... START_CHANGE()
   19 N..... STOP_SPINDLE_TURNING(0)
   20 N..... CHANGE_TOOL(1)
   21 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 12.9794, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)
   22 N..... SET_SPINDLE_SPEED(0, 1000.0000)
   23 N..... START_SPINDLE_CLOCKWISE(0)
   24 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 10.0000, 0.0000, 0.0000, 0.0000)
   25 N..... SET_FEED_RATE(100.0000)
   26 N..... STRAIGHT_FEED(0.0000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000)
   27 N..... ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, -1, -1.0000, 0.0000, 0.0000, 0.0000)
   28 N..... SELECT_PLANE(CANON_PLANE_XZ)
   29 N..... ARC_FEED(-1.0000, 20.0000, -1.0000, 15.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   30 N..... SELECT_PLANE(CANON_PLANE_YZ)
   31 N..... ARC_FEED(5.0000, -1.0000, 2.5000, -1.0000, -2, 20.0000, 0.0000, 0.0000, 0.0000)
   32 N..... MIST_ON()
   33 N..... FLOOD_ON()
   34 N..... MIST_OFF()
   35 N..... DWELL(0.5000)
   36 N..... SET_G5X_OFFSET(7, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   37 N..... OPTIONAL_PROGRAM_STOP()
   38 N..... MESSAGE("hello")
   39 N..... COMMENT("interpreter: feed mode set to inverse time")
   40 N..... SET_FEED_MODE(0, 0)
   41 N..... PROGRAM_END()
   42 N..... STRAIGHT_TRAVERSE(9.0000, 9.0000, 9.0000, 0.0000, 0.0000, 0.0000)
)";

TEST(Rs274Trace, RebuildsMotionAndState)
{
    auto program = readRs274Trace(kTrace);
    ASSERT_TRUE(program.ok()) << program.error().toString();
    EXPECT_TRUE(program->programEnd);
    EXPECT_EQ(program->messages, std::vector<std::string>{"hello"});
    EXPECT_EQ(program->toolLengthOffsetsMm, std::vector<double>{12.9794});
    const std::string trace = traceOf(program->motion);
    EXPECT_EQ(trace,
              "comment \"PART1\"\n"
              "tool 1 flat d 0.0000 r 0.0000 flute 0.0000 len 0.0000 \"\"\n"
              "spindle 1000.0000 cw\n"
              "rapid 0.0000 0.0000 10.0000\n"
              "linear 0.0000 0.0000 -1.0000 f 100.0000\n"
              "arc cw 10.0000 0.0000 -1.0000 c 5.0000 0.0000 -1.0000 n 0.0000 0.0000 1.0000 turns 0 f 100.0000\n"
              // G18: first axis Z, second X; +1 = counter-clockwise about +Y
              "arc ccw 20.0000 0.0000 -1.0000 c 15.0000 0.0000 -1.0000 n 0.0000 1.0000 0.0000 turns 0 f 100.0000\n"
              // G19: first axis Y, second Z; -2 = clockwise with one extra turn; X is the helix axis
              "arc cw 20.0000 5.0000 -1.0000 c 20.0000 2.5000 -1.0000 n 1.0000 0.0000 0.0000 turns 1 f 100.0000\n"
              "coolant mist\n"
              "coolant flood\n"  // M7 + M8 shows as flood; M7 off leaves flood: no change
              "dwell 0.5000\n"
              "workoffset 7\n"
              "stop optional\n"
              "feedmode inverseTime\n");
}

TEST(Rs274Trace, UnknownCallsAndGarbageAreErrorsWithTheLine)
{
    auto unknown = readRs274Trace("    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n    2 N..... NURBS_FEED(1, 2)\n");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().line, 2);
    EXPECT_NE(unknown.error().message.find("NURBS_FEED"), std::string::npos);
    auto garbage = readRs274Trace("Radius to end of arc differs from radius to start\n");
    ASSERT_FALSE(garbage.ok());
    EXPECT_EQ(garbage.error().line, 1);
    auto malformed = readRs274Trace("    1 N..... STRAIGHT_FEED(1.0, x, 3.0)\n");
    EXPECT_FALSE(malformed.ok());
}

TEST(MotionCompare, AcceptsRoundingAndArcPiecesButNotMore)
{
    Toolpath expected;
    expected.add(Rapid{{10, 0, 0}});
    expected.add(Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, -1}, false, 1, 300});  // two turns about -Z: clockwise
    Toolpath actual;
    actual.add(Rapid{{10, 0, 0.0004}});
    actual.add(Arc{{10, 0, -1}, {0.0005, -0.0005, 0}, {0, 0, 1}, true, 0, 300});
    actual.add(Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, 1}, true, 0, 300});
    EXPECT_FALSE(compareMotion(expected, actual));

    Toolpath oneTurnShort;
    oneTurnShort.add(Rapid{{10, 0, 0}});
    oneTurnShort.add(Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, 1}, true, 0, 300});
    const auto shortArc = compareMotion(expected, oneTurnShort);
    ASSERT_TRUE(shortArc);
    EXPECT_NE(shortArc->find("ends inside"), std::string::npos) << *shortArc;

    Toolpath wrongDirection;
    wrongDirection.add(Rapid{{10, 0, 0}});
    wrongDirection.add(Arc{{10, 0, -1}, {0, 0, 0}, {0, 0, 1}, false, 0, 300});
    const auto direction = compareMotion(expected, wrongDirection);
    ASSERT_TRUE(direction);
    EXPECT_NE(direction->find("plane or direction"), std::string::npos) << *direction;

    Toolpath offByAMicron;
    offByAMicron.add(Rapid{{10.001, 0, 0}});
    EXPECT_TRUE(compareMotion(Toolpath{}, offByAMicron));  // more motion than expected
    Toolpath rapidOnly;
    rapidOnly.add(Rapid{{10, 0, 0}});
    const auto endPoint = compareMotion(rapidOnly, offByAMicron);
    ASSERT_TRUE(endPoint);
    EXPECT_NE(endPoint->find("rapid end point"), std::string::npos) << *endPoint;
}

TEST(LinuxCncModel, PeckDrillingFollowsTheReference)
{
    // G83 R2 Q2 Z-5 from Z20, G98: LinuxCNC 2.9 pecks to 0, -2, -4, backs off 0.254 mm above the
    // last depth after each retract to R, and leaves from the bottom to the start Z.
    Toolpath cl;
    cl.add(Rapid{{0, 0, 20}});
    cl.add(Cycle{CycleKind::Peck, 20, 2, 0, -5, 2, 0, 100, {{10, 10, 0}}});
    std::string trace = traceOf(expectedMotion(cl));
    EXPECT_EQ(trace, "rapid 0.0000 0.0000 20.0000\n"
                     "rapid 10.0000 10.0000 20.0000\n"
                     "rapid 10.0000 10.0000 2.0000\n"
                     "linear 10.0000 10.0000 0.0000 f 100.0000\n"
                     "rapid 10.0000 10.0000 2.0000\n"
                     "rapid 10.0000 10.0000 0.2540\n"
                     "linear 10.0000 10.0000 -2.0000 f 100.0000\n"
                     "rapid 10.0000 10.0000 2.0000\n"
                     "rapid 10.0000 10.0000 -1.7460\n"
                     "linear 10.0000 10.0000 -4.0000 f 100.0000\n"
                     "rapid 10.0000 10.0000 2.0000\n"
                     "rapid 10.0000 10.0000 -3.7460\n"
                     "linear 10.0000 10.0000 -5.0000 f 100.0000\n"
                     "rapid 10.0000 10.0000 20.0000\n");
}

}  // namespace
}  // namespace camwb::external::test
