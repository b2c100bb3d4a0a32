// The simulator dock's view of the sim module's results: the seed-003 analysis of the sampled
// motion as named quantities per sample (what the path can be coloured by and the chart shows),
// and a tool's shape as revolved outlines to draw. Plain C++; the numbers are sim's.
#pragma once

#include "gui/sim/RevolvedPart.h"
#include "gui/sim/SimRun.h"
#include "sim/MotionPlan.h"

#include <atomic>
#include <optional>
#include <vector>

namespace camwb::sim {
class ToolShape;
}

namespace camwb::gui {

// Samples the plan (3 ms, coarser for very long programs) and analyses it; nullopt if cancelled.
std::optional<SimAnalysis> analyseMotion(const sim::MoveList& moves, const sim::MotionPlan& plan,
                                         const kinematics::Machine& machine, const std::atomic<bool>* cancel);

// Cutter, shank and holder of `shape`, each an outline from the axis round and back to it.
std::vector<RevolvedPart> revolvedParts(const sim::ToolShape& shape);

}  // namespace camwb::gui
