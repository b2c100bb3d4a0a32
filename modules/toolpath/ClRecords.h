// The typed cutter-location (CL) records: the one vocabulary between operations, importers,
// posts, NC interpreters and the simulator. Units: mm, mm/min, degrees, rpm, seconds.
#pragma once

#include "base/Vec.h"

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace camwb::toolpath {

using base::Vec3;

enum class CutterCompSide { Off, Left, Right };
enum class CoolantMode { Off, Flood, Mist, ThroughTool };
enum class FeedMode { PerMinute, PerRevolution, InverseTime };
enum class CycleKind { Drill, DrillDwell, Peck, ChipBreak, Tap, Bore };
// Which of its section's feeds (SectionBegin::feeds) a feed move uses, so that a post can write a
// parametric feed (Q601 cutting, Q603 plunge, ...) without guessing from values. An operation
// sets a kind only where the move's feed is exactly its section's feed of that kind. Unspecified:
// nobody said (NC read back, APT, FreeCAD dumps, hand-written traces). One byte: it sits in the
// records' padding.
enum class FeedKind : unsigned char { Unspecified, Cutting, Plunge, Entry, Exit, Finishing };

// Full tool geometry, so a post or the simulator never has to look the tool up elsewhere.
// Many callers give the first eight fields in this order; after them the order packs the record
// (a ToolChange is the largest record, so its padding is every record's).
struct Tool {
    int number = 1;
    std::string name;
    std::string kind = "flat";  // flat, ball, bull, drill, chamfer, groove (diameterMm = the insert's width)
    double diameterMm = 0;
    double cornerRadiusMm = 0;
    double fluteLengthMm = 0;
    double lengthMm = 0;
    int flutes = 2;
    bool centreCutting = true;  // false: must not plunge straight down (pockets ramp or helix instead)
    double pointAngleDeg = 0;   // drills (118, 135, ...) and chamfer mills: included tip angle; 0 = flat
    std::string holder{};       // the tool holder's name ("SK40 ER32"); empty = none given
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
    Linear(Vec3 target, double feed = 0, AxisMask given = {}, FeedKind kind = FeedKind::Unspecified) :
        to(target),
        feedMmPerMin(feed),
        axes(given),
        feedKind(kind)
    {
    }
    Vec3 to;
    double feedMmPerMin = 0;
    AxisMask axes;
    FeedKind feedKind = FeedKind::Unspecified;
};

// Circular move from the current position. When `to` leaves the arc's plane the arc is a helix.
// `turns` counts extra full revolutions (0 = less than one turn). A constructor keeps the
// positional Arc{to, center, normal, clockwise, turns, feed} while the kind sits in the padding
// after `clockwise`.
struct Arc {
    Arc() = default;
    Arc(Vec3 end, Vec3 centre, Vec3 planeNormal, bool cw, int extraTurns, double feed,
        FeedKind kind = FeedKind::Unspecified) :
        to(end),
        center(centre),
        normal(planeNormal),
        clockwise(cw),
        feedKind(kind),
        turns(extraTurns),
        feedMmPerMin(feed)
    {
    }
    Vec3 to;
    Vec3 center;
    Vec3 normal{0, 0, 1};
    bool clockwise = false;  // seen looking against the normal (from +Z down for G17)
    FeedKind feedKind = FeedKind::Unspecified;
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

// Machine rotary axis positions in degrees, where the source knows them: NC read back through a
// machine's kinematics, or a post that solved them. CL from operations and APT leaves them
// unknown (the machine is the post's business).
struct RotaryAxes {
    static constexpr unsigned char kA = 1, kB = 2, kC = 4;
    double aDeg = 0, bDeg = 0, cDeg = 0;
    unsigned char known = 0;  // kA | kB | kC

    bool has(unsigned char axis) const { return (known & axis) != 0; }

    // The bit of machine axis "A", "B" or "C" (a kinematic chain's joint names); 0 for any other.
    static unsigned char bitOf(const std::string& axis)
    {
        return axis == "A" ? kA : axis == "B" ? kB : axis == "C" ? kC : 0;
    }
    // The position of machine axis `axis`, where it is known.
    std::optional<double> of(const std::string& axis) const
    {
        const unsigned char bit = bitOf(axis);
        if (bit == 0 || !has(bit))
            return std::nullopt;
        return bit == kA ? aDeg : bit == kB ? bDeg : cDeg;
    }
    // Machine axis `axis` known at `deg`; a name other than A, B or C changes nothing.
    void set(const std::string& axis, double deg)
    {
        const unsigned char bit = bitOf(axis);
        if (bit == kA)
            aDeg = deg;
        else if (bit == kB)
            bDeg = deg;
        else if (bit == kC)
            cDeg = deg;
        known |= bit;
    }
};

// Five-axis move: tool tip and unit tool vector (from tip towards spindle), both in the workpiece
// frame. feed 0 = rapid. The tip goes straight to `tip` (a CL's promise, a control's tool-tip
// control) unless `jointInterpolated`: NC read back without TCPM, where the machine moves its
// linear and rotary axes together from `machine` to `machine`, and the tip curves between.
struct ToolAxisMove {
    Vec3 tip;
    Vec3 axis{0, 0, 1};
    double feedMmPerMin = 0;
    RotaryAxes machine{};
    bool jointInterpolated = false;
};

// 3+2 machining: the tilted working plane the records after it are in, until the next one. Its
// frame in the workpiece frame: origin and unit, perpendicular x and z axes (z is the tool axis).
// Moves, arcs and cycles after it give their coordinates in this frame, as a control's PLANE
// SPATIAL or CYCLE800 has them, so 2.5D operations compute as they do flat; the default (the
// workpiece frame itself) ends the tilt.
struct WorkingPlane {
    Vec3 origin;
    Vec3 xAxis{1, 0, 0};
    Vec3 zAxis{0, 0, 1};

    Vec3 yAxis() const { return zAxis.cross(xAxis); }
    bool tilted() const { return !(origin == Vec3{} && xAxis == Vec3{1, 0, 0} && zAxis == Vec3{0, 0, 1}); }
    // A direction given in this frame, in the workpiece frame; a point likewise; and back.
    Vec3 direction(const Vec3& v) const { return xAxis * v.x + yAxis() * v.y + zAxis * v.z; }
    Vec3 toWorkpiece(const Vec3& p) const { return origin + direction(p); }
    Vec3 toLocal(const Vec3& p) const
    {
        const Vec3 d = p - origin;
        return {d.dot(xAxis), d.dot(yAxis()), d.dot(zAxis)};
    }
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

// The feeds an operation uses, by kind (0: a kind it does not use).
struct SectionFeeds {
    double cuttingMmPerMin = 0;
    double plungeMmPerMin = 0;
    double entryMmPerMin = 0;
    double exitMmPerMin = 0;
    double finishingMmPerMin = 0;

    // The feed of `kind`; 0 for Unspecified.
    double of(FeedKind kind) const
    {
        switch (kind) {
        case FeedKind::Cutting:
            return cuttingMmPerMin;
        case FeedKind::Plunge:
            return plungeMmPerMin;
        case FeedKind::Entry:
            return entryMmPerMin;
        case FeedKind::Exit:
            return exitMmPerMin;
        case FeedKind::Finishing:
            return finishingMmPerMin;
        case FeedKind::Unspecified:
            break;
        }
        return 0;
    }
};

struct SectionBegin {
    std::string operationName;
    std::string strategy;  // "profile", "pocket", ...
    int toolNumber = 0;
    SectionFeeds feeds;
    // The operation's own values of post properties (name, value as text), over the job's for
    // this section: e.g. tcpm=off for one five-axis operation. The post must allow each per
    // operation; the kernel checks that and the value.
    std::vector<std::pair<std::string, std::string>> postProperties;
    // The strategy's inputs by name (the groove's R0..R11, R30), for a post that writes the
    // strategy as the control's own program instead of its moves; the moves are always there too.
    std::vector<std::pair<std::string, double>> strategyParameters;
};
struct SectionEnd {};
// The tool went somewhere on these axes that the program does not say: a retract to the end of the
// travel (M140 MB MAX) or a move in machine coordinates (G53, SUPA, M91/M92, G28, G74/G75) that no
// machine file places in the workpiece frame. The axes are unknown until a move gives them again;
// nobody may draw, cut, check or post from their old values.
struct UnknownAxes {
    AxisMask axes;
};

using Record = std::variant<Rapid, Linear, Arc, ToolChange, Spindle, Coolant, FeedModeChange, WorkOffset, Dwell, Cycle,
                            ToolAxisMove, CutterComp, Comment, SectionBegin, SectionEnd, ProgramStop, PassThrough,
                            WorkingPlane, UnknownAxes>;

// The feed kind of a Linear or Arc; Unspecified for any other record.
inline FeedKind feedKindOf(const Record& record)
{
    if (const auto* l = std::get_if<Linear>(&record))
        return l->feedKind;
    if (const auto* a = std::get_if<Arc>(&record))
        return a->feedKind;
    return FeedKind::Unspecified;
}

// Where a record came from, so the GUI can link it back to its operation. -1 = unknown.
// NC interpreters set `line` (1-based) and `file` (index into their list of program files).
struct SourceRef {
    int operationIndex = -1;
    int recordIndex = -1;
    int line = -1;
    int file = 0;
};

}  // namespace camwb::toolpath
