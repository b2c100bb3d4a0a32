// The turning simulation of a traced program: every move of a lathe program (G18, X a radius)
// cuts the revolved stock with the insert, and the checks a programmer needs before the machine
// runs it come out per record: rapids through stock and gouges of the design contour (errors),
// feed moves in air (counted, one note: grooving retracts and approaches make many of them).
#pragma once

#include "base/Diagnostic.h"
#include "sim/TurningStock.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sim {

enum class TurningCheckKind : std::uint8_t { RapidInStock, Gouge, FeedInAir };

struct TurningFinding {
    TurningCheckKind kind = TurningCheckKind::RapidInStock;
    base::Severity severity = base::Severity::Error;
    std::size_t record = 0;   // index in the toolpath
    int file = 0, line = -1;  // the record's SourceRef (file indexes the interpreter's files)
    double mm = 0;            // the rapid's depth in the stock, the gouge's depth (radial)
    Vec2 at;                  // where (Z, X)
    std::string message;
};

struct TurningOptions {
    Insert insert;
    // Set only for a toolpath whose X is a diameter: the NC interpreters already halve X under
    // DIAMON (nc/Interpreter.h), so programs read back never need it.
    bool xIsDiameter = false;
    double toleranceMm = 1e-3;  // cuts shallower than this are touching, not a rapid hit or a gouge
};

struct TurningReport {
    std::vector<TurningFinding> findings;  // in record order
    std::size_t moves = 0;                 // straight moves simulated
    std::size_t rapidsInStock = 0, gouges = 0, feedsInAir = 0;
    double removedMm2 = 0;
    double maxGougeMm = 0;
    Vec2 maxGougeAt;
    double maxRapidDepthMm = 0;
    TurningRegion stock;  // what is left

    bool hasErrors() const { return rapidsInStock + gouges > 0; }
};

// Simulates `program` on `stock` against `design` (empty: no gouge check). Each record's moves
// (arcs split by buildMoves) are mapped to the plane as (Z, X). A record makes at most one
// finding of each kind, with its deepest figure.
TurningReport checkTurning(const toolpath::Toolpath& program, TurningRegion stock, TurningRegion design,
                           const TurningOptions& options);

}  // namespace camwb::sim
