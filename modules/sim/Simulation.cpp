#include "sim/Simulation.h"

#include "kinematics/LimitCheck.h"
#include "sim/MakeStock.h"
#include "sim/StockRun.h"
#include "toolpath/ForwardingSink.h"
#include "toolpath/Toolpath.h"

#include <algorithm>

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
    if (setup.machine) {
        for (Check& c : machineLimitChecks(program, *setup.machine))
            result.checks.push_back(std::move(c));
    }
    return result;
}

}  // namespace camwb::sim
