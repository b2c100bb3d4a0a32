// The parameters of each operation kind as a list of named fields, so that reading and writing a
// .camwb file walk the same list and cannot drift apart. `visitFields(params, f)` calls f(key, member)
// for plain members (double, int, bool, std::string) and f(key, EnumField{...}) for enums.
// `fieldAliases(params)` gives other names a field is also read by (the groove's R names).
#pragma once

#include "ops/ContourOp.h"
#include "ops/DrillOp.h"
#include "ops/GrooveOp.h"
#include "ops/HelixOp.h"
#include "ops/ParallelOp.h"
#include "ops/Pocket3dOp.h"
#include "ops/PocketOp.h"
#include "ops/SwarfOp.h"
#include "ops/WaterlineOp.h"

#include <initializer_list>
#include <span>
#include <string_view>

namespace camwb::document::detail {

// An enum member with its names in the file, in enum order.
template <class E> struct EnumField {
    E& value;
    std::initializer_list<std::string_view> names;
};

template <class E> EnumField<E> enumField(E& e, std::initializer_list<std::string_view> names) { return {e, names}; }

template <class T> inline constexpr bool kIsEnumField = false;
template <class E> inline constexpr bool kIsEnumField<EnumField<E>> = true;

template <class F> void visitFields(ops::ContourParams& p, F&& f)
{
    f("side", enumField(p.side, {"outside", "inside", "on", "left", "right"}));
    f("climb", p.climb);
    f("radialStock", p.radialStockMm);
    f("axialStock", p.axialStockMm);
    f("stepDown", p.stepDownMm);
    f("radialPasses", p.radialPasses);
    f("radialStepover", p.radialStepoverMm);
    f("leadIn", enumField(p.leadIn, {"none", "arc", "line"}));
    f("leadOut", enumField(p.leadOut, {"none", "arc", "line"}));
    f("leadRadius", p.leadRadiusMm);
    f("entry", enumField(p.entry, {"plunge", "ramp", "helix"}));
    f("rampAngle", p.rampAngleDeg);
    f("helixDiameter", p.helixDiameterMm);
    f("helixPitch", p.helixPitchMm);
    f("tabCount", p.tabCount);
    f("tabWidth", p.tabWidthMm);
    f("tabHeight", p.tabHeightMm);
    f("compensation", enumField(p.compensation, {"toolCentre", "control"}));
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::PocketParams& p, F&& f)
{
    f("pattern", enumField(p.pattern, {"offset", "zigzag"}));
    f("zigZagAngle", p.zigZagAngleDeg);
    f("stepoverPercent", p.stepoverPercent);
    f("stepover", p.stepoverMm);
    f("stepDown", p.stepDownMm);
    f("wallStock", p.wallStockMm);
    f("floorStock", p.floorStockMm);
    f("finishWalls", p.finishWalls);
    f("finishFloor", p.finishFloor);
    f("climb", p.climb);
    f("entry", enumField(p.entry, {"plunge", "ramp", "helix"}));
    f("helixDiameter", p.helixDiameterMm);
    f("helixPitch", p.helixPitchMm);
    f("rampAngle", p.rampAngleDeg);
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::HelixParams& p, F&& f)
{
    f("depthsFromHoles", p.depthsFromHoles);
    f("pitch", p.pitchMm);
    f("climb", p.climb);
    f("radialStock", p.radialStockMm);
    f("finishingCircle", p.finishingCircle);
    f("breakthrough", p.breakthroughMm);
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::DrillParams& p, F&& f)
{
    // CycleKind also has Tap and Bore, which drilling does not offer: the names stop at chipBreak.
    f("cycle", enumField(p.cycle, {"drill", "dwell", "peck", "chipBreak"}));
    f("depthsFromHoles", p.depthsFromHoles);
    f("peck", p.peckMm);
    f("dwell", p.dwellSeconds);
    f("retractToClearance", p.retractToClearance);
    f("keepOrder", p.keepOrder);
    f("depthAtShoulder", p.depthAtShoulder);
    f("breakthrough", p.breakthroughMm);
}

template <class F> void visitFields(ops::SwarfParams& p, F&& f)
{
    f("climb", p.climb);
    f("axialOffset", p.axialOffsetMm);
    f("radialStock", p.radialStockMm);
    f("radialPasses", p.radialPasses);
    f("radialStepover", p.radialStepoverMm);
    f("chordTolerance", p.chordToleranceMm);
    f("angleTolerance", p.angleToleranceDeg);
    f("gougeTolerance", p.gougeToleranceMm);
}

template <class F> void visitFields(ops::Pocket3dParams& p, F&& f)
{
    f("pattern", enumField(p.pattern, {"offset", "zigzag"}));
    f("zigZagAngle", p.zigZagAngleDeg);
    f("stepoverPercent", p.stepoverPercent);
    f("stepover", p.stepoverMm);
    f("stepDown", p.stepDownMm);
    f("sideStock", p.sideStockMm);
    f("bottomStock", p.bottomStockMm);
    f("climb", p.climb);
    f("entry", enumField(p.entry, {"plunge", "ramp", "helix"}));
    f("helixDiameter", p.helixDiameterMm);
    f("helixPitch", p.helixPitchMm);
    f("rampAngle", p.rampAngleDeg);
    f("restMachining", p.restMachining);
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::WaterlineParams& p, F&& f)
{
    f("scallop", p.scallopMm);
    f("maxStepDown", p.maxStepDownMm);
    f("minSlope", p.minSlopeDeg);
    f("stock", p.stockMm);
    f("climb", p.climb);
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::ParallelParams& p, F&& f)
{
    f("stepover", p.stepoverMm);
    f("angle", p.angleDeg);
    f("maxSlope", p.maxSlopeDeg);
    f("stock", p.stockMm);
    f("zigZag", p.zigZag);
    f("tolerance", p.toleranceMm);
}

template <class F> void visitFields(ops::GrooveParams& p, F&& f)
{
    // The groove's R9 (insert width) is the tool's diameter, not a field: one width per insert.
    f("startX", p.groove.r0);
    f("startZ", p.groove.r1);
    f("coneAngle", p.groove.r2);
    f("depth", p.groove.r3);
    f("bottomWidth", p.groove.r4);
    f("rightFlankAngle", p.groove.r5);
    f("leftFlankAngle", p.groove.r6);
    f("bottomAllowance", p.groove.r7);
    f("flankAllowance", p.groove.r8);
    f("stepFactor", p.stepFactor);
    f("infeed", p.infeedMm);
    f("safety", p.safetyMm);
    f("finalRetract", p.finalRetractMm);
    f("surfaceSpeed", p.surfaceSpeedMPerMin);
    f("maxRpm", p.maxRpm);
    f("feedPerRev", p.feedMmPerRev);
    f("coolant", p.coolant);
}

// Another name a field is read by (never written): the thesis' R-parameter for the groove.
struct FieldAlias {
    std::string_view alias;
    std::string_view key;
};

inline constexpr FieldAlias kGrooveAliases[] = {
    {"R0", "startX"},         {"R1", "startZ"},          {"R2", "coneAngle"},      {"R3", "depth"},
    {"R4", "bottomWidth"},    {"R5", "rightFlankAngle"}, {"R6", "leftFlankAngle"}, {"R7", "bottomAllowance"},
    {"R8", "flankAllowance"}, {"R10", "stepFactor"},     {"R11", "infeed"},        {"R30", "safety"},
};

template <class Params> std::span<const FieldAlias> fieldAliases(const Params&) { return {}; }
inline std::span<const FieldAlias> fieldAliases(const ops::GrooveParams&) { return kGrooveAliases; }

}  // namespace camwb::document::detail
