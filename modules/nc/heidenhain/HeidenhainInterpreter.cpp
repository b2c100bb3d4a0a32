// Entry point of the Heidenhain Klartext interpreter (iTNC 530 / TNC 640): parse once, then run
// the blocks with a program counter, driving the sink. Never throws: an allocation failure on
// absurd input is reported as an error.
//
// Choices where the manuals leave room or the trace cannot follow the control:
// - Radius compensation RL/RR/R0 is applied (iTNC 530 User's Manual, 5.3 "Tool compensation"):
//   the compensation value is R of the TOOL DEF (else of the tool table given with the options)
//   plus DR of the TOOL CALL; the RL/RR block ends square to the contour's first element, the
//   R0 block starts square to the last; RL/RR or R0 on a circle is an error (the TNC takes them
//   in straight-line blocks only); outside corners get a transitional arc (MP7680's default, no
//   spline), inside corners the intersection of the tool-centre paths. Turns under 0.001 rad are
//   tangent, for the rounding of written coordinates.
// - Circles lie in the plane the axes of CC name (CC X Y: XY, CC X Z: ZX, CC Y Z: YZ); CR and CT
//   in the plane of their two axes, else the last CC's. DR+ is counter-clockwise by the right-hand
//   rule about +Z, +Y, +X (the mathematically positive turn from Z to X in ZX, from Y to Z in YZ)
//   and PA counts from X, Z, Y; CP makes a helix along the plane's normal (IY in ZX, IX in YZ).
//   Outside XY a C, CR or CT that moves along the normal, and RL/RR, are errors; RND/CHF next to
//   such a circle warn and are left out. A CC with one axis keeps the last CC's plane when it
//   lies in it (else XY) and takes the other coordinate from the current position. Circles.cpp
//   cites the manual pages.
// - Cycles 200/201/202/203/205/206/207/209/240 and 1/2/17 are Cycle records (clearance =
//   Q203+Q204, retract = Q203+Q200, top = Q203, bottom = Q203+Q201); 204 and 208 become moves.
// - CYCL DEF 247 DATUM SETTING is a WorkOffset record with the preset number Q339 at once; the
//   machining cycle defined before stays the one that is called.
// - M89 stays on through a new CYCL DEF and ends with M99 or CYCL CALL (TNC 306 manual).
// - A positive depth Q201 warns and is traced below the surface; a decimal comma warns.
// - Inch programs read F in 1/10 inch/min, as the TNC does.
// - "..." elisions warn and make the position unknown (no radius check on the next circle).
// - M91/M92 positions (machine coordinates) are not traced: the axes they give become unknown, as
//   after G53 or SUPA (Retract.cpp). M140 MB MAX and PLANE ... MB MAX retract
//   up the tool axis to the end of the first linear axis' travel when the machine's kinematic
//   chain places the workpiece in its axes; otherwise they are not traced and leave the axes they
//   move unknown (Retract.cpp).
// - A/B/C words, M128 / FUNCTION TCPM (on at the block start) and M129 / FUNCTION RESET TCPM (off
//   at the block end: iTNC 530 User's Manual, M128) run through the machine's kinematic chain
//   (nc/FiveAxis.h; Rotary.cpp), without a five-axis machine they warn. M126 (until M127) turns an
//   endless axis the shorter way; angles are traced continuous (C355 -> C5: C365). F after M128
//   is the compensating moves' feed and is not traced. AXIS SPAT takes A, B, C as spatial angles
//   (about X, then Y, then Z, as PLANE SPATIAL) from 0 at each FUNCTION TCPM; REFPNT ...-CENTER
//   warns and traces X Y Z as the tip. M140 MB with the axes turned retracts along the tool axis.
// - PLANE SPATIAL / VECTOR / AXIAL / RESET and CYCL DEF 19 (the machine's axis angles, through its
//   kinematics) tilt the working plane: WorkingPlane records, the moves after them in its frame
//   (Planes.cpp); a datum shift before the tilt moves its origin, one after it shifts in it.
#include "nc/detail/Dialects.h"
#include "nc/heidenhain/Machine.h"

#include <new>

namespace camwb::nc::detail {

InterpretResult interpretHeidenhain(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    try {
        CutterCompensation compensation(sink, CompensationRules::heidenhain(), result, options.maxDiagnostics);
        heidenhain::Machine machine(options, compensation, result);
        machine.run(text);
    } catch (const std::bad_alloc&) {
        result.completed = false;
        result.diagnostics.push_back({Severity::Error, options.fileName.empty() ? "<input>" : options.fileName, 0, 0,
                                      "out of memory while interpreting the program"});
    } catch (const std::exception& e) {
        result.completed = false;
        result.diagnostics.push_back({Severity::Error, options.fileName.empty() ? "<input>" : options.fileName, 0, 0,
                                      std::string("internal error: ") + e.what()});
    }
    if (result.files.empty())
        result.files.push_back(options.fileName);
    return result;
}

}  // namespace camwb::nc::detail
