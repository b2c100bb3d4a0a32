// Compares the motion LinuxCNC read back (Rs274Trace.h) with the motion expected from the CL
// (LinuxCncModel.h) within the output precision. An expected arc may come back as several pieces
// (the post's maxArcSweep): they must share the centre, plane and direction and add up to its sweep.
#pragma once

#include "toolpath/Toolpath.h"

#include <optional>
#include <string>

namespace camwb::external {

// Per axis: every written coordinate and centre offset is rounded to 3 decimals (0.0005), and the
// post measures centre offsets from the written start, so centres carry one rounding only.
struct MotionTolerance {
    double axisMm = 0.0005 + 1e-6;
    double feedRelative = 1e-3;         // feeds are written with 3 decimals, trimmed
    double inverseTimeRelative = 2e-3;  // LinuxCNC derives mm/min from written (rounded) lengths
    double secondsAbs = 0.0005 + 1e-6;
};

// Empty when `actual` does the same as `expected`; otherwise the first difference, naming the
// record index on both sides and their trace lines. Comments and zero-length moves are skipped.
std::optional<std::string> compareMotion(const toolpath::Toolpath& expected, const toolpath::Toolpath& actual,
                                         const MotionTolerance& tolerance = {});

}  // namespace camwb::external
