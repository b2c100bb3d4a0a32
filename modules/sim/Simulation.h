// A whole simulation in one call, for the command line and tests: the program's moves, every
// move cut through the stock (when there is one) with its checks, the machine's limits checked on
// the same records, and the remaining material compared with the design model. The simulator
// dock runs the same pieces (buildMoves, StockRun) step by step instead.
#pragma once

#include "base/Result.h"
#include "kinematics/Machine.h"
#include "sim/Checks.h"
#include "sim/MotionPlan.h"
#include "sim/Moves.h"
#include "sim/Stock.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sim {

// A stock for simulate() to make once it knows whether the program tilts the tool (then
// tri-dexels, else a height field): a box or a blank's mesh, and the design model to compare with.
struct StockSpec {
    std::optional<base::Box3> box;  // else `blank`
    TriangleMesh blank;
    double resolutionMm = 0.2;
    TriangleMesh design;             // empty: no gouge or leftover measured
    double gougeToleranceMm = 0.02;  // plus half the resolution (where a cell knows a wall to be)
};

// The stock `spec` describes, a height field or (`tilts`) tri-dexels, with its design model; what
// simulate() cuts and what the simulator dock animates. An error, made nothing of, where it would
// take more than half the computer's memory (stockTooLarge).
base::Result<std::unique_ptr<Stock>> makeStock(const StockSpec& spec, bool tilts);

struct SimulationSetup {
    const kinematics::Machine* machine = nullptr;  // limits and chain; nullptr: none checked
    Stock* stock = nullptr;                        // the caller's stock; else `stockSpec` or none
    const StockSpec* stockSpec = nullptr;
    double chordToleranceMm = 0.005;  // arcs and joint-interpolated moves
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double fraction)> progress;  // 0..1, from the cutting loop
    // Also plan the motion on this machine (planMotion), on a second thread while the stock is
    // cut: the plan needs only the moves, so a caller that wants both waits for the longer of the
    // two, not their sum. `cancel` stops the plan too (then the result is cancelled and has no
    // plan). nullptr: no plan.
    const kinematics::Machine* planOn = nullptr;
};

struct SimulationResult {
    MoveList moves;
    std::unique_ptr<Stock> stock;  // the stock simulate() made from a StockSpec, as cut
    std::vector<Check> checks;     // by record: the stock's, the untraced feed moves', the machine's limits
    bool cancelled = false;
    bool cut = false;        // a stock was cut
    std::string stockError;  // why the stock described could not be made (then nothing is cut)
    bool tilts = false;      // a cutting move tilts the tool (the made stock is tri-dexels)
    double removedMm3 = 0;
    double airCuttingMm = 0;
    double cuttingMm = 0;
    Deviation deviation;             // against the stock's design model (empty without one)
    std::optional<MotionPlan> plan;  // with SimulationSetup::planOn, unless cancelled

    int count(base::Severity severity) const;
};

// `recordsInError` (nc::recordsInError) as buildMoves takes it.
SimulationResult simulate(const toolpath::Toolpath& program, const SimulationSetup& setup,
                          const std::vector<bool>& recordsInError = {});

// A warning for each record in `moves.untraced` that feeds (it would cut, and where is not known):
// the simulation says what it could not follow rather than report a clean run.
std::vector<Check> untracedFeedChecks(const MoveList& moves);

// The machine's limits (kinematics::LimitCheck) on `program` as MachineLimit checks: errors, the
// record each was first met at (-1 for spans known only at the end).
std::vector<Check> machineLimitChecks(const toolpath::Toolpath& program, const kinematics::Machine& machine);

}  // namespace camwb::sim
