// The five-axis path analysis of seed 003 on any time-sampled trace, simulated (MotionSamples) or
// measured (MeasuredTrace): axis velocities and accelerations by finite differences (the thesis'
// backward differences by default), path speed, rotary ω and α, the tool-tip feed relative to the
// workpiece and its parts from the rotary axes (v_A, v_C), the rotation per unit of tip travel N,
// and axis reversals.
#pragma once

#include "base/Vec.h"
#include "kinematics/KinematicChain.h"

#include <array>
#include <cstddef>
#include <vector>

namespace camwb::sim {

using base::Vec3;

// One instant: the machine's axes (linear in mm, the chain's two rotaries in degrees; a
// three-axis machine leaves them 0) and the tool tip in the workpiece frame.
struct TraceSample {
    double time = 0;
    Vec3 linear;
    std::array<double, 2> rotaryDeg{0, 0};
    Vec3 tip;
    // The tool's length where a head turns the tool about a pivot above its tip (0 otherwise, and
    // for a measured trace, whose Z is already the tip's).
    double toolLengthMm = 0;
};
using Trace = std::vector<TraceSample>;

// A derived quantity: value[k] belongs to trace sample firstSample + k (and its time).
struct Series {
    std::size_t firstSample = 0;
    std::vector<double> time;
    std::vector<double> value;
};

enum class Difference {
    Backward,  // (x[k] − x[k−1]) / (t[k] − t[k−1]) at t[k]: seed 003 eqs. 11-22
    Central,   // (x[k+1] − x[k−1]) / (t[k+1] − t[k−1]) at t[k]: not in the thesis, smoother
};

// The derivative of `s` (a series of positions, or of velocities for an acceleration). Both kinds
// shorten the series by one sample, so velocities start at sample 1 and accelerations at sample 2
// either way (Backward: aligned to the later sample as in the thesis; Central: to the middle one).
Series derivative(const Series& s, Difference kind = Difference::Backward);

enum class Channel { X, Y, Z, Rotary0, Rotary1 };  // rotaries in KinematicChain::joints order
// A machine axis of the trace as a series (rotaries in radians, so derivatives come in rad/s).
Series channel(const Trace& trace, Channel axis);

struct ReversalOptions {
    // Velocities at or below these are a stop, not a direction. TNCscope records 0.1 µm and
    // 0.0001° steps: one step in 3 ms reads as 0.033 mm/s or 0.00058 rad/s, so the defaults lie
    // just above that quantisation noise.
    double linearDeadBand = 0.05;   // mm/s
    double rotaryDeadBand = 0.001;  // rad/s
};

// Samples where `velocity` reverses (seed 003 §6 item 11): its sign differs from the last sign
// outside the dead band; a stop between opposite signs counts once, a stop followed by the same
// direction is no reversal. The new direction first shows in the velocity of the step from one
// sample to the next; the reversal is placed at the first of those two, the sample the axis
// leaves in the new direction (the turning point within one step, or the last sample of a stop),
// which is where a marker on the path belongs. Trace sample indices.
std::vector<std::size_t> reversals(const Series& velocity, double deadBand);

struct AnalysisOptions {
    Difference difference = Difference::Backward;
    ReversalOptions reversal;
    // Below this tip travel (mm) between two samples N is undefined (a rotation in place): NaN.
    double minTravelMm = 1e-6;
};

struct PathAnalysis {
    std::array<Series, 3> linearVelocity;      // X Y Z, mm/s (eqs. 11-13)
    std::array<Series, 3> linearAcceleration;  // mm/s² (eqs. 15-17)
    Series pathSpeed;                          // |v| of X Y Z, mm/s (eq. 14: machine frame)
    Series pathAcceleration;                   // |a|, mm/s² (eq. 18)
    std::array<Series, 2> rotaryVelocity;      // ω, rad/s (eqs. 19-20)
    std::array<Series, 2> rotaryAcceleration;  // α, rad/s² (eqs. 21-22)
    Series tipFeed;                            // |Δtip / Δt| in the workpiece frame, mm/s (§6 item 10)
    std::array<Series, 2> rotationPerTravel;   // N per rotary, rad/mm (§6 item 12); NaN: undefined
    Series rotationPerTravelCombined;          // sqrt(Δ0² + Δ1²) / s, rad/mm
    // The tip's speed relative to the workpiece that each rotary axis makes alone: ω·r, r the
    // tip's distance from that axis at the sample (seed 003 eqs. 23-26: v_A, v_C), mm/s, signed
    // as ω; aligned with rotaryVelocity. Empty without a chain.
    std::array<Series, 2> rotaryTipSpeed;
    std::array<std::vector<std::size_t>, 5> reversals;  // per Channel, trace sample indices
};

// Everything above but rotaryTipSpeed for `trace`; `rotaries` false (a three-axis machine)
// leaves the rotary quantities empty.
PathAnalysis analysePath(const Trace& trace, bool rotaries, const AnalysisOptions& options = {});
// Everything, on the machine whose chain made the trace (its rotaries, their axes for v_A, v_C).
PathAnalysis analysePath(const Trace& trace, const kinematics::KinematicChain& chain,
                         const AnalysisOptions& options = {});

// The tip's feed relative to the workpiece from the tips alone (what analysePath's tipFeed holds).
Series tipFeed(const Trace& trace, Difference kind = Difference::Backward);

}  // namespace camwb::sim
