#include "gui/sim/SimAnalysis.h"

#include "kinematics/Machine.h"
#include "sim/MotionSamples.h"
#include "sim/PathAnalysis.h"
#include "sim/ToolShape.h"

#include <algorithm>
#include <cmath>

namespace camwb::gui {

namespace {

// Samples kept at most (about 70 MB of trace): beyond it the step grows.
constexpr double kMaxSamples = 1e6;
constexpr double kSeedStepSeconds = 0.003;
constexpr int kCutterSteps = 24;

SampledQuantity quantity(std::string id, std::string label, const sim::Series& series,
                         std::vector<std::size_t> reversals = {})
{
    return {std::move(id), std::move(label), series.firstSample, series.time, series.value, std::move(reversals)};
}

// Every axis' reversals, in sample order.
std::vector<std::size_t> allReversals(const sim::PathAnalysis& a)
{
    std::vector<std::size_t> all;
    for (const auto& axis : a.reversals)
        all.insert(all.end(), axis.begin(), axis.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

std::vector<SampledQuantity> quantitiesOf(const sim::PathAnalysis& a, const kinematics::Machine& machine)
{
    std::vector<SampledQuantity> q;
    const char* axes[3]{"X", "Y", "Z"};
    const char* ids[3]{"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        q.push_back(quantity(std::string("v") + ids[i], std::string("v") + axes[i] + " (mm/s)", a.linearVelocity[i],
                             a.reversals[i]));
    for (int i = 0; i < 3; ++i)
        q.push_back(quantity(std::string("a") + ids[i], std::string("a") + axes[i] + " (mm/s²)",
                             a.linearAcceleration[i], a.reversals[i]));
    q.push_back(quantity("tipFeed", "tip feed (mm/s)", a.tipFeed, allReversals(a)));
    q.push_back(quantity("pathSpeed", "path speed (mm/s)", a.pathSpeed, allReversals(a)));
    q.push_back(quantity("pathAcceleration", "path acceleration (mm/s²)", a.pathAcceleration, allReversals(a)));
    const auto& joints = machine.kinematics.joints;
    for (std::size_t r = 0; r < joints.size() && r < 2; ++r) {
        const std::string axis = joints[r].axis;
        q.push_back(
            quantity("omega" + std::to_string(r), "ω " + axis + " (rad/s)", a.rotaryVelocity[r], a.reversals[3 + r]));
        q.push_back(quantity("alpha" + std::to_string(r), "α " + axis + " (rad/s²)", a.rotaryAcceleration[r],
                             a.reversals[3 + r]));
        q.push_back(quantity("n" + std::to_string(r), "N " + axis + " (rad/mm)", a.rotationPerTravel[r]));
        q.push_back(
            quantity("vRotary" + std::to_string(r), "v_" + axis + " (mm/s)", a.rotaryTipSpeed[r], a.reversals[3 + r]));
    }
    // N is undefined (NaN) where the tip stands; those samples are left out of the colour range.
    for (SampledQuantity& s : q)
        for (double& v : s.values)
            if (!std::isfinite(v))
                v = 0;
    q.erase(std::remove_if(q.begin(), q.end(), [](const SampledQuantity& s) { return s.values.empty(); }), q.end());
    return q;
}

}  // namespace

std::optional<SimAnalysis> analyseMotion(const sim::MoveList& moves, const sim::MotionPlan& plan,
                                         const kinematics::Machine& machine, const std::atomic<bool>* cancel)
{
    SimAnalysis analysis;
    analysis.stepSeconds = std::max(kSeedStepSeconds, plan.totalSeconds / kMaxSamples);
    sim::Trace trace;
    trace.reserve(static_cast<std::size_t>(plan.totalSeconds / analysis.stepSeconds) + 2);
    bool stopped = false;
    sim::sampleMotion(moves, plan, machine,
                      [&](const sim::MotionSample& sample) {
                          trace.push_back(sample.at);
                          stopped = cancel != nullptr && (trace.size() % 4096) == 0 && cancel->load();
                          return !stopped;
                      },
                      {analysis.stepSeconds});
    if (stopped)
        return std::nullopt;
    const sim::PathAnalysis result = sim::analysePath(trace, machine.kinematics);
    analysis.tip.reserve(trace.size());
    for (const sim::TraceSample& sample : trace)
        analysis.tip.push_back(sample.tip);
    analysis.quantities = quantitiesOf(result, machine);
    return analysis;
}

std::vector<RevolvedPart> revolvedParts(const sim::ToolShape& shape)
{
    std::vector<RevolvedPart> parts;
    // The cutter: its outline sampled densely near the tip (ball, corner, point), closed on the axis.
    RevolvedPart cutter{{{0.0, 0.0}}, {0.85f, 0.62f, 0.15f}};
    const double flute = std::max(shape.fluteLengthMm(), 1e-3);
    for (int i = 0; i <= kCutterSteps; ++i) {
        const double h = flute * std::pow(static_cast<double>(i) / kCutterSteps, 2.0);
        cutter.profile.emplace_back(shape.profileRadius(std::min(h, flute - 1e-9)), h);
    }
    cutter.profile.emplace_back(0.0, flute);
    parts.push_back(cutter);
    if (shape.stickOutMm() > flute)
        parts.push_back({{{0.0, flute},
                          {shape.shankRadiusMm(), flute},
                          {shape.shankRadiusMm(), shape.stickOutMm()},
                          {0.0, shape.stickOutMm()}},
                         {0.62f, 0.64f, 0.68f}});
    double h = shape.stickOutMm();
    for (const sim::HolderStep& step : shape.holder().steps) {
        const double r = step.diameterMm / 2;
        parts.push_back({{{0.0, h}, {r, h}, {r, h + step.lengthMm}, {0.0, h + step.lengthMm}}, {0.25f, 0.30f, 0.40f}});
        h += step.lengthMm;
    }
    return parts;
}

}  // namespace camwb::gui
