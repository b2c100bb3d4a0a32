// The two clearing patterns of the pocket, computed once in 2D and repeated at every level:
// offset rings (successive inward offsets of the tool-centre region, cut from the walls inward,
// depth first per branch) and zig-zag lines (clipped to the tool-centre region, joined back and
// forth) followed by a wall pass. Loop direction: climb runs outer loops counter-clockwise and
// loops round islands clockwise (material on the right of travel with a clockwise spindle).
#pragma once

#include "ops/OpCommon.h"
#include "ops/pocket/CutPath.h"

#include <optional>
#include <vector>

namespace camwb::ops::pocket {

struct PatternInput {
    const std::vector<geom::Region>* toolCentre = nullptr;  // where the tool centre may go
    double stepover = 0;
    double radius = 0;  // of the tool
    bool climb = true;
    double toleranceMm = 0.01;
    double zigZagAngleDeg = 0;
};

// nullopt when cancelled. `progress` is reported in [0, 0.5].
std::optional<std::vector<Cut>> offsetPattern(const PatternInput& in, const Progress& progress);
std::optional<std::vector<Cut>> zigZagPattern(const PatternInput& in, const Progress& progress);

// Every loop of the regions once, in the milling direction, ordered nearest next from `from` and
// started at the point nearest to the previous end (from the longest side when `from` is empty).
std::vector<Cut> wallLoops(const std::vector<geom::Region>& regions, bool climb, std::optional<Vec2> from);

}  // namespace camwb::ops::pocket
