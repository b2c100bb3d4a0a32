// What the simulator finds wrong (or worth knowing) in a program, block by block: the one
// finding type the runner, the command line's report and the simulator dock share.
#pragma once

#include "base/Diagnostic.h"
#include "base/Vec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::sim {

enum class CheckKind {
    RapidInStock,       // a rapid removed material: error
    Gouge,              // the cutter went into the design model: error
    HolderCollision,    // the shank or holder reached into the stock: error
    PlungeNotCentre,    // a tool that does not cut at its centre plunged into material: error
    SpindleOffCutting,  // material removed with the spindle stopped: error
    MachineLimit,       // travel, rotary range, feed, spindle, tool size (kinematics::LimitCheck): error
    AirCutting,         // a feed move that removed nothing: note
    NoToolShape,        // moves with a tool of no diameter (NC without tool data): not cut, warning
    UnknownPosition,    // a feed move from where an axis is not known yet: not simulated, warning
};
// "rapid-in-stock", "gouge", "holder-collision", "plunge-not-centre-cutting", "spindle-off-cutting",
// "machine-limit", "air-cutting", "no-tool-shape", "unknown-position": the names the JSON report
// and the dock use.
const char* checkKindName(CheckKind kind);

// One finding for one program record (the moves of one block are one finding, with the worst
// value among them).
struct Check {
    CheckKind kind = CheckKind::Gouge;
    base::Severity severity = base::Severity::Error;
    std::int64_t record = -1;  // toolpath record; -1: about no record
    std::int64_t move = -1;    // the move of MoveList with the worst value; -1: none
    int moves = 0;             // moves of the record it concerns
    double valueMm = 0;        // depth (gouge, holder, plunge), length (air cutting), 0 where it has none
    double removedMm3 = 0;     // material removed (rapid in stock, spindle off), over all its moves
    base::Vec3 at;             // where, in the workpiece frame (when move >= 0)
    std::string message;
};

// Gathers checks, one per (kind, record): a block that gouges over forty moves of its arc is one
// finding at its deepest point.
class CheckList {
public:
    void add(Check check);
    // In order of first appearance.
    const std::vector<Check>& checks() const { return m_checks; }
    int count(base::Severity severity) const;
    bool hasErrors() const { return count(base::Severity::Error) > 0; }

private:
    std::vector<Check> m_checks;
    std::vector<std::pair<std::uint64_t, std::size_t>> m_index;  // (key, position) sorted by key
};

}  // namespace camwb::sim
