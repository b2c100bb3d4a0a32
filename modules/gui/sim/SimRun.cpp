#include "gui/sim/SimRun.h"

#include "document/Simulate.h"
#include "gui/sim/SimAnalysis.h"
#include "kinematics/Machine.h"
#include "sim/MachineAxes.h"
#include "sim/MotionPlan.h"
#include "sim/Simulation.h"
#include "sim/Stock.h"
#include "sim/ToolShape.h"
#include "toolpath/ProgramStats.h"
#include "toolpath/Toolpath.h"

namespace camwb::gui {

namespace {

bool cancelled(const SimRunRequest& request) { return request.cancel && request.cancel->load(); }

void progress(const SimRunRequest& request, int percent)
{
    if (request.progress)
        request.progress(percent);
}

// The motion plan's times, the cycle time beside the simple estimate, and the analysis of the
// sampled motion. False when cancelled.
bool planInTime(const SimRunRequest& request, const kinematics::Machine& machine, const sim::MotionPlan& plan,
                SimRun& run)
{
    toolpath::StatsOptions stats;
    stats.rapidMmPerMin = kinematics::estimateRapidMmPerMin(request.machine.get());
    stats.recordsInError = &request.trace->recordsInError;
    const sim::CycleTimes times =
        sim::cycleTimes(run.moves, plan, toolpath::programStats(request.trace->program, stats));
    run.cycleSeconds = times.planned.totalSeconds();
    run.simpleSeconds = times.simpleSeconds;
    run.timeline = Timeline(&run.moves, plan);
    auto analysis = analyseMotion(run.moves, plan, machine, request.cancel);
    if (!analysis)
        return false;
    run.analysis = std::move(*analysis);
    if (run.analysis.stepSeconds > 0.003 + 1e-12)
        run.notes.push_back("The path analysis samples every " +
                            std::to_string(static_cast<int>(run.analysis.stepSeconds * 1e3)) +
                            " ms (the program is long; 3 ms would not fit in memory)");
    return true;
}

// The tools' shapes (to cut with) and revolved outlines (to draw).
void shapeTools(SimRun& run)
{
    for (const auto& [number, tool] : run.moves.tools) {
        if (tool.diameterMm <= 0)
            continue;  // the checks say so (no-tool-shape)
        auto shape = std::make_shared<const sim::ToolShape>(tool);
        run.toolParts[number] = revolvedParts(*shape);
        run.toolShapes[number] = std::move(shape);
    }
}

}  // namespace

std::shared_ptr<SimRun> buildSimRun(const SimRunRequest& request)
{
    auto run = std::make_shared<SimRun>();
    run->trace = request.trace;
    run->programName = request.programName;
    if (!request.trace)
        return run;
    progress(request, 2);
    toolpath::Toolpath program = request.trace->program;
    document::sizeTools(program, request.tools);  // a posted program's T1 means the job's tool 1

    // The whole program through the stock first: the checks and the end's deviation, as
    // camwb-cli sim reports them. The dock then animates a stock of the same kind.
    std::optional<sim::StockSpec> spec;
    if (request.stockBox || !request.stockSolid.empty()) {
        spec.emplace();
        spec->box = request.stockBox;
        spec->blank = request.stockSolid;
        spec->resolutionMm = request.resolutionMm;
        if (request.model) {
            spec->design = document::designMesh(*request.model);
            run->hasDesign = !spec->design.empty();
        }
    }
    // Without a machine, the default limits (as camwb-cli sim): a time, said to be a default's.
    run->machine = request.machine ? request.machine
                                   : std::make_shared<const kinematics::Machine>(kinematics::defaultLimitsMachine());
    const kinematics::Machine& machine = *run->machine;
    run->machineChosen = request.machine != nullptr;

    sim::SimulationSetup setup;
    setup.machine = request.machine.get();
    setup.planOn = &machine;  // planned beside the cut; Cancel stops both
    setup.stockSpec = spec ? &*spec : nullptr;
    setup.cancel = request.cancel;
    setup.progress = [&request](double fraction) { progress(request, 5 + static_cast<int>(60 * fraction)); };
    sim::SimulationResult result = sim::simulate(program, setup, request.trace->recordsInError);
    if (result.cancelled || cancelled(request) || !result.plan)
        return nullptr;
    run->moves = std::move(result.moves);
    run->checks = std::move(result.checks);
    if (result.cut && run->hasDesign)
        run->deviation = result.deviation;
    result.stock.reset();  // the cut one: the dock animates a fresh one, never both at once
    if (spec) {
        base::Result<std::unique_ptr<sim::Stock>> stock = sim::makeStock(*spec, result.tilts);
        if (stock) {
            run->stock = std::move(stock).value();
        } else {  // simulate() found the same and cut nothing
            run->stockError = "No stock removal: " + stock.error().message + ", then simulate again.";
            run->notes.push_back(run->stockError);
        }
        shapeTools(*run);
    }
    progress(request, 70);
    if (!request.machine)  // after the stock's notes: what went wrong first
        run->notes.push_back("No machine chosen: the cycle time and the path analysis assume default axis limits "
                             "(choose the machine in the NC inspector)");
    if (!planInTime(request, machine, *result.plan, *run))
        return nullptr;
    run->rotaryAtStart = sim::rotaryAtMoveStarts(machine.kinematics, run->moves);
    const auto trace = request.trace;
    run->timeline.setLineOfRecord([trace](std::size_t record) { return trace->lineOfRecord(record); });
    progress(request, 100);
    return run;
}

}  // namespace camwb::gui
