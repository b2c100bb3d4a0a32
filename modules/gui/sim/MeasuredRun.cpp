#include "gui/sim/MeasuredRun.h"

#include "kinematics/Machine.h"

#include <algorithm>
#include <cmath>

namespace camwb::gui {

MeasuredRun carryMeasured(sim::MeasuredTrace trace, std::string path, const sim::TraceColumns& columns,
                          double spindleFaceToTipMm, const SimRun& run)
{
    MeasuredRun m;
    m.path = std::move(path);
    m.trace = std::move(trace);
    m.columns = columns;
    m.spindleFaceToTipMm = spindleFaceToTipMm;
    const kinematics::KinematicChain chain = run.machine ? run.machine->kinematics : kinematics::KinematicChain{};
    const sim::Trace nominal = sim::workpieceTrace(m.trace, false, chain, spindleFaceToTipMm);
    const sim::Trace actual = sim::workpieceTrace(m.trace, true, chain, spindleFaceToTipMm);
    for (const sim::TraceSample& s : nominal)
        m.nominalTip.push_back(s.tip);
    for (const sim::TraceSample& s : actual)
        m.actualTip.push_back(s.tip);
    std::vector<double> toProgram = sim::distanceToPath(actual, run.moves);
    // A program without a move gives no distance (infinite): nothing to colour by.
    if (!std::all_of(toProgram.begin(), toProgram.end(), [](double d) { return std::isfinite(d); }))
        toProgram.clear();
    m.quantities.push_back(
        {kMeasuredFollowingId, "measured Δ (mm)", 0, m.trace.time, sim::deviationDistance(nominal, actual), {}});
    if (!toProgram.empty())
        m.quantities.push_back({kMeasuredToProgramId, "Δ to program (mm)", 0, m.trace.time, toProgram, {}});
    return m;
}

}  // namespace camwb::gui
