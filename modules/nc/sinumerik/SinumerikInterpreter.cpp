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
//   trace stays in the programmed frame. TRAORI and CYCLE800 are recognised with a warning until
//   the five-axis machine model exists; A/B/C are not traced.
// - DIAMON halves X, incremental X and I=AC(..); incremental I/K stay radii.
// - A block wrapped over lines the way printed listings do (operator repeated at the wrap) is
//   joined with a warning; the control itself needs one block per line.
// - Operator priorities are the control's: comparisons bind loosest, so write (a>b) AND (c<d).
// - Runtime errors leave the block out and are reported once per place; parse errors leave the
//   block out; a runaway (more than options.maxBlocks blocks) names the loop and stops.
#include "nc/detail/Dialects.h"
#include "nc/sinumerik/Machine.h"

namespace camwb::nc::detail {

InterpretResult interpretSinumerik(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink)
{
    InterpretResult result;
    sinumerik::Machine machine(options, sink, result);
    machine.run(text);
    return result;
}

}  // namespace camwb::nc::detail
