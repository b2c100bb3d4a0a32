// The planned motion sampled at a fixed time step (seed 003's 3 ms by default): where the tool
// and the machine's axes are at each instant, for playback, the path analysis and a trace file.
// The streaming form holds one sample at a time, so a 1M-move program costs memory only for the
// plan; the cost grows with the moves and the samples (time / step), nothing else.
#pragma once

#include "kinematics/Machine.h"
#include "sim/MotionPlan.h"
#include "sim/Moves.h"
#include "sim/PathAnalysis.h"

#include <functional>

namespace camwb::sim {

struct SampleOptions {
    double stepSeconds = 0.003;
};

struct MotionSample {
    TraceSample at;           // time, machine axes, tip in the workpiece frame
    Vec3 toolAxis{0, 0, 1};   // workpiece frame, tip towards spindle
    std::size_t move = 0;     // index in the MoveList
    double feedMmPerMin = 0;  // the tip's planned speed on the workpiece (0 while standing)
};

// Calls `visit` for the samples at 0, step, 2·step, ... up to the plan's end, in order; `visit`
// returns false to stop early (cancel). Rotaries are filled for a five-axis chain only.
void sampleMotion(const MoveList& moves, const MotionPlan& plan, const kinematics::Machine& machine,
                  const std::function<bool(const MotionSample&)>& visit, const SampleOptions& options = {});

// The same samples in a vector (for short programs and tests).
std::vector<MotionSample> sampleMotion(const MoveList& moves, const MotionPlan& plan,
                                       const kinematics::Machine& machine, const SampleOptions& options = {});

}  // namespace camwb::sim
