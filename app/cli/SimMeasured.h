// camwb-cli sim --measured: a recorded trace beside the program, as a part of the JSON report.
#pragma once

#include "base/Result.h"
#include "kinematics/Machine.h"
#include "sim/Moves.h"

#include <nlohmann/json.hpp>

#include <string>

namespace camwb::cli {

// The trace at `path` (seed 003's column order) on `machine`'s chain against `program`:
// {file, samples, seconds, maxFollowingDeviation {mm, timeSeconds}, maxDistanceToProgram {...},
// reversals {axis: [times]}, maxTipFeedMmPerMin}. An unreadable trace is an error naming its line.
base::Result<nlohmann::json> measuredReport(const std::string& path, const kinematics::Machine& machine,
                                            const sim::MoveList& program, double spindleFaceToTipMm);

}  // namespace camwb::cli
