// One part of a tool as the simulator draws it (cutter, shank or holder): an outline revolved
// about the tool axis. Plain data from the tool's shape (sim::ToolShape), for the 3D overlay.
#pragma once

#include <utility>
#include <vector>

namespace camwb::gui {

struct RevolvedPart {
    std::vector<std::pair<double, double>> profile;  // (radius, height above the tip), mm, tip first
    float rgb[3]{0.7f, 0.7f, 0.7f};
};

}  // namespace camwb::gui
