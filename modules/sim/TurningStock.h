// Stock removal for turning and grooving in the XZ half-plane: the stock and the design contour
// are revolved profiles (regions of the half-plane, X = radius), the tool is a 2D insert, and each
// move removes what the insert sweeps. A lathe cuts a body of revolution, so this 2D model is
// exact where the tool is a plane insert on the spindle's centre height: no dexels are needed.
#pragma once

#include "geom/Region.h"

#include <vector>

namespace camwb::sim {

using base::Vec2;

// A region of the half-plane in the plane's coordinates: Vec2::x is Z (along the spindle),
// Vec2::y is X as a radius (>= 0), so drawings look like the lathe drawings (Z right, X up).
using TurningRegion = std::vector<geom::Region>;

inline Vec2 turningPoint(double radius, double z) { return {z, radius}; }

// A grooving/turning insert. The reference (programmed) point is the left (-Z) corner of the
// cutting edge, as the seed-001 program programs it: the edge spans Z .. Z + width at X, the body
// rises towards +X. With a corner radius the corners are rounded and the reference point stays
// the sharp corner the radius rounds (no nose radius compensation is assumed).
struct Insert {
    double widthMm = 3;
    // Height of the body above the edge (blade included). 0: taller than the stock, so the body
    // is a strip and anything the blade would pass through counts (a grooving blade is as tall
    // as the groove is deep).
    double lengthMm = 0;
    double cornerRadiusMm = 0;
};

// The insert placed with its reference point at `at`, counter-clockwise; `length` replaces
// Insert::lengthMm (already resolved), corners chorded within `tolerance` inside the arc.
std::vector<Vec2> insertOutline(const Insert& insert, Vec2 at, double length, double tolerance);

// Counter-clockwise convex hull (Andrew's monotone chain); collinear points are dropped.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

// What one move did.
struct TurningCut {
    double removedMm2 = 0;  // area of stock removed
    double depthMm = 0;     // deepest the removed part reached below the stock's surface (radially)
    Vec2 depthAt;           // where (Z, X)
    double gougeMm = 0;     // deepest the removed material reached below the design contour (radially)
    Vec2 gougeAt;
};

// The stock being cut, and the design contour it is compared with (the part, or the part plus the
// finishing allowances when roughing is checked: the region that must stay).
class TurningStock {
public:
    TurningStock(TurningRegion stock, TurningRegion design, double toleranceMm = 1e-4);

    // Removes what the insert sweeps going straight from `from` to `to`. The sweep of a convex
    // insert along a segment is the convex hull of its two placements (exact for the rectangle).
    TurningCut cut(Vec2 from, Vec2 to, const Insert& insert);

    const TurningRegion& stock() const { return m_stock; }
    const TurningRegion& design() const { return m_design; }
    double toleranceMm() const { return m_tolerance; }

private:
    TurningRegion m_stock;
    TurningRegion m_design;
    double m_tolerance;
    double m_top;  // highest X of stock and design: where a strip insert ends
};

// The deepest point of `cut` below the top of `material`, measured along +X at the same Z: for
// each chord of `cut` on a vertical line, its lower end against the top of the chord of
// `material` holding it. The depth is linear in Z between the loops' vertices, so the lines just
// either side of every vertex find the maximum (vertical edges are everywhere here). Returns 0
// when `cut` is empty; `at` gets the deepest point.
double radialDepth(const TurningRegion& cut, const TurningRegion& material, double tolerance, Vec2& at);

}  // namespace camwb::sim
