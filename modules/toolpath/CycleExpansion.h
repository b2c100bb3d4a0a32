// Canned cycles as the moves a control makes for each hole (as LinuxCNC's G81-G89 do): the
// fallback for posts that do not write a cycle natively, and what the backplot draws. One
// definition, so the NC of an expanding post and the 3D view agree.
#pragma once

#include "toolpath/ClRecords.h"
#include "toolpath/KnownPosition.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::toolpath {

// Re-entry gap above the previous depth when pecking, and the lift that breaks a chip (mm).
inline constexpr double kPeckClearanceMm = 0.5;

// Why `cycle` cannot be expanded: more pecks in a hole than base::kMaxRepeats (a slip such as
// Q0.0000001 for Q1, which a control would spend hours on); nothing when it can.
std::optional<std::string> tooManyPecks(const Cycle& cycle);

// The spindle state a tapping cycle reverses and restores.
struct SpindleState {
    double rpm = 0;
    bool clockwise = true;
};

// Height the tool returns to after each hole: clearance (G98 style, never below the R plane) or R.
double cycleReturnZ(const Cycle& cycle);

// The records for one hole, starting with the tool at `from`: up to the R plane if below it,
// rapid over the hole, rapid down to R, the drilling motion of the cycle's kind (pecks measured
// from the hole top, dwell at the bottom), then back to cycleReturnZ(). Ends over the hole.
// A cycle with too many pecks (tooManyPecks) makes no motion into the hole, whoever draws or
// counts it: the interpreters, the operations and the posts report it as an error.
// Feed moves into the hole are Plunge, those back out (tapping, boring) Exit, all at the cycle's
// own feed: in a drilling section that is its cutting feed, not its plunge feed, so a post that
// writes feeds as parameters compares the value before it names one.
std::vector<Record> expandCycleHole(const Cycle& cycle, const Vec3& hole, const Vec3& from,
                                    const SpindleState& spindle);
// The same from a position of which only Z need be known (a CL that retracted in Z before its
// first X/Y): the climb to the R plane then moves Z alone. A caller with Z unknown must refuse
// the cycle: nothing says how high the tool is before it travels over the hole.
std::vector<Record> expandCycleHole(const Cycle& cycle, const Vec3& hole, const KnownPosition& from,
                                    const SpindleState& spindle);

}  // namespace camwb::toolpath
