// How the tool gets down to a level at the start of a cut: a helix beside the cut start (its
// circle inside the tool-centre region, then a short feed to the start), a ramp along the cut
// itself, or a plunge. Planned once in 2D per cut, written at every level.
#pragma once

#include "geom/RegionIndex.h"
#include "ops/ContourOp.h"  // EntryKind
#include "ops/pocket/PathWriter.h"

#include <string>
#include <vector>

namespace camwb::ops::pocket {

struct EntrySettings {
    EntryKind kind = EntryKind::Helix;
    double helixRadius = 0;
    double helixPitch = 1;
    double rampAngleDeg = 3;
    bool ccw = true;  // helix direction (climb: counter-clockwise, like the outer walls)
    double toleranceMm = 0.01;
    Feed rampFeed, plungeFeed, cuttingFeed;  // Entry, Plunge and Cutting moves
};

// How a pocket asks to enter, as the 2.5D and the 3D pocket's parameters both give it.
struct EntryRequest {
    EntryKind kind = EntryKind::Helix;
    double helixDiameterMm = 0;  // 0 = 90 % of the tool diameter
    double helixPitchMm = 1;
    double rampAngleDeg = 3;
    bool climb = true;
    double toleranceMm = 0.01;
};
template <class PocketParameters> EntryRequest entryRequest(const PocketParameters& p)
{
    return {p.entry, p.helixDiameterMm, p.helixPitchMm, p.rampAngleDeg, p.climb, p.toleranceMm};
}

// The checks both pockets make of their entry ("pocket \"P\": helix pitch must be positive, ..."):
// the ramp angle, a plunge with a tool that does not cut at its centre, the helix's size and pitch.
base::Status checkEntry(const std::string& what, const EntryRequest& request, const ToolController& tc);
// The settings the planner and the writer use: the helix radius (the default when none is asked),
// pitch, ramp angle, direction (climb: counter-clockwise) and the tool controller's feeds.
EntrySettings entrySettings(const EntryRequest& request, const ToolController& tc);

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
