// Where the machine's axes are along a simulated move: the tip and tool axis in the workpiece
// frame at a fraction of the move, and the machine pose behind them through the machine's chain.
// The motion plan (axis speed limits), the samples and the measured-trace overlay share it, so
// there is one way a move becomes machine axes.
#pragma once

#include "kinematics/KinematicChain.h"
#include "sim/Moves.h"

#include <array>
#include <vector>

namespace camwb::sim {

// The tool at fraction `u` (0..1) of `move`: the tip straight from `from` to `to`, the axis
// turned evenly between the ends (normalised linear interpolation; a control's TCP interpolation
// of the axis vector is of the same kind, it differs in how the angle is spread, not in the path).
kinematics::ToolPose toolAt(const Move& move, double u);

// The machine pose of `move` at fraction `u`. Rotary angles: interpolated between the move's
// known machine positions (what the program gave, as a control interpolates programmed angles),
// else from the inverse kinematics, the solution nearest `previousRotaryDeg` (C unwrapped to the
// nearest turn). A three-axis chain gives the linear axes only (rotary 0).
kinematics::MachinePose machinePoseAt(const kinematics::KinematicChain& chain, const Move& move, double u,
                                      const std::array<double, 2>& previousRotaryDeg, double toolLengthMm);

// A five-axis move is followed in this many pieces wherever its rotary axes are walked along a
// program (the motion plan's speed caps, the playback's machine frame): a rotary axis that turns
// fast in the middle is seen, and each piece's solution nearest the last keeps C on its turn.
inline constexpr int kRotaryPiecesPerMove = 4;

// The rotary angles (chain order) at the start of each move of `moves`, walked from 0 at the
// program's start as the motion plan walks them: what a playback that jumps into a program needs
// to ask machinePoseAt for the pose inside a move. Moves that stand keep the angles before them.
// Empty for a chain that is not five-axis.
std::vector<std::array<double, 2>> rotaryAtMoveStarts(const kinematics::KinematicChain& chain, const MoveList& moves);

// The move's known rotary angles at its start (`end` false) or end, in chain order, when the
// move carries both; false when it does not.
bool knownRotaries(const kinematics::KinematicChain& chain, const Move& move, bool end,
                   std::array<double, 2>& rotaryDeg);

}  // namespace camwb::sim
