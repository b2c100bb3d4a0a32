// No uncut slivers: the area the tool can reach (the tool-centre region grown by the radius)
// minus the area the pattern sweeps is what the rings or lines left between them. Each piece
// gets a detour from the nearest point of the pattern to a point inside it (clamped into the
// tool-centre region), out and back, where that link stays inside; repeated a few times.
#pragma once

#include "ops/pocket/CutPath.h"

#include <vector>

namespace camwb::ops::pocket {

struct CleanupResult {
    int detours = 0;
    double uncutArea = 0;  // what is still left after the clean-up (mm^2)
};

// `spacing`: the pattern's stepover (how far apart neighbouring passes run).
CleanupResult addCleanup(std::vector<Cut>& cuts, const std::vector<geom::Region>& toolCentre, double radius,
                         double spacing, double tolerance);

// Polylines of the cuts (arcs sampled within the tolerance), for swept areas.
std::vector<std::vector<Vec2>> cutPolylines(const std::vector<Cut>& cuts, double tolerance);

}  // namespace camwb::ops::pocket
