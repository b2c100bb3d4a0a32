// How the tool gets down to a level at the start of a cut: a helix beside the cut start (its
// circle inside the tool-centre region, then a short feed to the start), a ramp along the cut
// itself, or a plunge. Planned once in 2D per cut, written at every level.
#pragma once

#include "geom/RegionIndex.h"
#include "ops/ContourOp.h"  // EntryKind
#include "ops/pocket/PathWriter.h"

#include <vector>

namespace camwb::ops::pocket {

// The helix diameter a pocket asks for, or 90 % of the tool's where it asks for none (0).
inline double helixDiameterOr(double requestedMm, double toolDiameterMm)
{
    return requestedMm > 0 ? requestedMm : 0.9 * toolDiameterMm;
}

struct EntrySettings {
    EntryKind kind = EntryKind::Helix;
    double helixRadius = 0;
    double helixPitch = 1;
    double rampAngleDeg = 3;
    bool ccw = true;  // helix direction (climb: counter-clockwise, like the outer walls)
    double toleranceMm = 0.01;
    Feed rampFeed, plungeFeed, cuttingFeed;  // Entry, Plunge and Cutting moves
};

struct EntryPlan {
    EntryKind kind = EntryKind::Plunge;
    Vec2 start;  // where the tool comes down: on the helix circle, else the cut start
    Vec2 helixCentre;
};

class EntryPlanner {
public:
    EntryPlanner(const geom::RegionIndex& region, const EntrySettings& settings);

    // A helix falls back to a ramp where its circle fits nowhere near the cut start.
    EntryPlan plan(const Cut& cut);
    int helixFallbacks() const { return m_fallbacks; }

private:
    const geom::RegionIndex& m_region;
    EntrySettings m_settings;
    std::vector<geom::Region> m_helixCentres;  // where a helix centre may be
    int m_fallbacks = 0;
};

// From (plan.start, top) down to `level`, ending at (cut.start(), level).
void writeEntry(PathWriter& out, const EntryPlan& plan, const Cut& cut, double top, double level,
                const EntrySettings& settings);

}  // namespace camwb::ops::pocket
