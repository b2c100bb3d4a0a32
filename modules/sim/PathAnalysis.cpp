#include "sim/PathAnalysis.h"

#include <cmath>
#include <limits>

namespace camwb::sim {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

double valueOf(const TraceSample& s, Channel axis)
{
    switch (axis) {
    case Channel::X:
        return s.linear.x;
    case Channel::Y:
        return s.linear.y;
    case Channel::Z:
        return s.linear.z;
    case Channel::Rotary0:
        return s.rotaryDeg[0] * kDegToRad;
    case Channel::Rotary1:
        return s.rotaryDeg[1] * kDegToRad;
    }
    return 0;
}

// |(a, b, c)| per index of three aligned series.
Series magnitude(const std::array<Series, 3>& parts)
{
    Series m{parts[0].firstSample, parts[0].time, {}};
    m.value.resize(parts[0].value.size());
    for (std::size_t k = 0; k < m.value.size(); ++k)
        m.value[k] = std::hypot(parts[0].value[k], parts[1].value[k], parts[2].value[k]);
    return m;
}

}  // namespace

Series derivative(const Series& s, Difference kind)
{
    Series d;
    d.firstSample = s.firstSample + 1;
    const std::size_t n = s.value.size();
    if (n < 2)
        return d;
    const bool central = kind == Difference::Central && n >= 3;
    const std::size_t count = n - 1;
    d.time.reserve(count);
    d.value.reserve(count);
    if (central) {
        // Central: n−2 values at samples 1..n−2; the last one repeats the backward value at n−1 so
        // that both kinds give the same length and alignment (seed 003's n−1, n−2).
        for (std::size_t k = 1; k + 1 < n; ++k) {
            d.time.push_back(s.time[k]);
            d.value.push_back((s.value[k + 1] - s.value[k - 1]) / (s.time[k + 1] - s.time[k - 1]));
        }
        d.time.push_back(s.time[n - 1]);
        d.value.push_back((s.value[n - 1] - s.value[n - 2]) / (s.time[n - 1] - s.time[n - 2]));
        return d;
    }
    for (std::size_t k = 1; k < n; ++k) {
        d.time.push_back(s.time[k]);
        d.value.push_back((s.value[k] - s.value[k - 1]) / (s.time[k] - s.time[k - 1]));
    }
    return d;
}

Series channel(const Trace& trace, Channel axis)
{
    Series s;
    s.time.reserve(trace.size());
    s.value.reserve(trace.size());
    for (const TraceSample& sample : trace) {
        s.time.push_back(sample.time);
        s.value.push_back(valueOf(sample, axis));
    }
    return s;
}

std::vector<std::size_t> reversals(const Series& velocity, double deadBand)
{
    std::vector<std::size_t> found;
    int lastSign = 0;  // the last direction outside the dead band; 0: none yet
    for (std::size_t k = 0; k < velocity.value.size(); ++k) {
        const double v = velocity.value[k];
        if (!(std::abs(v) > deadBand))
            continue;  // a stop (or noise) keeps the last direction: stop-and-continue is no reversal
        const int sign = v > 0 ? 1 : -1;
        if (lastSign != 0 && sign != lastSign)
            found.push_back(velocity.firstSample + k - 1);
        lastSign = sign;
    }
    return found;
}

Series tipFeed(const Trace& trace, Difference kind)
{
    std::array<Series, 3> parts;
    for (int c = 0; c < 3; ++c) {
        Series p;
        for (const TraceSample& s : trace) {
            p.time.push_back(s.time);
            p.value.push_back(c == 0 ? s.tip.x : c == 1 ? s.tip.y : s.tip.z);
        }
        parts[c] = derivative(p, kind);
    }
    return magnitude(parts);
}

PathAnalysis analysePath(const Trace& trace, bool rotaries, const AnalysisOptions& options)
{
    PathAnalysis a;
    for (int c = 0; c < 3; ++c) {
        a.linearVelocity[c] = derivative(channel(trace, Channel(c)), options.difference);
        a.linearAcceleration[c] = derivative(a.linearVelocity[c], options.difference);
        a.reversals[c] = reversals(a.linearVelocity[c], options.reversal.linearDeadBand);
    }
    a.pathSpeed = magnitude(a.linearVelocity);
    a.pathAcceleration = magnitude(a.linearAcceleration);
    a.tipFeed = tipFeed(trace, options.difference);
    if (!rotaries || trace.size() < 2)
        return a;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int j = 0; j < 2; ++j) {
        const Channel axis = j == 0 ? Channel::Rotary0 : Channel::Rotary1;
        a.rotaryVelocity[j] = derivative(channel(trace, axis), options.difference);
        a.rotaryAcceleration[j] = derivative(a.rotaryVelocity[j], options.difference);
        a.reversals[3 + j] = reversals(a.rotaryVelocity[j], options.reversal.rotaryDeadBand);
        a.rotationPerTravel[j].firstSample = 1;
    }
    a.rotationPerTravelCombined.firstSample = 1;
    for (std::size_t k = 1; k < trace.size(); ++k) {
        const double s = base::distance(trace[k].tip, trace[k - 1].tip);
        const double d0 = (trace[k].rotaryDeg[0] - trace[k - 1].rotaryDeg[0]) * kDegToRad;
        const double d1 = (trace[k].rotaryDeg[1] - trace[k - 1].rotaryDeg[1]) * kDegToRad;
        const bool defined = s >= options.minTravelMm;
        const double t = trace[k].time;
        a.rotationPerTravel[0].time.push_back(t);
        a.rotationPerTravel[0].value.push_back(defined ? d0 / s : nan);
        a.rotationPerTravel[1].time.push_back(t);
        a.rotationPerTravel[1].value.push_back(defined ? d1 / s : nan);
        a.rotationPerTravelCombined.time.push_back(t);
        a.rotationPerTravelCombined.value.push_back(defined ? std::hypot(d0, d1) / s : nan);
    }
    return a;
}

PathAnalysis analysePath(const Trace& trace, const kinematics::KinematicChain& chain, const AnalysisOptions& options)
{
    PathAnalysis a = analysePath(trace, chain.fiveAxis(), options);
    if (!chain.fiveAxis())
        return a;
    for (int j = 0; j < 2; ++j) {
        const Series& omega = a.rotaryVelocity[j];
        Series& v = a.rotaryTipSpeed[j];
        v.firstSample = omega.firstSample;
        v.time = omega.time;
        v.value.resize(omega.value.size());
    }
    // ω is aligned to a sample (the later one of a backward step, the middle of a central one):
    // r is taken at that same sample's pose.
    for (std::size_t k = 0; k < a.rotaryVelocity[0].value.size(); ++k) {
        const TraceSample& s = trace[a.rotaryVelocity[0].firstSample + k];
        const std::array<double, 2> r = kinematics::tipRadii(chain, {s.linear, s.rotaryDeg}, s.toolLengthMm);
        for (int j = 0; j < 2; ++j)
            a.rotaryTipSpeed[j].value[k] = a.rotaryVelocity[j].value[k] * r[j];
    }
    return a;
}

}  // namespace camwb::sim
