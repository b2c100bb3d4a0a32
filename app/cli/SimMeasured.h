// camwb-cli sim --measured and --analysis: a recorded trace beside the program, and seed 003's
// analysis of a trace, as parts of the JSON report.
#pragma once

#include "base/Result.h"
#include "kinematics/Machine.h"
#include "sim/Moves.h"
#include "sim/PathAnalysis.h"

#include <nlohmann/json.hpp>

#include <string>

namespace camwb::cli {

// The trace at `path` (seed 003's column order) on `machine`'s chain against `program`:
// {file, samples, seconds, maxFollowingDeviation {mm, timeSeconds}, maxDistanceToProgram {...},
// reversals {axis: [times]}, maxTipFeedMmPerMin}. An unreadable trace is an error naming its line.
// Seed 003's analysis of a trace on the workpiece (simulated or measured): {reversals {axis:
// [times]}, maxTipFeedMmPerMin}; the rotaries are the chain's, for a five-axis chain.
nlohmann::json analysisReport(const sim::Trace& trace, const kinematics::KinematicChain& chain);

base::Result<nlohmann::json> measuredReport(const std::string& path, const kinematics::Machine& machine,
                                            const sim::MoveList& program, double spindleFaceToTipMm);

}  // namespace camwb::cli
