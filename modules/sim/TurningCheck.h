// The turning simulation of a traced program: every move of a lathe program (G18, X a radius)
// cuts the revolved stock with the insert, and the checks a programmer needs before the machine
// runs it come out per record: rapids through stock and gouges of the design contour (errors),
// feed moves in air (counted, one note: grooving retracts and approaches make many of them).
#pragma once

#include "base/Diagnostic.h"
#include "sim/Checks.h"
#include "sim/TurningStock.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sim {

struct TurningOptions {
    Insert insert;
    // Set only for a toolpath whose X is a diameter: the NC interpreters already halve X under
    // DIAMON (nc/Interpreter.h), so programs read back never need it.
    bool xIsDiameter = false;
    double toleranceMm = 1e-3;  // cuts shallower than this are touching, not a rapid hit or a gouge
};

struct TurningReport {
    // In record order: RapidInStock, Gouge (valueMm: the radial depth) and one AirCutting note;
    // `at` is (X radius, 0, Z).
    std::vector<Check> findings;
    std::size_t moves = 0;  // straight moves simulated
    std::size_t rapidsInStock = 0, gouges = 0, feedsInAir = 0;
    double removedMm2 = 0;
    double maxGougeMm = 0;
    Vec2 maxGougeAt;
    double maxRapidDepthMm = 0;
    TurningRegion stock;  // what is left
    // What is left above the design contour (none without a design): its area and its thickest
    // point, measured radially down to the contour (roughing leaves no more than its step's cusp).
    double leftoverMm2 = 0;
    double maxLeftoverMm = 0;
    Vec2 maxLeftoverAt;

    bool hasErrors() const { return rapidsInStock + gouges > 0; }
};

// Simulates `program` on `stock` against `design` (empty: no gouge check). Each record's moves
// (arcs split by buildMoves) are mapped to the plane as (Z, X). A record makes at most one
// finding of each kind, with its deepest figure.
TurningReport checkTurning(const toolpath::Toolpath& program, TurningRegion stock, TurningRegion design,
                           const TurningOptions& options);

// A lathe has no Y axis: its programs never give Y, and buildMoves would wait for it forever.
// The turning plane is Y = 0 by definition, so a straight move that leaves Y out is taken there
// (X and Z stay exactly as the program has them; a Y a program does give is kept and ignored).
toolpath::Toolpath inTurningPlane(const toolpath::Toolpath& program);

}  // namespace camwb::sim
