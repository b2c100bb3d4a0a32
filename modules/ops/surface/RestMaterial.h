// Rest machining from the simulator's stock (a z-map cut by the operations before): where a
// level still has material to cut, and how much of a new toolpath cuts air in that stock.
#pragma once

#include "geom/Region.h"
#include "ops/OpCommon.h"
#include "ops/pocket/CutPath.h"
#include "sim/HeightField.h"

#include <vector>

namespace camwb::ops::surface {

// The part of `toolCentre` within `reach` (the tool radius) of a column whose top is above
// `level` + `tolerance` and that the tool can reach from `toolCentre` at all (not the part's own
// walls): where the tool centre must go to cut what is left at this level.
std::vector<geom::Region> restRegion(const sim::HeightField& rest, double level, double reach,
                                     const std::vector<geom::Region>& toolCentre, double tolerance);

// The pattern's cuts at `level` that still remove material from `stock` (what the operations
// before and this one's earlier cuts left), each cut into it as it is kept; a cut that would
// remove less than one column's area times the tolerance is dropped: a ring of a rest pattern
// that only runs through air the ring before it cleared. Dropping such a cut changes nothing the
// tool leaves behind.
std::vector<pocket::Cut> cutsThatCut(std::vector<pocket::Cut> cuts, sim::HeightField& stock, double level,
                                     const toolpath::Tool& tool, double tolerance);

struct StockFigures {
    double cuttingMm = 0;  // feed moves that removed material
    double airMm = 0;      // feed moves that removed nothing
    double removedMm3 = 0;
};

// Runs `section` (an operation's SectionBegin..SectionEnd) with `tool` through a copy of `rest`.
StockFigures simulateOn(const sim::HeightField& rest, const toolpath::Toolpath& section, const toolpath::Tool& tool);

}  // namespace camwb::ops::surface
