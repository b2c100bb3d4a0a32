// Facts about a whole program that a post wants before it writes its first line: the work
// offset, the tools for a header list, the extents.
#pragma once

#include "toolpath/Toolpath.h"

#include <vector>

namespace camwb::post {

struct ProgramSummary {
    int firstWorkOffset = 1;            // the WorkOffset before the first motion, else 1
    std::vector<toolpath::Tool> tools;  // in order of first use, each number once
    bool hasMotion = false;
    toolpath::Vec3 min, max;           // every tool tip position (arcs exactly, cycles included)
    toolpath::AxisMask extentAxes{0};  // the axes min/max hold: an axis no move gave has none
};

ProgramSummary summarizeProgram(const toolpath::Toolpath& toolpath);

}  // namespace camwb::post
