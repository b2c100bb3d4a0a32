// The benchmark program: a deterministic 3-axis toolpath of straight moves and arcs, the same for
// our posts and, written as a FreeCAD path dump, for FreeCAD's posts side by side.
#pragma once

#include "toolpath/Toolpath.h"

#include <cstddef>
#include <string>

namespace camwb::bench {

// `moves` motion records after a tool change and a spindle start: groups of two lines and two
// quarter arcs (radius 2 to 5 mm) waving across a 150 mm field and back, with a step down every
// 200 moves. Half the moves are arcs; none is longer than 180 degrees, so every move is one NC
// block.
toolpath::Toolpath benchProgram(std::size_t moves);

// The program as a FreeCAD path dump (feeds in mm/s, absolute X/Y/Z, incremental I/J), which
// toolpath::readFreeCadDump reads back to the same moves.
std::string asFreeCadDump(const toolpath::Toolpath& program);

// The program as APT CL source in NX's style (TOOL PATH, LOADTL, SPINDL, FEDRAT, GOTO, CIRCLE +
// GOTO for the arcs), which toolpath::readAptSource reads back to the same moves.
std::string asAptSource(const toolpath::Toolpath& program);

// The process's resident memory now (VmRSS), in KiB: what a benchmark holds, taken before and after.
long currentRssKb();

}  // namespace camwb::bench
