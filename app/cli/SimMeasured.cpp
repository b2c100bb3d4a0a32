// camwb-cli sim --measured: a trace the control recorded (TNCscope CSV, seed 003), carried onto
// the workpiece through the machine's chain and set beside the program: how far the actual tip
// followed the nominal one, how far it strayed from the programmed path, and the seed-003
// analysis of the actual motion (axis reversals, the tip's feed), as of the simulated motion.
#include "SimMeasured.h"

#include "sim/MeasuredTrace.h"
#include "sim/PathAnalysis.h"

#include <algorithm>
#include <cmath>

namespace camwb::cli {

namespace {

// The largest value and the time it was reached.
nlohmann::json extreme(const std::vector<double>& values, const sim::Trace& trace)
{
    if (values.empty())
        return nlohmann::json();
    const auto it = std::max_element(values.begin(), values.end());
    return {{"mm", *it}, {"timeSeconds", trace[static_cast<std::size_t>(it - values.begin())].time}};
}

}  // namespace

nlohmann::json analysisReport(const sim::Trace& trace, const kinematics::KinematicChain& chain)
{
    nlohmann::json report;
    const bool rotaries = chain.fiveAxis();
    const sim::PathAnalysis analysis = sim::analysePath(trace, chain);
    nlohmann::json reversals;
    const char* linear[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 5; ++axis) {
        if (axis >= 3 && !rotaries)
            break;
        const std::string name = axis < 3 ? linear[axis] : chain.joints[axis - 3].axis;
        nlohmann::json times = nlohmann::json::array();
        for (std::size_t sample : analysis.reversals[axis])
            times.push_back(trace[sample].time);
        reversals[name] = times;
    }
    report["reversals"] = reversals;
    const std::vector<double>& feed = analysis.tipFeed.value;
    report["maxTipFeedMmPerMin"] = feed.empty() ? 0.0 : *std::max_element(feed.begin(), feed.end()) * 60;
    // Seed 003 eqs. 23-26: the largest part of the tip's feed each rotary axis makes (|ω|·r).
    if (rotaries) {
        nlohmann::json rotary;
        for (int j = 0; j < 2; ++j) {
            double top = 0;
            for (double v : analysis.rotaryTipSpeed[j].value)
                top = std::max(top, std::abs(v));
            rotary[chain.joints[j].axis] = top * 60;
        }
        report["maxRotaryTipFeedMmPerMin"] = rotary;
    }
    return report;
}

base::Result<nlohmann::json> measuredReport(const std::string& path, const kinematics::Machine& machine,
                                            const sim::MoveList& program, double spindleFaceToTipMm)
{
    auto measured = sim::loadMeasuredTrace(path);
    if (!measured)
        return measured.error();
    const sim::MeasuredTrace& m = measured.value();
    const sim::Trace nominal = sim::workpieceTrace(m, false, machine.kinematics, spindleFaceToTipMm);
    const sim::Trace actual = sim::workpieceTrace(m, true, machine.kinematics, spindleFaceToTipMm);
    nlohmann::json report;
    report["file"] = path;
    report["samples"] = actual.size();
    report["seconds"] = actual.empty() ? 0.0 : actual.back().time - actual.front().time;
    report["maxFollowingDeviation"] = extreme(sim::deviationDistance(nominal, actual), actual);
    report["maxDistanceToProgram"] = extreme(sim::distanceToPath(actual, program), actual);
    report.update(analysisReport(actual, machine.kinematics));
    return report;
}

}  // namespace camwb::cli
