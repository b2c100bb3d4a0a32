// Groove roughing on a lathe by side-stepping plunges: the strategy of Šolar (2015) for SINUMERIK
// 840D (../shared/reference seed-001), made safe. Staircase sweeps left to right and back, each
// plunge one infeed deeper than the last, flank contact plunges and clean-ups along the offset
// flanks, then a bottom phase; the allowances stay for a finishing operation.
// The CL is in the XZ plane: X is a radius, Y is 0 and never given, Z along the spindle. The
// insert's reference point is its left (-Z) corner, as the thesis programs it.
#pragma once

#include "ops/OpCommon.h"
#include "sim/TurningProfile.h"

#include <string>

namespace camwb::ops {

struct GrooveParams {
    std::string name = "Groove";
    // The groove and its allowances: the thesis' R0..R8 (Kod 1 by default). Its r9 (insert
    // width) is not read: the width is the tool's (Tool::kind "groove", diameterMm = width).
    sim::GrooveParameters groove;
    double stepFactor = 0.8;      // R10: axial step = stepFactor * insert width, 0 < f <= 1
    double infeedMm = 1;          // R11: each plunge this much deeper than the one before
    double safetyMm = 1;          // R30: clearance of every retract over the material
    double finalRetractMm = 100;  // the last rapid goes to X = R0 + this (the thesis' R0+100)
    // Cutting data as the thesis' Kod 5 frame has it: G96 S, LIMS, G95 F.
    double surfaceSpeedMPerMin = 300;
    double maxRpm = 3000;
    double feedMmPerRev = 0.2;
    bool coolant = true;
};

// Records (each with SourceRef{operationIndex, i}): SectionBegin{name, "groove-roughing", tool,
// feeds.cutting = feedMmPerRev, strategyParameters R0..R11, R30 and "fallback" (1 where the
// narrow-groove fallback was used, else 0)}; FeedModeChange{PerRevolution}; Spindle{rpm = maxRpm,
// clockwise, surfaceSpeedMPerMin}; Coolant{Flood} when coolant; Rapid X (safe: R0 + finalRetract)
// then the strategy's moves, every Rapid along one axis only (AxisMask kX or kZ), every Linear in
// X and Z (never Y); the last Rapid to X = R0 + finalRetractMm; SectionEnd.
// Errors (nothing produced): each invalid input by name and R name (REQ-06; fixes F6 and V1 of
// docs/groove-strategy.md), a tool that is not a grooving insert, an offset
// bottom narrower than the insert, a strategy that does not finish (iteration limit, REQ-25).
// The moves are ops/turning/GrooveSweeps: with Kod 1 block by block the thesis' program.
base::Result<OpResult> computeGroove(const GrooveParams& params, const ToolController& tc, int operationIndex,
                                     const Progress& progress = {});

}  // namespace camwb::ops
