// Waterline contours from the drop-cutter (DropCutter.h): at a tip height z, the loops round the
// places where the tool, lowered from above, stops higher than z (it would touch the model there).
// The drop heights over a square grid are taken once for all levels; each level is contoured by
// marching squares, and each crossing is placed on its grid edge by further drops to a tenth of
// the tolerance, on the free side. Between crossings a contour is straight, so its chords cut the
// convex bends of the tool-centre contour; DropContours::step sizes the grid so that no chord
// brings the tool closer into the model than half the tolerance (waterline grows the loops by
// that before cutting along them). Where a loop turns sharply (a corner where two walls meet
// within a cell) more points are found on it, so the contour reaches into the corner.
#pragma once

#include "base/Vec.h"
#include "ops/OpCommon.h"
#include "toolpath/ClRecords.h"

#include <vector>

namespace camwb::ops::surface {

class DropCutter;

class DropContours {
public:
    // The grid step for `tool` grown by `stockMm`: sqrt(2 c tolerance), c the cutter's smallest
    // radius of curvature seen from the side (a ball's radius, a bull-nose's corner, a flat end's
    // radius). A chord L across a bend of the contour enters the tool's reach by at most L^2/(8c)
    // along the contact normal (a bend of radius r is a contact seen at sin a = r / c of the way
    // round the cutter, and entering it by d sideways goes d sin a into the model), and the cell's
    // diagonal L = sqrt(2) step makes that tolerance / 2; a bump narrow enough to fall between two
    // grid points stands no higher above the level than that either. 0 for a pointed tool, whose
    // point has no such radius.
    static double step(const toolpath::Tool& tool, double stockMm, double toleranceMm);

    // Drops over [lo, hi] and two steps round it on all cores, reporting progress in [from, to];
    // complete() is false when cancelled. `ignoreMm`: material less than this above the tip does
    // not count (a floor exactly at a level is touched, not cut).
    DropContours(const DropCutter& cutter, base::Vec2 lo, base::Vec2 hi, double step, double ignoreMm,
                 double toleranceMm, const Progress& progress, double from, double to);
    bool complete() const { return m_complete; }
    double gridStep() const { return m_step; }

    // Closed loops (first point not repeated) round where the tool with its tip at z touches,
    // material on their left: counter-clockwise round material, clockwise round a hole in it.
    // Loops that reach the grid's border close along it, outside [lo, hi].
    std::vector<std::vector<base::Vec2>> loopsAt(double z) const;
    // Whether the tool with its tip at z over `xy` touches the model (by more than ignoreMm).
    bool touches(base::Vec2 xy, double z) const;

private:
    double value(int i, int j) const;  // the drop at a node; -infinity outside the grid
    // Within a step of [lo, hi]: where crossings are found exactly (farther out, loops only close).
    bool nearArea(base::Vec2 p) const;
    base::Vec2 node(int i, int j) const { return {m_x0 + i * m_step, m_y0 + j * m_step}; }
    base::Vec2 crossing(base::Vec2 touching, base::Vec2 clear, double level) const;
    std::vector<base::Vec2> refined(const std::vector<base::Vec2>& loop, double level) const;

    const DropCutter& m_cutter;
    double m_x0 = 0, m_y0 = 0, m_step = 1, m_ignore = 0, m_tol = 0.01;
    base::Vec2 m_lo, m_hi;
    int m_nx = 0, m_ny = 0;
    std::vector<double> m_z;
    bool m_complete = false;
};

}  // namespace camwb::ops::surface
