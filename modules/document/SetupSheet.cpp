#include "document/SetupSheet.h"

#include "base/NumberFormat.h"
#include "document/JobPipeline.h"
#include "document/OperationGeometry.h"
#include "document/Simulate.h"
#include "document/StockBlank.h"
#include "document/TurningSetup.h"
#include "occ/Model.h"
#include "sim/MotionPlan.h"
#include "sim/Simulation.h"
#include "sim/TurningCheck.h"
#include "toolpath/ProgramStats.h"
#include "toolpath/Toolpath.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace camwb::document {

namespace {

constexpr std::size_t kFindingsShown = 5;

// The highest point of `box` along `axis` (towards the spindle).
double highestAlong(const base::Box3& box, const base::Vec3& axis)
{
    double top = -1e300;
    for (const base::Vec3& corner : base::boxCorners(box.min, box.max))
        top = std::max(top, corner.dot(axis));
    return top;
}

SheetOperation sheetOperation(const Job& job, const Operation& op, const occ::Model& model)
{
    SheetOperation out;
    out.name = op.name();
    // A disabled operation stays in the list (its number is its place in the job) but says it is
    // not in the program, so the operator does not look for it on the control.
    out.kind =
        op.enabled ? std::string(kindLabel(op.kind())) : std::string(kindLabel(op.kind())) + " (disabled: not posted)";
    out.toolNumber = op.toolNumber;
    if (const ops::ToolController* tc = job.tool(op.toolNumber)) {
        out.spindleRpm = tc->spindleRpm;
        out.cuttingFeed = tc->cuttingFeedMmPerMin;
        out.plungeFeed = tc->plungeFeedMmPerMin;
        out.rampFeed = tc->rampFeed();
    }
    // The heights the job computed the operation with (the program does not keep them).
    if (auto geometry = resolveGeometry(op, model))
        out.heights = resolveHeights(op, geometry.value(), model, job.stock);
    if (const auto* contour = std::get_if<ops::ContourParams>(&op.params))
        out.stepDownMm = contour->stepDownMm;
    else if (const auto* pocket = std::get_if<ops::PocketParams>(&op.params))
        out.stepDownMm = pocket->stepDownMm;
    else if (const auto* pocket3d = std::get_if<ops::Pocket3dParams>(&op.params))
        out.stepDownMm = pocket3d->stepDownMm;
    else if (const auto* waterline = std::get_if<ops::WaterlineParams>(&op.params))
        out.stepDownMm = waterline->maxStepDownMm;
    if (const auto* groove = std::get_if<ops::GrooveParams>(&op.params)) {
        out.stepDownMm = groove->infeedMm;
        out.turningSpeed = "G96 " + base::NumberFormat{1, true}.format(groove->surfaceSpeedMPerMin) + " m/min, LIMS " +
                           base::NumberFormat{0, true}.format(groove->maxRpm);
        out.turningFeed = base::NumberFormat{3, true}.format(groove->feedMmPerRev) + " mm/rev";
    }
    return out;
}

SheetVerification verification(const sim::SimulationResult& result, double resolutionMm, const Job& job,
                               const std::string& jobPath, const toolpath::Toolpath& program)
{
    SheetVerification out;
    out.run = true;
    out.resolutionMm = resolutionMm;
    out.maxGougeMm = result.deviation.maxGougeMm;
    for (const sim::Check& check : result.checks) {
        if (check.severity == base::Severity::Warning)
            ++out.warnings;
        if (check.severity != base::Severity::Error)
            continue;
        switch (check.kind) {
        case sim::CheckKind::Gouge:
            ++out.gouges;
            break;
        case sim::CheckKind::HolderCollision:
            ++out.holderCollisions;
            break;
        case sim::CheckKind::RapidInStock:
            ++out.rapidsInStock;
            break;
        case sim::CheckKind::MachineLimit:
            ++out.machineLimits;
            break;
        default:
            ++out.otherErrors;
            break;
        }
        if (out.firstFindings.size() < kFindingsShown) {
            const RecordPlace place = placeOfRecord(job, jobPath, program, check.record);
            out.firstFindings.push_back(place.operation.empty() ? check.message
                                                                : place.operation + ": " + check.message);
        }
    }
    return out;
}

std::vector<std::pair<std::string, std::string>> changedProperties(const Job& job, const post::PostInfo& info)
{
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [name, value] : job.postProperties) {
        const post::PropertyDef* def = info.property(name);
        if (!def || def->defaultValue != value)
            out.emplace_back(name, value);
    }
    return out;
}

}  // namespace

std::optional<double> requiredStickOut(const sim::MoveList& moves, int tool, const base::Box3& clear, double marginMm)
{
    std::optional<double> deepest;
    for (const sim::Move& move : moves.moves) {
        if (move.tool != tool || !move.moves() || !move.positionKnown)
            continue;
        for (const auto& [tip, axis] : {std::pair{move.from, move.fromAxis()}, std::pair{move.to, move.toAxis()}}) {
            const double depth = std::max(0.0, highestAlong(clear, axis) - tip.dot(axis));
            deepest = std::max(deepest.value_or(0.0), depth);
        }
    }
    if (!deepest)
        return std::nullopt;
    return *deepest + marginMm;
}

base::Result<SetupSheet> collectSetupSheet(const Job& job, const std::string& jobPath, const occ::Model& model,
                                           const toolpath::Toolpath& program, const SheetOptions& options)
{
    SetupSheet sheet;
    sheet.jobName = job.name;
    const post::PostContext context = post::PostContext::fromEnvironment(job.name);
    sheet.created = post::formatDateUtc(context.dateEpochSeconds);
    sheet.user = context.user;
    sheet.version = context.version;
    sheet.jobFile = std::filesystem::path(jobPath).filename().string();
    sheet.modelFile = std::filesystem::path(job.modelPath).filename().string();
    sheet.stock = job.stock.box();
    sheet.modelBounds = base::Box3{model.boundsMin(), model.boundsMax(), false};
    sheet.workOffset = job.workOffset;
    sheet.stickOutMarginMm = options.stickOutMarginMm;

    auto post = loadJobPost(job, options.postDirs);
    if (!post)
        return post.error();
    const post::PostInfo& info = post.value().info();
    sheet.postId = info.id;
    sheet.postDescription = info.description;
    sheet.postProperties = changedProperties(job, info);
    sheet.ncFile = std::filesystem::path(jobPath).stem().string() + "." + info.extension;

    std::optional<kinematics::Machine> machine = options.machine;
    if (!machine) {
        auto found = jobMachine(job);
        if (!found)
            return found.error();
        machine = std::move(found).value();
    }
    if (machine) {
        sheet.machineId = machine->id;
        sheet.machineName = machine->name;
    }

    // A lathe job: its program gives no Y (its moves are built in the turning plane) and it is
    // checked on the grooves' turning stock instead of a height field of a model it has not.
    const std::optional<TurningSetup> turning = turningSetup(job);
    const toolpath::Toolpath inPlane = turning ? sim::inTurningPlane(program) : toolpath::Toolpath();
    const toolpath::Toolpath& moving = turning ? inPlane : program;

    // The moves: simulated against the stock and model when asked, else only built.
    const base::Box3 stockBox = jobStockBox(job, model);
    sim::SimulationResult simulated;
    if (options.simulate && turning) {
        sim::SimulationSetup setup;
        setup.machine = machine ? &*machine : nullptr;
        setup.cancel = options.cancel;
        setup.progress = options.progress;
        simulated = sim::simulate(moving, setup);  // the machine's limits and the motion
        if (simulated.cancelled)
            return base::makeError(kCollectCancelled);
        sim::TurningOptions turningOptions;
        turningOptions.insert = turning->insert;
        const sim::TurningReport turned = sim::checkTurning(moving, turning->stock, turning->design, turningOptions);
        simulated.checks.insert(simulated.checks.begin(), turned.findings.begin(), turned.findings.end());
        sheet.verification = verification(simulated, 0, job, jobPath, moving);
        sheet.verification.maxGougeMm = turned.maxGougeMm;
        sheet.verification.turning = true;
    } else if (options.simulate) {
        // The stock as the solid it is (a cylinder, a blank's mesh), not only its box.
        auto blank = loadStockBlank(job, jobPath);
        if (!blank)
            return blank.error();
        sim::StockSpec spec = jobStockSpec(job, model, blank.value(), 0);
        spec.design = designMesh(model);
        sim::SimulationSetup setup;
        setup.machine = machine ? &*machine : nullptr;
        setup.stockSpec = &spec;
        setup.cancel = options.cancel;
        setup.progress = options.progress;
        simulated = sim::simulate(program, setup);
        if (simulated.cancelled)
            return base::makeError(kCollectCancelled);
        if (!simulated.stockError.empty())
            return base::makeError(simulated.stockError);
        sheet.verification = verification(simulated, spec.resolutionMm, job, jobPath, program);
    } else {
        simulated.moves = sim::buildMoves(moving);
    }
    const sim::MoveList& moves = simulated.moves;

    // Time: planned with the machine's accelerations, per operation by where each move came from.
    const kinematics::Machine planMachine = machine ? *machine : kinematics::defaultLimitsMachine();
    const sim::MotionPlan plan = sim::planMotion(moves, planMachine);
    if (options.cancel && options.cancel->load())
        return base::makeError(kCollectCancelled);
    toolpath::StatsOptions statsOptions;
    statsOptions.rapidMmPerMin = kinematics::estimateRapidMmPerMin(machine ? &*machine : nullptr);
    const toolpath::ProgramStats stats = toolpath::programStats(moving, statsOptions);
    sheet.cycleSeconds = plan.totalSeconds;
    sheet.simpleSeconds = stats.totals.totalSeconds();
    sheet.rapidLengthMm = stats.totals.rapidLengthMm;
    sheet.feedLengthMm = stats.totals.feedLengthMm;

    for (const Operation& op : job.operations)
        sheet.operations.push_back(sheetOperation(job, op, model));
    for (const auto& [index, seconds] : sim::secondsPerOperation(moving, moves, plan))
        if (index >= 0 && index < static_cast<int>(sheet.operations.size()))
            sheet.operations[static_cast<std::size_t>(index)].seconds = seconds;

    // Tools by number, with the stick-out their moves need over the stock and the model.
    base::Box3 clear = stockBox;
    clear.add(sheet.modelBounds.min);
    clear.add(sheet.modelBounds.max);
    std::map<int, SheetTool> tools;
    for (const ops::ToolController& tc : job.tools) {
        SheetTool& tool = tools[tc.tool.number];
        tool.controller = tc;
        // A lathe's insert sticks out along X, not along a spindle axis: no stick-out figure.
        if (!turning)
            tool.stickOutMm = requiredStickOut(moves, tc.tool.number, clear, options.stickOutMarginMm);
        tool.tooShort = tool.stickOutMm && tc.tool.lengthMm > 0 && tc.tool.lengthMm < *tool.stickOutMm;
    }
    for (const Operation& op : job.operations)
        if (auto it = tools.find(op.toolNumber); op.enabled && it != tools.end())
            it->second.operations.push_back(op.name());
    for (auto& [number, tool] : tools)
        sheet.tools.push_back(std::move(tool));
    return sheet;
}

}  // namespace camwb::document
