#include "gui/sim/SimRun.h"

#include "gui/sim/SimAnalysis.h"
#include "kinematics/Machine.h"
#include "sim/MakeStock.h"
#include "sim/MotionPlan.h"
#include "sim/Stock.h"
#include "sim/ToolShape.h"
#include "toolpath/ProgramStats.h"
#include "toolpath/Toolpath.h"

namespace camwb::gui {

namespace {

// A cut deeper than this into the model is a gouge (the stock's resolution adds its own).
constexpr double kGougeToleranceMm = 0.01;

bool cancelled(const SimRunRequest& request) { return request.cancel && request.cancel->load(); }

void progress(const SimRunRequest& request, int percent)
{
    if (request.progress)
        request.progress(percent);
}

// The program with each tool change given the job's tool of that number where the NC gives no
// diameter (a posted program calls T1 and means the job's tool 1).
toolpath::Toolpath withJobTools(const toolpath::Toolpath& program, const std::map<int, toolpath::Tool>& tools)
{
    toolpath::Toolpath sized = program;
    for (std::size_t i = 0; i < sized.size(); ++i) {
        auto* change = std::get_if<toolpath::ToolChange>(&sized.record(i));
        if (change == nullptr || change->tool.diameterMm > 0)
            continue;
        if (auto it = tools.find(change->tool.number); it != tools.end())
            change->tool = it->second;
    }
    return sized;
}

// The motion plan's times, the cycle time beside the simple estimate, and the analysis of the
// sampled motion. False when cancelled.
bool planInTime(const SimRunRequest& request, const kinematics::Machine& machine, SimRun& run)
{
    const sim::MotionPlan plan = sim::planMotion(run.moves, machine);
    if (cancelled(request))
        return false;
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

void makeStock(const SimRunRequest& request, SimRun& run)
{
    std::unique_ptr<sim::Stock> stock =
        sim::makeStock(*request.stockBox, request.resolutionMm, sim::anyToolTilts(run.moves));
    if (!request.design.empty()) {
        stock->setDesign(request.design, kGougeToleranceMm);
        run.hasDesign = true;
    }
    run.stock = std::move(stock);
    for (const auto& [number, tool] : run.moves.tools) {
        if (tool.diameterMm <= 0) {
            run.notes.push_back("Tool " + std::to_string(number) +
                                " has no diameter: its moves are played but cut nothing");
            continue;
        }
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
    progress(request, 5);
    sim::MoveOptions options;
    if (request.machine)
        options.chain = &request.machine->kinematics;
    const toolpath::Toolpath program =
        request.tools.empty() ? request.trace->program : withJobTools(request.trace->program, request.tools);
    run->moves = sim::buildMoves(program, options, request.trace->recordsInError);
    if (cancelled(request))
        return nullptr;
    progress(request, 25);

    // Without a machine, the default limits (as camwb-cli sim): a time, said to be a default's.
    const kinematics::Machine fallback;
    const kinematics::Machine& machine = request.machine ? *request.machine : fallback;
    if (!request.machine)
        run->notes.push_back("No machine chosen: the cycle time and the path analysis assume default axis limits "
                             "(choose the machine in the NC inspector)");
    if (!planInTime(request, machine, *run))
        return nullptr;
    const auto trace = request.trace;
    run->timeline.setLineOfRecord([trace](std::size_t record) { return trace->lineOfRecord(record); });
    progress(request, 70);

    if (request.stockBox)
        makeStock(request, *run);
    if (cancelled(request))
        return nullptr;
    progress(request, 100);
    return run;
}

}  // namespace camwb::gui
