// Statistics of a toolpath, CL or interpreted NC (the editor's Program Information, the machining
// time a post writes): extents per axis for rapids, cutting moves and both; rapid and feed path
// lengths; a machining time estimate from the programmed feeds (per minute, per revolution with
// the spindle speed, inverse time), rapids at one rate, dwells, canned cycles expanded hole by
// hole; and the same per tool. The one time estimate: what shows it must not compute its own.
#pragma once

#include "base/Vec.h"
#include "toolpath/Toolpath.h"

#include <optional>
#include <vector>

namespace camwb::toolpath {

// Axis-aligned box of what was visited; empty until a point is added.
using Extents = base::Box3;

struct MotionTotals {
    Extents rapidExtents;    // end points of rapids (and the start points they leave from)
    Extents cuttingExtents;  // feed moves, arcs with their bulges, cycle holes down to the bottom
    Extents allExtents;
    double rapidLengthMm = 0;
    double feedLengthMm = 0;
    double rapidSeconds = 0;
    double feedSeconds = 0;
    double dwellSeconds = 0;
    double totalSeconds() const { return rapidSeconds + feedSeconds + dwellSeconds; }
};

struct ToolStats {
    int toolNumber = 0;  // 0: moves before the first tool change
    MotionTotals totals;
};

struct ProgramStats {
    MotionTotals totals;
    std::vector<ToolStats> tools;  // in order of first use
    int rapids = 0;
    int feedMoves = 0;  // linear moves and arcs, cycle moves included
    int arcs = 0;
    int cycleHoles = 0;
    int toolChanges = 0;
    int movesWithoutFeed = 0;  // feed moves at feed 0 (or per revolution with the spindle off): no time counted
    int movesLeftOut = 0;      // motions of blocks with an error (StatsOptions::recordsInError)
    double rapidMmPerMin = 0;  // the rate the estimate used
};

// The rapid rate an estimate assumes when the machine gives none.
inline constexpr double kDefaultRapidMmPerMin = 5000;

struct StatsOptions {
    // The machine's (kinematics::estimateRapidMmPerMin); <= 0: kDefaultRapidMmPerMin.
    double rapidMmPerMin = kDefaultRapidMmPerMin;
    // Where the tool is before the first move; unknown: the first move only sets the position.
    std::optional<base::Vec3> startPosition;
    // Per record, true for a block with an error (nc::recordsInError): its motion is not what the
    // program means, so it only moves the position, adding no extents, length or time.
    const std::vector<bool>* recordsInError = nullptr;
};

ProgramStats programStats(const Toolpath& program, const StatsOptions& options = {});

}  // namespace camwb::toolpath
