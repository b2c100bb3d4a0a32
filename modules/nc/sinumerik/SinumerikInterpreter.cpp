// Entry of the SINUMERIK 828D/840D interpreter (nc::interpret with Dialect::Sinumerik).
//
// Choices where the manuals leave room or the trace cannot follow the control:
// - G500 gives WorkOffset{0} (no settable offset); G54..G57 are 1..4, G505..G599 are 5..99.
// - M6 changes to the tool selected with T. A main program without any M6 is a turret lathe's:
//   there T changes the tool at once (seed-001 Kod 5: T=5 D1).
// - M2/M30 in a subprogram return from it like M17/RET; in the main program they end it.
// - G96 switches to revolutional feed (G95) as the control does; its Spindle record carries the
//   surface speed with LIMS as the rpm limit. G4 S<rev> under G96 counts revolutions at LIMS.
// - Under MCALL a rapid that only moves in the plane is the cycle's own positioning: the Cycle
//   record (one per hole) stands for it, as in the CL a post writes from.
// - Programmable frames (TRANS, ROT, SCALE, MIRROR, ...) are passed through with a warning: the
//   trace stays in the programmed frame. CYCLE800 swivels the working plane (Swivel.cpp).
// - TRAORI / TRAFOOF, rotary words (AC, IC, DC, ACP, ACN; G90/G91) and the tool vector A3= B3= C3=
//   run through the machine's kinematic chain (nc/FiveAxis.h; Rotary.cpp); without a five-axis
//   machine they warn. TRAORI's arguments (orientation offsets) are not read.
// - DIAMON halves X, incremental X and I=AC(..); incremental I/K stay radii.
// - A block wrapped over lines the way printed listings do (operator repeated at the wrap) is
//   joined with a warning; the control itself needs one block per line.
// - Operator priorities are the control's: comparisons bind loosest, so write (a>b) AND (c<d).
// - Runtime errors leave the block out and are reported once per place; parse errors leave the
//   block out; a runaway (more than options.maxBlocks blocks) names the loop and stops.
// - Cutter compensation (828D Function Manual W1, 18.5 "Tool radius compensation 2D"; Programming
//   Manual "Corner behavior G450/G451"): the radius of the active tool's cutting edge D is
//   $TC_DP6 + $TC_DP15 (wear) where the program sets them, else the tool table's (any D >= 1);
//   D1 is active after a tool change ($MC_CUTTING_EDGE_DEFAULT), D0 compensates nothing. NORM:
//   the selection block ends square to the contour's first element, the deselection block
//   starts square to the last; selection and deselection on an arc are errors (the control
//   selects TRC only with G0/G1). G450 (default): a transition circle about outside corners,
//   with the feed of the next block; G451: the offsets' intersection, and a transition circle
//   past 100 degrees of turn (MD20210 $MC_CUTCOM_CORNER_LIMIT's default, as read here); inside
//   corners always the intersection. KONT, DISC and a change of D while G41/G42 is on are not
//   traced (the radius is taken when compensation is selected); turns under 0.001 rad are
//   tangent, for the rounding of written coordinates.
#include "nc/detail/Dialects.h"
#include "nc/sinumerik/Machine.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    CutterCompensation compensation(sink, CompensationRules::sinumerik(), result, options.maxDiagnostics);
    sinumerik::Machine machine(options, compensation, result);
    machine.run(text);
    return result;
}

}  // namespace camwb::nc::detail
