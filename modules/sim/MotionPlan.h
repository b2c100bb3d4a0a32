// The program in time: each move of a MoveList planned on a machine with trapezoidal velocity
// profiles (programmed feed on the tool tip relative to the workpiece, rapids at the rapid rate,
// no machine axis above its velocity or acceleration), a look-ahead over the corners, dwells,
// tool changes and spindle ramps; and the cycle time per tool and per section beside the simple
// distance/feed estimate (toolpath::programStats) it replaces.
#pragma once

#include "kinematics/Machine.h"
#include "sim/Moves.h"
#include "toolpath/ProgramStats.h"

#include <atomic>
#include <map>
#include <vector>

namespace camwb::sim {

struct PlanOptions {
    // A velocity step each axis may take at a corner, as the acceleration times this time (the
    // control's interpolation cycle): a 90° corner is passed at a_axis·t per axis, a straight
    // continuation at full speed. Controls that blend corners within a tolerance are faster.
    double cornerStepSeconds = 0.003;
    // Once set, planMotion stops within a few thousand moves and returns a plan that says it was
    // cancelled (its times are not the program's). nullptr: the plan runs to the end.
    const std::atomic<bool>* cancel = nullptr;
};

// One move in time. It starts at `start`, stands for `pauseSeconds` (dwell, tool change, a
// spindle ramp before it), then moves for `moveSeconds` along its parameter of length `length`:
// millimetres of the tip on the workpiece, or degrees of the rotary axis that turns most when the
// tip stands (a rotation in place; `rotationOnly`). Speeds and `acceleration` are in those units
// per second (per second squared): entry, the top it reaches, exit.
struct PlannedMove {
    double start = 0;
    double pauseSeconds = 0;
    double moveSeconds = 0;
    double length = 0;
    double entrySpeed = 0;
    double cruiseSpeed = 0;
    double exitSpeed = 0;
    double acceleration = 0;
    bool rotationOnly = false;
    bool fixedTime = false;  // inverse time: the program gave the time, it runs at one speed

    double end() const { return start + pauseSeconds + moveSeconds; }
    // Distance along the parameter `t` seconds after the motion began (0..moveSeconds).
    double distanceAt(double t) const;
};

struct MotionPlan {
    std::vector<PlannedMove> moves;  // one per MoveList move, same index
    // The spindle's stop after the last move (an M5 there, or the program's end, which stops it
    // too): no move follows to carry the ramp down, so it stands here, in totalSeconds.
    double endPauseSeconds = 0;
    double totalSeconds = 0;
    // Moves a speed limit of 0 stopped (a feed move at feed 0): they take no time, as the simple
    // estimate counts them (toolpath::ProgramStats::movesWithoutFeed).
    std::size_t movesWithoutSpeed = 0;
    bool cancelled = false;  // PlanOptions::cancel stopped it: incomplete, not to be shown
};

MotionPlan planMotion(const MoveList& moves, const kinematics::Machine& machine, const PlanOptions& options = {});

// Cycle time split as the program information shows it, planned and simple side by side.
struct TimeSplit {
    double rapidSeconds = 0;
    double feedSeconds = 0;
    double pauseSeconds = 0;  // dwells, tool changes, spindle ramps
    double totalSeconds() const { return rapidSeconds + feedSeconds + pauseSeconds; }
};
struct SectionTime {
    std::string name;
    int tool = 0;
    TimeSplit planned;
};
struct CycleTimes {
    TimeSplit planned;
    std::map<int, TimeSplit> plannedPerTool;  // by tool number (0: before the first tool)
    std::vector<SectionTime> sections;        // MoveList::sections order
    // toolpath::programStats' estimate (distance/feed, no acceleration): total and per tool;
    // it has no per-section figure.
    double simpleSeconds = 0;
    std::map<int, double> simplePerTool;
};

CycleTimes cycleTimes(const MoveList& moves, const MotionPlan& plan, const toolpath::ProgramStats& simple);

// Planned seconds by job operation: each move counts for the operation of the CL record it came
// from (toolpath::SourceRef::operationIndex; -1: none), so a tool change the pipeline inserted
// counts for the operation it was inserted for. `moves` is buildMoves(program).
std::map<int, double> secondsPerOperation(const toolpath::Toolpath& program, const MoveList& moves,
                                          const MotionPlan& plan);

}  // namespace camwb::sim
