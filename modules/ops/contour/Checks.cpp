#include "ops/contour/Checks.h"

#include "base/NumberFormat.h"

#include <cmath>

namespace camwb::ops::contour {

namespace {

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

const char* sideName(ContourSide side)
{
    switch (side) {
    case ContourSide::Outside:
        return "outside";
    case ContourSide::Inside:
        return "inside";
    case ContourSide::On:
        return "on";
    case ContourSide::Left:
        return "left";
    case ContourSide::Right:
        return "right";
    }
    return "?";
}

base::Status checkGeometry(const std::vector<geom::Profile>& contours, const ContourParams& p)
{
    const std::string w = what(p);
    if (contours.empty())
        return opError(w, "nothing to cut: no contour or edge chain selected");
    for (std::size_t i = 0; i < contours.size(); ++i) {
        const geom::Profile& c = contours[i];
        const std::string name = "contour " + std::to_string(i + 1);
        if (c.empty())
            return opError(w, name + " is empty");
        if (!c.isContinuous())
            return opError(w, name + " is not continuous: consecutive segments do not meet");
        const bool loopSide = p.side == ContourSide::Outside || p.side == ContourSide::Inside;
        const bool chainSide = p.side == ContourSide::Left || p.side == ContourSide::Right;
        if (c.closed && chainSide)
            return opError(w, std::string("side ") + sideName(p.side) + " is for open edge chains, but " + name +
                                  " is a closed loop: use outside, inside or on");
        if (!c.closed && loopSide)
            return opError(w, std::string("side ") + sideName(p.side) + " needs a closed loop, but " + name +
                                  " is an open edge chain: use left, right or on");
    }
    return base::Status::success();
}

constexpr double kMaxLeadDiameters = 100;

base::Status checkParameters(const ContourParams& p, const ToolController& tc)
{
    const std::string w = what(p);
    const double toolRadius = tc.tool.diameterMm / 2;
    const double depth = p.heights.startZ - p.heights.finalZ;
    if (p.stepDownMm < 0)
        return opError(w, "step-down must not be negative, got " + fmt(p.stepDownMm) + " mm");
    if (p.radialStockMm < 0 || p.axialStockMm < 0)
        return opError(w, "stock to leave must not be negative");
    if (depth > 0 && p.axialStockMm >= depth - 1e-9)
        return opError(w, "axial stock " + fmt(p.axialStockMm) + " mm leaves nothing of the " + fmt(depth) +
                              " mm depth to cut");
    if (base::Status s = checkRepeats(w, "step-down", p.stepDownMm, depth - p.axialStockMm, "levels"); !s)
        return s;
    if (p.radialPasses < 1)
        return opError(w, "radial passes must be at least 1, got " + std::to_string(p.radialPasses));
    if (p.radialPasses > 1 && !(p.radialStepoverMm > 0))
        return opError(w, "radial stepover must be positive for " + std::to_string(p.radialPasses) + " passes");
    const bool leads = p.leadIn != LeadKind::None || p.leadOut != LeadKind::None;
    if (leads && !(p.leadRadiusMm > 0))
        return opError(w, "lead radius/length must be positive, got " + fmt(p.leadRadiusMm) + " mm");
    // A lead is a short approach; a far larger one is a slip (1e9 for 10), whose clearance check
    // alone would sample it for hours.
    if (leads && p.leadRadiusMm > kMaxLeadDiameters * 2 * toolRadius)
        return opError(w, "lead radius/length " + fmt(p.leadRadiusMm) + " mm is more than " + fmt(kMaxLeadDiameters) +
                              " tool diameters (" + fmt(kMaxLeadDiameters * 2 * toolRadius) + " mm)");
    if (p.entry == EntryKind::Ramp && !(p.rampAngleDeg > 0 && p.rampAngleDeg <= 90))
        return opError(w, "ramp angle must be above 0 and at most 90 degrees, got " + fmt(p.rampAngleDeg));
    if (p.entry == EntryKind::Helix) {
        if (p.helixDiameterMm < 0)
            return opError(w, "helix diameter must not be negative, got " + fmt(p.helixDiameterMm) + " mm");
        if (!(p.helixPitchMm > 0))
            return opError(w, "helix pitch must be positive, got " + fmt(p.helixPitchMm) + " mm");
        if (base::Status s = checkRepeats(w, "helix pitch", p.helixPitchMm, depth, "turns"); !s)
            return s;
    }
    if (p.tabCount < 0)
        return opError(w, "tab count must not be negative, got " + std::to_string(p.tabCount));
    if (p.tabCount > 0) {
        if (!(p.tabWidthMm > 0))
            return opError(w, "tab width must be positive, got " + fmt(p.tabWidthMm) + " mm");
        if (!(p.tabHeightMm > 0))
            return opError(w, "tab height must be positive, got " + fmt(p.tabHeightMm) + " mm");
        if (p.tabHeightMm >= depth)
            return opError(w, "tab height " + fmt(p.tabHeightMm) + " mm reaches the start depth (cut depth " +
                                  fmt(depth) + " mm)");
    }
    if (p.compensation == CompensationOutput::Control) {
        if (p.side == ContourSide::On)
            return opError(w, "cutter compensation needs a side: on the contour there is nothing to compensate");
        if ((p.leadIn == LeadKind::Arc || p.leadOut == LeadKind::Arc) && p.leadRadiusMm <= toolRadius)
            return opError(w, "with cutter compensation the lead arc radius " + fmt(p.leadRadiusMm) +
                                  " mm must be larger than the tool radius " + fmt(toolRadius) + " mm");
    }
    if (!(p.toleranceMm > 0))
        return opError(w, "tolerance must be positive, got " + fmt(p.toleranceMm) + " mm");
    return base::Status::success();
}

}  // namespace

std::string what(const ContourParams& params) { return "contour \"" + params.name + "\""; }

base::Status checkContourInput(const std::vector<geom::Profile>& contours, const ContourParams& params,
                               const ToolController& tc)
{
    const std::string w = what(params);
    if (base::Status s = checkToolController(w, tc); !s)
        return s;
    if (base::Status s = checkHeights(w, params.heights); !s)
        return s;
    if (base::Status s = checkCuttingLength(w, params.heights, tc.tool); !s)
        return s;
    if (base::Status s = checkGeometry(contours, params); !s)
        return s;
    return checkParameters(params, tc);
}

}  // namespace camwb::ops::contour
