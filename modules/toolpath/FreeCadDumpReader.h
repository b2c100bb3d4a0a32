// Reader of FreeCAD path command dumps (the output of FreeCAD's dumper_post, seed-004 §2.9) into
// CL records. readFreeCadDump() in ClImport.h is its entry point; this header documents what it
// accepts and what each command becomes.
//
// Format: "Command <Name> [ K:v K:v ... ]" per Path.Command (keys single letters, values numbers
// as Python prints them; the list may wrap onto following lines until its ']'), "Command (text)
// [ ]" for comments, and the dumper's own "(...)" lines outside Command: "(Path: <label>)" before
// each object, header remarks (which may wrap until their ')').
//
// Units: lengths are mm; feeds F are mm/s (FreeCAD's internal unit) and become mm/min (x60, so
// F:3.3333 -> 199.998). X, Y, Z are absolute and modal (missing ones keep their value).
//
// Commands and the records they give:
//  (Path: label)      closes the open section and opens SectionBegin{label}; other "(...)" lines
//                     and Command (text) [ ] -> Comment, except "Command (label) [ ]" right after
//                     its "(Path: label)": FreeCAD repeats each object's label there, and the
//                     section already carries it.
//  G0/G00, G1/G01     -> Rapid, Linear. F on a G0 is not a feed (FreeCAD writes F:0 there) and is
//                     ignored; a G1 without F keeps the last feed. A move gives only the axes the
//                     command names (AxisMask); the others stay where they are, so FreeCAD's usual
//                     first move "G0 Z<clearance>" is a retract in Z alone, whatever X and Y are.
//  G2/G3              -> Arc (G2 clockwise) with the centre start + (I,J,K) (incremental; the part
//                     along the plane normal is ignored; missing I/J/K are 0), in the plane of
//                     G17 (XY, normal +Z, the default), G18 (ZX, normal +Y: seen from +Y, as ISO
//                     defines G18) or G19 (YZ, normal +X); a helix when the axis along the normal moves;
//                     P = number of turns (turns = P - 1). Start and end radii that differ by more
//                     than the dump's rounding (5 significant digits) are warned about. R-form
//                     arcs are Errors (FreeCAD writes I, J, K).
//  G81/G82/G83/G73/G84/G85 X Y Z R Q P F -> Cycle Drill/DrillDwell/Peck/ChipBreak/Tap/Bore:
//                     consecutive holes with equal parameters form one Cycle; Z = bottomZ, R =
//                     retractZ and, since the dump does not carry the hole top, topZ = R (holes
//                     at (X, Y, R)); Q = peck (G83/G73, required), P = dwell in seconds (G82,
//                     required; on the others a warning); Z, R, Q, P are modal until G80; F sets
//                     the feed as on a G1; clearanceZ = the tool Z before the run; G98/G99 set
//                     returnToClearance (G98 is the default). A Cycle carries the line of its
//                     first hole; any other record between two holes ends the run. G80 ends the
//                     cycle mode.
//  G4 P               -> Dwell{P seconds}.  G17/G18/G19 select the arc plane.  G21, G90 accepted;
//                     G20 (inch) and G91 (incremental) are Errors at the command.
//  G40/G41/G42        -> CutterComp Off/Left/Right.   G54..G59 -> WorkOffset 1..6.
//  M0/M1 -> ProgramStop (M1 optional); M3/M4 [S] -> Spindle (S, or the last speed); M5 -> Spindle
//  {0}; M6 T -> ToolChange{T} (the dump has no tool geometry); M7/M8/M9 -> Coolant Mist/Flood/Off;
//  M2/M30 are accepted without a record (the post writes the program end).
//  A/B/C on a motion are Errors (rotary axes need the machine's kinematics); other commands, a
//  Command with no name and a G0 without X, Y or Z are warnings with their line and column.
#pragma once

#include "toolpath/ClBuilder.h"
#include "toolpath/FreeCadDumpScanner.h"
#include "toolpath/KnownPosition.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

class FreeCadDumpReader {
public:
    FreeCadDumpReader(base::LineReader& lines, std::string fileName);
    base::Result<ClImport> read();

private:
    base::Status entry(const DumpEntry& e);
    base::Status gCode(const DumpEntry& e, int code);
    base::Status mCode(const DumpEntry& e, int code);
    base::Status move(const DumpEntry& e, bool rapid);
    base::Status arc(const DumpEntry& e, bool clockwise);
    base::Status hole(const DumpEntry& e, CycleKind kind);
    base::Status noRotaryAxes(const DumpEntry& e) const;
    // The target of a motion: the axes it gives (`given`), the others from the current position
    // where known (0 where not: never read).
    Vec3 target(const DumpEntry& e, AxisMask& given) const;
    std::optional<double> feedOf(const DumpEntry& e);
    void emit(Record record, int line);
    void flushCycleRun();
    void warnNoFeed(int line);

    struct CycleRun {
        Cycle cycle;
        int line = 0;
    };

    base::LineReader& m_lines;
    ClBuilder m_out;
    FreeCadDumpScanner m_scanner;
    DumpEntry m_entry;  // the entry being read, its storage reused for the next
    // The label of the section the previous entry opened ("(Path: label)"), while nothing else
    // came after it: FreeCAD repeats it as a comment command, which is not a comment of its own.
    std::optional<std::string> m_justOpened;
    KnownPosition m_position;
    Vec3 m_planeNormal{0, 0, 1};
    double m_feed = 0;
    bool m_feedSet = false;
    bool m_warnedNoFeed = false;
    Spindle m_spindle{0, true};
    bool m_spindleSet = false;
    bool m_returnToClearance = true;
    bool m_cycleMode = false;
    std::optional<double> m_cycleZ, m_cycleR, m_cycleQ, m_cycleP;
    std::optional<CycleRun> m_run;
};

}  // namespace camwb::toolpath
