// Revolved profiles for the turning stock: from the command line (`--stock-profile`: a rectangle
// `x0,z0,x1,z1` in radius/Z, or a file of X,Z points), and the stock and offset contour of the
// seed-001 groove built from the thesis' R-parameters, so tests and users need no drawn geometry.
#pragma once

#include "base/Result.h"
#include "sim/TurningStock.h"

#include <string>
#include <string_view>

namespace camwb::sim {

// `x0,z0,x1,z1`: the rectangle between radii x0..x1 and Z z0..z1 (either order). Errors name the
// text: not four numbers, a negative radius, no area.
base::Result<TurningRegion> parseProfileRectangle(std::string_view spec);

// Points `X,Z` (or `X Z`), one a line; blank lines and text after `;` or `#` are left out. They
// go round the half-section; where the first and last point are off the axis, the profile is
// closed along the axis (a bar's outline from left to right is enough). Errors carry file:line:
// a line that is not two numbers, a negative radius, fewer than two points, no area.
base::Result<TurningRegion> parseProfilePoints(std::string_view text, const std::string& fileName = {});

// The command line's argument: a rectangle when it is four comma-separated numbers, else the file.
base::Result<TurningRegion> stockProfileFromArgument(const std::string& argument);

// The seed-001 groove's inputs, the R-parameters of the thesis (Kod 1 by default); X is a radius.
struct GrooveParameters {
    double r0 = 180, r1 = 185;    // start point P: X, Z (corner of the right flank and the surface)
    double r2 = 21.801;           // cone angle of the shaft surface (deg), rising to the right
    double r3 = 170;              // depth below P
    double r4 = 45;               // bottom width
    double r5 = 6.71, r6 = 4.09;  // right and left flank angles from the radial direction (deg)
    double r7 = 0.5, r8 = 0.5;    // allowances on the bottom (in X) and on the flanks (normal)
    double r9 = 3;                // insert width
};

// The groove's points (Z, X as turningPoint gives them): P, the bottom corners, C1 where the left
// flank meets the surface; R, S, T, U the corners of the contour offset by the allowances. Found by
// intersecting lines (groove spec F1, seed REQ-04), never dividing by tan R2, tan R5 or tan R6, so
// a cylinder (R2 = 0) and vertical flanks (R5 = 0, R6 = 0) work; for R2, R5, R6 > 0 they equal the
// thesis' closed forms (seed §2.5).
struct GrooveGeometry {
    Vec2 p, bottomRight, bottomLeft, c1;
    Vec2 r, s, t, u;
    double tan2 = 0, tan5 = 0, tan6 = 0;  // tan R2, tan R5, tan R6
    double d = 0, c = 0;                  // Z widths of the right flank and of the left flank (Rov. 2, 9)
    double h1 = 0, h2 = 0;                // heights of the surface at C1 below P and of the left flank
    double bottomOffsetX = 0;             // R0 - R3 + R7: the offset bottom (Sx = Tx)

    // The offset flanks as lines: Z at radius x, and (only where that flank is not vertical,
    // tan5 > 0 / tan6 > 0) the radius at z; dz/dx = tan R5 on the right, -tan R6 on the left.
    double zRight(double x) const { return t.x + tan5 * (x - t.y); }
    double zLeft(double x) const { return s.x - tan6 * (x - s.y); }
    double xRight(double z) const { return t.y + (z - t.x) / tan5; }
    double xLeft(double z) const { return s.y + (s.x - z) / tan6; }
    // The shaft's surface (the cone line through P) at z.
    double surfaceX(double z) const { return p.y + (z - p.x) * tan2; }
};
GrooveGeometry grooveGeometry(const GrooveParameters& g);

// The shaft before grooving: under the cone line from `marginMm` left of C1 to `marginMm` right
// of P, down to the axis.
TurningRegion grooveStock(const GrooveParameters& g, double marginMm = 20);
// What must stay after roughing: the same shaft with the groove's offset contour (R, S, T, U)
// taken out, the contour the thesis' program must never cut (seed REQ-15).
TurningRegion grooveOffsetPart(const GrooveParameters& g, double marginMm = 20);

}  // namespace camwb::sim
