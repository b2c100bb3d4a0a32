// The groove roughing strategy of Šolar (2015) as moves: the five subprograms of seed-001 §4.3
// (PODPROG_ZAPICH, _ZL, _ZP, _DNO_ZL, _DNO_ZP) transliterated with their R-parameters as names,
// and the fixes of docs/groove-strategy.md (F2 left corner in DNO_ZP, F3 clamped half-step start, F4 stop
// after a bottom phase, F5 narrow-groove fallback; G1 gap before a
// flank plunge, G2 fallback when B is at the bottom, G3/G5 rapids that rise over the material,
// G4 retracts of a clamped bottom sweep). Kept apart from the CL records so that the mode-B
// subprograms can be read against it line by line.
#pragma once

#include "base/Result.h"
#include "sim/TurningProfile.h"

#include <functional>
#include <string>
#include <vector>

namespace camwb::ops::turning {

// One move of the insert's left corner: a rapid along X or along Z, or a feed move to (x, z).
struct GrooveMove {
    enum class Kind { RapidX, RapidZ, Feed };
    Kind kind = Kind::Feed;
    double x = 0, z = 0;  // a RapidX gives only x, a RapidZ only z; a Feed both
};

// Every strategy loop counts its turns against this; beyond it the strategy stops with an error
// (seed REQ-25) rather than run away, whatever the fixes miss.
inline constexpr long kGrooveIterationLimit = 1000000;

// The strategy's inputs: the groove's geometry and the thesis' R9, R10, R11, R30.
struct GrooveSetup {
    sim::GrooveGeometry geo;
    double widthMm = 3;       // R9: the insert's width (programmed point = its left corner)
    double stepFactor = 0.8;  // R10
    double infeedMm = 1;      // R11
    double safetyMm = 1;      // R30
    long iterationLimit = kGrooveIterationLimit;
};

// One pass of the main loop as PODPROG_ZAPICH computes it (seed REQ-10): the plunge counts and
// the points B (end of the left-to-right sweep, right corner) and the next Rp. l2, r28 and the
// next Rp stay NaN / -1 where the pass did not get that far.
struct GroovePass {
    double l1 = 0;
    long r27 = -1;
    double bx = 0, bz = 0;
    double l2 = 0;
    long r28 = -1;
    double rpx = 0, rpz = 0;
};

struct GrooveMoves {
    std::vector<GrooveMove> moves;
    bool fallback = false;  // the narrow-groove fallback (fix F5, docs/groove-strategy.md) made (part of) the path
    std::vector<GroovePass> passes;
    std::vector<std::string> calls;  // "ZL", "ZP", "DNO_ZL", "DNO_ZP", "FALLBACK" in order
};

// The strategy's moves from the approach (G0 Z=Rz, G0 X=Rx+R9 tan R2+R30) to the end of the
// bottom phase; the caller adds the retracts before and after. `keepGoing(fraction done)` is
// asked once a pass; false stops with the error "cancelled". Errors name `what`.
base::Result<GrooveMoves> grooveMoves(const GrooveSetup& setup, const std::string& what,
                                      const std::function<bool(double)>& keepGoing);

}  // namespace camwb::ops::turning
