#include "sim/Simulation.h"

#include "kinematics/LimitCheck.h"
#include "sim/MakeStock.h"
#include "sim/StockRun.h"
#include "toolpath/ForwardingSink.h"
#include "toolpath/Toolpath.h"

#include <algorithm>
#include <future>
#include <system_error>

namespace camwb::sim {

int SimulationResult::count(base::Severity severity) const
{
    return static_cast<int>(
        std::count_if(checks.begin(), checks.end(), [severity](const Check& c) { return c.severity == severity; }));
}

std::vector<Check> machineLimitChecks(const toolpath::Toolpath& program, const kinematics::Machine& machine)
{
    toolpath::NullSink nowhere;
    kinematics::LimitCheck limits(machine, nowhere);
    toolpath::play(program, limits);
    std::vector<Check> out;
    for (const kinematics::LimitCheck::Finding& f : limits.findings()) {
        Check c;
        c.kind = CheckKind::MachineLimit;
        c.severity = base::Severity::Error;
        // LimitCheck numbers the records it saw, which play() gives in order; the travel spans,
        // known only at the end, name the record where the extreme was reached.
        c.record = static_cast<std::int64_t>(f.record);
        c.moves = f.count;
        c.message = f.message;
        if (f.count > 1)
            c.message += " (" + std::to_string(f.count) + " times in all)";
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<Check> untracedFeedChecks(const MoveList& moves)
{
    std::vector<Check> out;
    const std::vector<UntracedMove>& untraced = moves.untraced;
    for (std::size_t k = 0; k < untraced.size();) {
        // A stretch: the untraced records with no move between them. A lathe program in X and Z
        // never gives Y, and its hundreds of moves are one finding, not hundreds.
        std::size_t end = k + 1;
        while (end < untraced.size() && untraced[end].nextMove == untraced[k].nextMove)
            ++end;
        const UntracedMove* first = nullptr;
        int feeds = 0;
        std::uint32_t lastRecord = 0;
        for (std::size_t j = k; j < end; ++j) {
            if (untraced[j].kind != MoveKind::Feed || (feeds > 0 && untraced[j].record == lastRecord))
                continue;
            first = first ? first : &untraced[j];
            lastRecord = untraced[j].record;
            ++feeds;
        }
        const bool toTheEnd = untraced[k].nextMove == moves.moves.size();
        k = end;
        if (!first)
            continue;
        std::string axes;
        for (int axis = 0; axis < 3; ++axis)
            if (first->unknownAxes.has(axis))
                axes += (axes.empty() ? "" : ", ") + std::string(1, "XYZ"[axis]);
        Check c;
        c.kind = CheckKind::UnknownPosition;
        c.severity = base::Severity::Warning;
        c.record = first->record;
        c.moves = feeds;
        c.message = "feed move from an unknown position (" + axes +
                    " not given before it): where it cuts is not known and not simulated";
        if (feeds > 1)
            c.message += (feeds == 2 ? "; nor is the feed move after it"
                                     : "; nor are the " + std::to_string(feeds - 1) + " feed moves after it") +
                         std::string(toTheEnd ? ", up to the program's end" : ", until the position is known");
        out.push_back(std::move(c));
    }
    return out;
}

base::Result<std::unique_ptr<Stock>> makeStock(const StockSpec& spec, bool tilts)
{
    const base::Box3 box = spec.box ? *spec.box : spec.blank.bounds();
    if (std::optional<std::string> why = stockBeyondReach(box))
        return base::makeError(*why);
    if (std::optional<std::string> why = stockTooLarge(box, spec.resolutionMm, tilts, stockMemoryBudget()))
        return base::makeError(*why);
    std::unique_ptr<Stock> stock = spec.box ? makeStock(*spec.box, spec.resolutionMm, tilts)
                                            : makeStockFromMesh(spec.blank, spec.resolutionMm, tilts);
    // A stock of cells knows where the model's wall lies only within half a cell: a cut exactly
    // to the wall may read as that much into it.
    if (!spec.design.empty())
        stock->setDesign(spec.design, spec.gougeToleranceMm + 0.5 * stock->resolutionMm());
    return stock;
}

SimulationResult simulate(const toolpath::Toolpath& program, const SimulationSetup& setup,
                          const std::vector<bool>& recordsInError)
{
    SimulationResult result;
    MoveOptions options;
    options.chordToleranceMm = setup.chordToleranceMm;
    if (setup.machine && setup.machine->kinematics.fiveAxis())
        options.chain = &setup.machine->kinematics;
    result.moves = buildMoves(program, options, recordsInError);
    result.tilts = anyToolTilts(result.moves);
    // Nothing below changes the moves; the plan is joined before they are returned (and, should the
    // cut throw, by the future's destructor).
    std::future<MotionPlan> planned;
    PlanOptions planOptions;
    planOptions.cancel = setup.cancel;
    if (setup.planOn) {
        try {
            planned = std::async(std::launch::async, [&moves = result.moves, machine = setup.planOn, planOptions] {
                return planMotion(moves, *machine, planOptions);
            });
        } catch (const std::system_error&) {
            // no thread to be had: planned after the cut instead
        }
    }
    Stock* stock = setup.stock;
    if (!stock && setup.stockSpec) {
        base::Result<std::unique_ptr<Stock>> made = makeStock(*setup.stockSpec, result.tilts);
        if (made) {
            result.stock = std::move(made).value();
            stock = result.stock.get();
        } else {
            result.stockError = made.error().message;
        }
    }
    if (stock) {
        StockRun run(result.moves, *stock);
        const std::size_t total = result.moves.moves.size();
        const std::size_t step = std::max<std::size_t>(total / 100, 1024);
        while (!run.finished()) {
            run.cutTo(run.nextMove() + step, setup.cancel);
            if (setup.cancel && setup.cancel->load()) {
                result.cancelled = true;
                break;
            }
            if (setup.progress)
                setup.progress(total ? double(run.nextMove()) / double(total) : 1.0);
        }
        result.cut = true;
        result.checks = run.checks();
        result.removedMm3 = run.removedMm3();
        result.airCuttingMm = run.airCuttingMm();
        result.cuttingMm = run.cuttingMm();
        if (!result.cancelled) {
            result.deviation = stock->compare();
            if (std::optional<Check> gouge = finishedStockGouge(result.deviation, result.moves, result.checks))
                result.checks.push_back(std::move(*gouge));
        }
    }
    for (Check& c : untracedFeedChecks(result.moves))
        result.checks.push_back(std::move(c));
    if (setup.machine) {
        for (Check& c : machineLimitChecks(program, *setup.machine))
            result.checks.push_back(std::move(c));
    }
    if (planned.valid())
        result.plan = planned.get();
    else if (setup.planOn && !result.cancelled)
        result.plan = planMotion(result.moves, *setup.planOn, planOptions);
    if (result.plan && result.plan->cancelled) {  // half a plan is no plan
        result.plan.reset();
        result.cancelled = true;
    }
    return result;
}

}  // namespace camwb::sim
