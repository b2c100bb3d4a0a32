// Where the simulator's playback is: a position in machine time (the motion plan's seconds),
// mapped to the move, the tool's pose along its velocity profile and the NC line. Plain C++ (no Qt, no VTK): the dock,
// the 3D overlay and the stock animation all ask it, so stepping and jumping have one definition.
#pragma once

#include "base/Vec.h"
#include "sim/MotionPlan.h"
#include "sim/Moves.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace camwb::gui {

// A point in a move: `fraction` 0 at its start, 1 at its end.
struct MovePoint {
    std::size_t move = 0;
    double fraction = 0;
    bool operator==(const MovePoint&) const = default;
    bool operator<(const MovePoint& o) const { return move != o.move ? move < o.move : fraction < o.fraction; }
};

struct ToolPose {
    base::Vec3 tip;
    base::Vec3 axis{0, 0, 1};
    int tool = 0;
    bool known = false;  // false before the first move that knows where the tool is
};

class Timeline {
public:
    Timeline() = default;
    // `plan`: the motion plan of `moves` (sim::planMotion), one planned move per move.
    Timeline(const sim::MoveList* moves, const sim::MotionPlan& plan);

    double total() const { return m_total; }
    std::size_t moveCount() const { return m_start.size(); }
    double start(std::size_t move) const { return m_start[move]; }
    double end(std::size_t move) const { return m_start[move] + m_length[move]; }

    MovePoint pointAt(double position) const;
    ToolPose poseAt(const MovePoint& point) const;

    // The NC line of each move's record; steps and jumps go by lines. Without it, by records.
    void setLineOfRecord(std::function<int(std::size_t)> lineOfRecord) { m_lineOf = std::move(lineOfRecord); }
    int lineOf(std::size_t move) const;
    // Block steps, as a control's single block: the end of the block the position is in (the
    // start of the next block's first move), and back: the start of this block's run, or of the
    // block before when the position stands at that start already.
    double nextBlock(double position) const;
    double previousBlock(double position) const;
    // The first move at or after a record (moves follow records in order); moveCount() if none.
    std::size_t firstMoveOfRecord(std::size_t record) const;

private:
    std::size_t runStart(std::size_t move) const;

    const sim::MoveList* m_moves = nullptr;
    std::vector<double> m_start;
    std::vector<double> m_length;
    std::vector<sim::PlannedMove> m_planned;  // the distance along a move at a time
    double m_total = 0;
    std::function<int(std::size_t)> m_lineOf;
};

// The straight piece of `move` between two fractions (the rest of the move's state unchanged):
// what the stock cuts while the playback is inside a move.
sim::Move partOf(const sim::Move& move, double from, double to);

}  // namespace camwb::gui
