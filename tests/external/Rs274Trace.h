// Reader of the canonical-call trace that LinuxCNC's standalone interpreter prints (`rs274 -g`):
// rebuilds what the control would do as CL records, so posted NC can be compared with the toolpath
// it came from. Lengths come back in program units (mm under G21), arcs as one Arc per ARC_FEED.
#pragma once

#include "base/Result.h"
#include "toolpath/Toolpath.h"

#include <string>
#include <string_view>
#include <vector>

namespace camwb::external {

struct Rs274Program {
    // Rapid, Linear, Arc, Dwell, Spindle, Coolant, ToolChange, WorkOffset, FeedModeChange,
    // ProgramStop and Comment records. State records appear only when the state changes; Linear
    // and Arc carry the feed rate in force (LinuxCNC turns inverse time into mm/min per move).
    // Arc centres take the start point's coordinate along the arc axis, as CL arcs do.
    toolpath::Toolpath motion;
    std::vector<double> toolLengthOffsetsMm;  // Z of each USE_TOOL_LENGTH_OFFSET after a tool change
    std::vector<std::string> messages;        // MESSAGE(...): active comments shown to the operator
    bool programEnd = false;                  // PROGRAM_END() seen (M2/M30); later calls are ignored
};

// Parses the whole trace. Unknown canonical calls and malformed lines are errors naming the line, so
// that a LinuxCNC version with new behaviour is noticed instead of silently ignored.
base::Result<Rs274Program> readRs274Trace(std::string_view trace);

}  // namespace camwb::external
