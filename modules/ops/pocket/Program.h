// A pattern ready to be written at any level: the cuts, how each is reached (a feed at the level
// from the previous cut when the straight link stays inside the region, else retract to the safe
// height and enter again) and each entry's plan. Written once per level.
#pragma once

#include "geom/RegionIndex.h"
#include "ops/pocket/Entry.h"

#include <vector>

namespace camwb::ops::pocket {

struct Program {
    std::vector<Cut> cuts;
    std::vector<EntryPlan> entries;             // per cut
    std::vector<bool> linked;                   // cut i follows cut i-1 by a feed at the level
    const geom::RegionIndex* region = nullptr;  // where links may run
};

Program makeProgram(std::vector<Cut> cuts, const geom::RegionIndex& region, EntryPlanner& planner);

struct Clearances {
    double clearanceZ = 0, safeZ = 0;
};

// The program at `level`, material already removed down to `top` (the previous level); its cuts
// at `cutFeed` (the cutting feed, or the finishing feed for a finishing pass), links at the cutting
// feed.
void writeProgram(PathWriter& out, const Program& program, double top, double level, const Clearances& heights,
                  const EntrySettings& entry, Feed cutFeed);

}  // namespace camwb::ops::pocket
