// One simulation as the dock plays it: the NC trace it was made from (lines <-> records), the
// moves, their times from the motion model, the seed-003 analysis of the sampled motion, and what
// the stock animation needs (the stock as it starts, the tools' revolved shapes, the design model
// to compare with). Built on a worker thread by buildSimRun from the modules that own each part
// (sim, document); the GUI only shows it.
#pragma once

#include "document/NcTrace.h"
#include "gui/sim/RevolvedPart.h"
#include "gui/sim/Timeline.h"
#include "occ/Model.h"
#include "sim/Checks.h"
#include "sim/Moves.h"
#include "sim/Stock.h"

#include <array>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::sim {
class ToolShape;
}
namespace camwb::kinematics {
struct Machine;
}

namespace camwb::gui {

// One analysed quantity of the sampled motion (sim::analysePath), per sample from firstSample.
struct SampledQuantity {
    std::string id;     // stable: "vx", "ax", "tipFeed", "omega0", ...
    std::string label;  // shown, with the unit
    std::size_t firstSample = 0;
    std::vector<double> time;
    std::vector<double> values;
    std::vector<std::size_t> reversals;  // samples where the axis it belongs to reverses (all axes: any)
};

struct SimAnalysis {
    double stepSeconds = 0.003;
    std::vector<base::Vec3> tip;  // per sample, workpiece frame
    std::vector<SampledQuantity> quantities;
};

struct SimRun {
    std::shared_ptr<const document::NcTrace> trace;
    std::string programName;
    // The machine it was planned on (the default limits' when none was chosen): a measured trace
    // is carried onto the workpiece through its chain.
    std::shared_ptr<const kinematics::Machine> machine;
    bool machineChosen = false;  // false: `machine` is the default limits' (no chain, no table)
    sim::MoveList moves;
    // The rotary angles at each move's start (sim::rotaryAtMoveStarts; empty unless the machine
    // is five-axis): the machine frame's pose anywhere in the program (gui/sim/MachineFrame).
    std::vector<std::array<double, 2>> rotaryAtStart;
    Timeline timeline;         // over `moves`, in the motion plan's time
    double cycleSeconds = 0;   // the motion plan's (with accelerations)
    double simpleSeconds = 0;  // the distance / feed estimate of the program information
    SimAnalysis analysis;
    std::vector<std::string> notes;  // what could not be simulated and why (shown in the report)
    // What sim::simulate found, block by block (the same checks as camwb-cli sim), and the
    // largest gouge and leftover at the program's end.
    std::vector<sim::Check> checks;
    std::optional<sim::Deviation> deviation;

    // The stock animation's inputs; without a stock the tool plays over the path only.
    std::shared_ptr<const sim::Stock> stock;
    std::string stockError;  // why the job's stock was not made (too fine for this computer's memory)
    std::map<int, std::shared_ptr<const sim::ToolShape>> toolShapes;
    std::map<int, std::vector<RevolvedPart>> toolParts;  // for drawing
    bool hasDesign = false;                              // the stock compares with a model

    SimRun() = default;
    SimRun(const SimRun&) = delete;
    SimRun& operator=(const SimRun&) = delete;
};

struct SimRunRequest {
    std::shared_ptr<const document::NcTrace> trace;
    std::string programName;
    // Null: a three-axis machine of the default limits (kinematics::Machine{}), as camwb-cli sim.
    std::shared_ptr<const kinematics::Machine> machine;
    std::optional<base::Box3> stockBox;  // the job's stock box; none: `stockSolid`, else no stock removal
    sim::TriangleMesh stockSolid;        // a round or blank stock's solid (document::jobStockSpec)
    // The job's tools by number (its CL's tool changes): the NC's T words name them, give no shape.
    std::map<int, toolpath::Tool> tools;
    std::optional<occ::Model> model;  // the job's: compared with (document::designMesh)
    double resolutionMm = 0.25;
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(int percent)> progress;
};

// Null when cancelled. Whatever part cannot be made is left out and named in `notes`.
std::shared_ptr<SimRun> buildSimRun(const SimRunRequest& request);

}  // namespace camwb::gui
