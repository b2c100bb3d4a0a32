// The typed cutter-location (CL) records: the one vocabulary between operations, importers,
// posts, NC interpreters and the simulator. Units: mm, mm/min, degrees, rpm, seconds.
#pragma once

#include "base/Vec.h"

#include <string>
#include <variant>
#include <vector>

namespace camwb::toolpath {

using base::Vec3;

enum class CutterCompSide { Off, Left, Right };
enum class CoolantMode { Off, Flood, Mist, ThroughTool };
enum class FeedMode { PerMinute, PerRevolution, InverseTime };
enum class CycleKind { Drill, DrillDwell, Peck, ChipBreak, Tap, Bore };

// Full tool geometry, so a post or the simulator never has to look the tool up elsewhere.
struct Tool {
    int number = 1;
    std::string name;
    std::string kind = "flat";  // flat, ball, bull, drill, chamfer
    double diameterMm = 0;
    double cornerRadiusMm = 0;
    double fluteLengthMm = 0;
    double lengthMm = 0;
    int flutes = 2;
    double pointAngleDeg = 0;   // drills (118, 135, ...) and chamfer mills: included tip angle; 0 = flat
    bool centreCutting = true;  // false: must not plunge straight down (pockets ramp or helix instead)
};

// The axes a straight move gives (bit 0 X, 1 Y, 2 Z). A move moves only these; the others stay
// where they are, which may be unknown: a CL that retracts with "G0 Z20" before its first X/Y
// says nothing about X and Y, and nobody may invent them. The coordinates of `to` on axes the
// move does not give mean nothing (readers leave them 0).
struct AxisMask {
    static constexpr unsigned char kX = 1, kY = 2, kZ = 4, kAll = 7;
    unsigned char bits = kAll;

    bool has(int axis) const { return (bits >> axis) & 1; }
    bool all() const { return bits == kAll; }
    bool none() const { return bits == 0; }
    bool operator==(const AxisMask&) const = default;
};

// Constructors rather than aggregates, so that the many Rapid{to} and Linear{to, feed} that give
// every axis need not spell the mask out.
struct Rapid {
    Rapid() = default;
    Rapid(Vec3 target, AxisMask given = {}) : to(target), axes(given) {}
    Vec3 to;
    AxisMask axes;
};
struct Linear {
    Linear() = default;
    Linear(Vec3 target, double feed = 0, AxisMask given = {}) : to(target), feedMmPerMin(feed), axes(given) {}
    Vec3 to;
    double feedMmPerMin = 0;
    AxisMask axes;
};

// Circular move from the current position. When `to` leaves the arc's plane the arc is a helix.
// `turns` counts extra full revolutions (0 = less than one turn).
struct Arc {
    Vec3 to;
    Vec3 center;
    Vec3 normal{0, 0, 1};
    bool clockwise = false;  // seen looking against the normal (from +Z down for G17)
    int turns = 0;
    double feedMmPerMin = 0;
};

struct ToolChange {
    Tool tool;
};
struct Spindle {
    double rpm = 0;
    bool clockwise = true;
    double surfaceSpeedMPerMin = 0;  // constant surface speed (lathe G96); rpm is then the limit, 0 = none
};                                   // rpm 0 = stop
struct Coolant {
    CoolantMode mode = CoolantMode::Off;
};
// Until the next change, the feed of Linear/Arc/Cycle records is in this mode's unit: mm/min,
// mm/rev (PerRevolution) or 1/min (InverseTime: the move takes 1/feed minutes).
struct FeedModeChange {
    FeedMode mode = FeedMode::PerMinute;
};
struct WorkOffset {
    int index = 1;
};  // 1 = first offset (G54 / datum 1)
struct Dwell {
    double seconds = 0;
};

// A canned cycle over a set of holes; `holes` are the hole top centres.
struct Cycle {
    CycleKind kind = CycleKind::Drill;
    double clearanceZ = 0;  // return plane between holes when retracting fully (G98)
    double retractZ = 0;    // R plane: where feeding starts (G99 return plane)
    double topZ = 0;        // hole top (reference plane)
    double bottomZ = 0;     // final depth
    double peckMm = 0;
    double dwellSeconds = 0;
    double feedMmPerMin = 0;
    std::vector<Vec3> holes;
    bool returnToClearance = true;  // after each hole: up to clearanceZ (G98 style), else retractZ (G99)
};

// Five-axis move: tool tip and unit tool vector (from tip towards spindle). feed 0 = rapid.
struct ToolAxisMove {
    Vec3 tip;
    Vec3 axis{0, 0, 1};
    double feedMmPerMin = 0;
};

struct CutterComp {
    CutterCompSide side = CutterCompSide::Off;
};
struct Comment {
    std::string text;
};
// Program stop: M0, or M1 when optional (the operator's optional-stop switch decides).
struct ProgramStop {
    bool optional = false;
};
// NC text the post writes as it is (APT INSERT): the CL author answers for what it does.
struct PassThrough {
    std::string text;
};

struct SectionFeeds {
    double cuttingMmPerMin = 0;
    double plungeMmPerMin = 0;
    double entryMmPerMin = 0;
    double exitMmPerMin = 0;
    double finishingMmPerMin = 0;
};

struct SectionBegin {
    std::string operationName;
    std::string strategy;  // "profile", "pocket", ...
    int toolNumber = 0;
    SectionFeeds feeds;
};
struct SectionEnd {};

using Record = std::variant<Rapid, Linear, Arc, ToolChange, Spindle, Coolant, FeedModeChange, WorkOffset, Dwell, Cycle,
                            ToolAxisMove, CutterComp, Comment, SectionBegin, SectionEnd, ProgramStop, PassThrough>;

// Where a record came from, so the GUI can link it back to its operation. -1 = unknown.
// NC interpreters set `line` (1-based) and `file` (index into their list of program files).
struct SourceRef {
    int operationIndex = -1;
    int recordIndex = -1;
    int line = -1;
    int file = 0;
};

}  // namespace camwb::toolpath
