// A measured trace as the simulator dock shows it: the CSV the control recorded (sim::MeasuredTrace,
// read by the kernel with the dock's column layout), carried onto the workpiece through the
// simulation's machine, its nominal and actual tips to draw, and the deviations per sample as
// quantities the path can be coloured by and the chart plots. Plain C++; the numbers are sim's.
#pragma once

#include "gui/sim/SimRun.h"
#include "sim/MeasuredTrace.h"

#include <string>
#include <vector>

namespace camwb::gui {

// Ids of the measured quantities (SampledQuantity::id): the distance between the actual and the
// nominal tip ("measured Δ"), and from the actual tip to the nearest programmed move, both in mm
// (short labels: the colour bar's title has little room).
inline constexpr const char* kMeasuredFollowingId = "measuredFollowing";
inline constexpr const char* kMeasuredToProgramId = "measuredToProgram";

struct MeasuredRun {
    std::string path;
    sim::MeasuredTrace trace;  // as read: carried again through a later simulation's machine
    sim::TraceColumns columns;
    double spindleFaceToTipMm = 0;
    std::vector<base::Vec3> nominalTip, actualTip;  // per sample, workpiece frame
    std::vector<SampledQuantity> quantities;        // per sample from 0, of the actual tips
};

// `trace` through `run`'s machine onto the workpiece and against its moves.
MeasuredRun carryMeasured(sim::MeasuredTrace trace, std::string path, const sim::TraceColumns& columns,
                          double spindleFaceToTipMm, const SimRun& run);

}  // namespace camwb::gui
