#include "ops/contour/Plan.h"

#include "base/NumberFormat.h"
#include "geom/ChainOffset.h"
#include "geom/Offset.h"
#include "ops/contour/Checks.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops::contour {

namespace {

std::string fmt(double v) { return base::NumberFormat{3, true}.format(v); }

MaterialSide materialSide(const geom::Profile& contour, ContourSide side)
{
    switch (side) {
    case ContourSide::Outside:
        return MaterialSide::InsideLoop;
    case ContourSide::Inside:
        return MaterialSide::OutsideLoop;
    case ContourSide::Left:
        return MaterialSide::RightOfChain;
    case ContourSide::Right:
        return MaterialSide::LeftOfChain;
    case ContourSide::On:
        break;
    }
    return MaterialSide::None;
}

// The cutting path `distance` off the contour (ccw if closed) on the tool's side, in the
// direction of climb or conventional milling.
base::Result<Path> passPath(const geom::Profile& contour, ContourSide side, double distance, bool climb)
{
    // Climb with a clockwise spindle keeps the material on the right of travel. On the contour
    // there is no material side: it is cut as if from outside (or left of a chain).
    const bool materialOnRight = side == ContourSide::Inside || (!contour.closed && side != ContourSide::Right);
    base::Result<geom::Profile> off = contour;
    if (distance > 0 && side != ContourSide::On) {
        if (side == ContourSide::Outside)
            off = geom::offsetOutside(contour, distance);
        else if (side == ContourSide::Inside)
            off = geom::offsetInside(contour, distance);
        else
            off = geom::offsetChain(contour, side == ContourSide::Left ? geom::ChainSide::Left : geom::ChainSide::Right,
                                    distance);
    }
    if (!off)
        return off.error();
    Path path;
    path.closed = contour.closed;
    for (const Segment& s : off.value().segments)
        if (s.length() > 1e-9)
            path.segments.push_back(s);
    path.materialOnRight = materialOnRight;
    if (climb != materialOnRight) {
        path.segments = geom::Profile{path.segments, path.closed}.reversed().segments;
        path.materialOnRight = !materialOnRight;
    }
    if (path.closed)
        path.segments = startAtLongestLine(path.segments);
    return path;
}

Vec2 pointAtLength(const Path& path, double s)
{
    const std::vector<Segment> before = piecesBetween(path, 0, s);
    return before.empty() ? path.start() : before.back().end;
}

// Tabs evenly spaced along the innermost pass; outer passes get them at the nearest points.
base::Status placeTabs(LoopPlan& plan, const ContourParams& params, double toolDiameter)
{
    if (params.tabCount == 0)
        return base::Status::success();
    const Path& last = plan.passes.back().cut.path;
    const double length = last.length();
    const double width = params.tabWidthMm + toolDiameter;  // the tool's footprint leaves tabWidth
    if (params.tabCount * width >= length)
        return opError(what(params), std::to_string(params.tabCount) + " tabs of " + fmt(params.tabWidthMm) +
                                         " mm (plus the tool diameter) do not fit on contour " +
                                         std::to_string(plan.index + 1) + " of length " + fmt(length) + " mm");
    for (int k = 0; k < params.tabCount; ++k) {
        const Vec2 centre = pointAtLength(last, (k + 0.5) * length / params.tabCount);
        for (PassPlan& pass : plan.passes) {
            const double s = &pass == &plan.passes.back() ? (k + 0.5) * length / params.tabCount
                                                          : nearestArclength(pass.cut.path, centre);
            pass.tabs.spans.push_back({s - width / 2, s + width / 2});
            pass.tabs.pathLength = pass.cut.path.closed ? pass.cut.path.length() : 0;
        }
    }
    return base::Status::success();
}

}  // namespace

base::Result<LoopPlan> planLoop(const geom::Profile& input, std::size_t index, const ContourParams& params,
                                const ToolController& tc)
{
    const std::string w = what(params);
    const std::string name = "contour " + std::to_string(index + 1);
    const geom::Profile contour = input.closed && input.signedArea() < 0 ? input.reversed() : input;
    const bool control = params.compensation == CompensationOutput::Control;
    const bool on = params.side == ContourSide::On;
    const double toolRadius = tc.tool.diameterMm / 2;
    const double stock = on ? 0 : params.radialStockMm;
    const double toolCentreClearance = on ? 0 : toolRadius + stock;
    // Under compensation the programmed contour is offset by the stock only.
    const double base = stock + (control ? 0 : toolRadius);
    const int passes = on ? 1 : params.radialPasses;
    const double step = std::clamp(toolRadius / 4, 0.05, 2.0);

    LoopPlan plan{index, Material(contour, materialSide(contour, params.side)), {}, toolpath::CutterCompSide::Off};
    for (int k = passes - 1; k >= 0; --k) {
        auto path = passPath(contour, params.side, on ? 0 : base + k * params.radialStepoverMm, params.climb);
        if (!path)
            return opError(w, name + ": " + path.error().message);
        // The exact offset trims locally; a neck narrower than the tool shows here.
        if (base::Status s = checkClear(plan.material, path.value().segments, control ? stock : toolCentreClearance,
                                        step, "the tool path of " + name);
            !s)
            return opError(w, s.error().message + ": tool too large for the feature");
        PassPlan pass;
        pass.cut = withLeads(path.value(), params, control, tc.tool.diameterMm);
        const double leadClearance = control ? stock : toolCentreClearance;
        if (base::Status s = checkClear(plan.material, pass.cut.leadIn, leadClearance, step, "the lead-in of " + name);
            !s)
            return opError(w, s.error().message + ": make the lead smaller");
        if (base::Status s =
                checkClear(plan.material, pass.cut.leadOut, leadClearance, step, "the lead-out of " + name);
            !s)
            return opError(w, s.error().message + ": make the lead smaller");
        if (control) {
            for (Vec2 p : {*pass.cut.approach, *pass.cut.departure})
                if (base::Status s = checkClear(plan.material, {Segment::line(p, p)}, toolCentreClearance, step,
                                                "the compensation approach of " + name);
                    !s)
                    return opError(w, s.error().message);
            plan.compSide =
                path.value().materialOnRight ? toolpath::CutterCompSide::Left : toolpath::CutterCompSide::Right;
        }
        if (params.entry == EntryKind::Helix) {
            const double radius = (params.helixDiameterMm > 0 ? params.helixDiameterMm : tc.tool.diameterMm) / 2;
            for (bool left : {true, false}) {
                Helix h =
                    helixTo(pass.cut.entryPoint(), pass.cut.entryDirection(), left, radius, params.helixPitchMm, 1, 0);
                if (checkClear(plan.material, {h.circle()}, toolCentreClearance, step, "helix")) {
                    pass.helix = h;
                    pass.helixLeft = left;
                    break;
                }
            }
            if (!pass.helix) {
                const Vec2 at = pass.cut.entryPoint();
                return opError(w, "a helix of diameter " + fmt(2 * radius) + " mm does not fit beside " + name +
                                      " at (" + fmt(at.x) + ", " + fmt(at.y) + "): make it smaller");
            }
        }
        plan.passes.push_back(std::move(pass));
    }
    if (base::Status s = placeTabs(plan, params, tc.tool.diameterMm); !s)
        return s.error();
    return plan;
}

bool linkIsClear(const LoopPlan& plan, Vec2 from, Vec2 to, double toolRadius, const ContourParams& params)
{
    if (plan.material.side() == MaterialSide::None)
        return distance(from, to) < 1e-9;  // no known material side: only where it already is
    const double clearance = toolRadius + params.radialStockMm;
    return checkClear(plan.material, {Segment::line(from, to)}, clearance, std::clamp(toolRadius / 4, 0.05, 2.0),
                      "link")
        .ok();
}

}  // namespace camwb::ops::contour
