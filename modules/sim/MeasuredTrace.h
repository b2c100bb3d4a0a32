// Measured axis traces (Heidenhain TNCscope exported as CSV, seed 003 §3): time plus nominal and
// actual positions of X Y Z and the two rotaries and their following errors; read with a
// configurable column layout and units, carried onto the workpiece through the machine's chain,
// and compared with each other and with the programmed path for the overlay.
#pragma once

#include "base/Result.h"
#include "kinematics/KinematicChain.h"
#include "sim/Moves.h"
#include "sim/PathAnalysis.h"

#include <array>
#include <string>
#include <vector>

namespace camwb::sim {

// Which CSV column (0-based) holds each channel; -1: absent. The default is seed 003's order:
// time, X_nom X_act Y_nom Y_act Z_nom Z_act A_nom A_act C_nom C_act, then the deviations of X Y Z
// A C. The rotaries are the chain's two in KinematicChain::joints order (A/C or B/C).
struct TraceColumns {
    int time = 0;
    std::array<int, 5> nominal{1, 3, 5, 7, 9};
    std::array<int, 5> actual{2, 4, 6, 8, 10};
    std::array<int, 5> deviation{11, 12, 13, 14, 15};
    int headerLines = 1;  // lines before the data (channel names, units)
    // Factors to s, mm and degrees (ms: 0.001; µm: 0.001; radians: 180/π).
    double timeScale = 1;
    double linearScale = 1;
    double rotaryScale = 1;
    // Field separator; 0: ';' if the first data line has one, else a tab if it has one, else ','.
    // With ';' or a tab, a decimal comma ("2,302", as TNCscope writes in Czech) reads as a point.
    char separator = 0;
};

struct MeasuredTrace {
    std::vector<double> time;                    // s
    std::array<std::vector<double>, 5> nominal;  // X Y Z in mm, rotaries in degrees; empty: absent
    std::array<std::vector<double>, 5> actual;
    std::array<std::vector<double>, 5> deviation;
};

// Errors name path:line:column (the field's first character) for a bad number or a missing field.
base::Result<MeasuredTrace> readMeasuredTrace(const std::string& text, const std::string& pathForMessages,
                                              const TraceColumns& columns = {});
base::Result<MeasuredTrace> loadMeasuredTrace(const std::string& path, const TraceColumns& columns = {});

// The nominal (`actual` false) or actual channels as a trace on the workpiece, through
// kinematics::forwardKinematics. `spindleFaceToTipMm`: subtract this from Z first where the
// recorded Z is the spindle face, not the tool tip (seed 003: Z − L). Absent rotaries count 0.
Trace workpieceTrace(const MeasuredTrace& trace, bool actual, const kinematics::KinematicChain& chain,
                     double spindleFaceToTipMm = 0);

// Per sample, the distance between the nominal and the actual tip on the workpiece (mm).
std::vector<double> deviationDistance(const Trace& nominal, const Trace& actual);

// Per sample, the distance from its tip to the nearest programmed move (Rapid or Feed) of
// `program` (mm): how far the measured path lies from the path the program asked for.
std::vector<double> distanceToPath(const Trace& trace, const MoveList& program);

}  // namespace camwb::sim
