#include "ops/GrooveOp.h"

#include "base/NumberFormat.h"
#include "ops/turning/GrooveSweeps.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace camwb::ops {

namespace {

using toolpath::AxisMask;

std::string num(double v) { return base::NumberFormat{6, true}.format(v); }

// Spec F6 (seed REQ-06): every input the strategy divides by or loops on, each with its own
// message naming the value and its R-parameter; then the groove's geometry.
base::Status checkInputs(const std::string& what, const GrooveParams& p, const ToolController& tc)
{
    const sim::GrooveParameters& g = p.groove;
    const double w = tc.tool.diameterMm;
    auto fail = [&](const std::string& message) { return base::Status(opError(what, message)); };
    if (tc.tool.kind != "groove")
        return fail("the tool must be a grooving insert (kind \"groove\"), got \"" + tc.tool.kind + "\"");
    if (!(w > 0))
        return fail("insert width (R9, the tool's width) must be positive, got " + num(w) + " mm");
    if (!(tc.tool.cornerRadiusMm >= 0 && 2 * tc.tool.cornerRadiusMm <= w))
        return fail("the insert's corner radius must be between 0 and half its width (" + num(w / 2) + " mm), got " +
                    num(tc.tool.cornerRadiusMm) + " mm");
    if (!(p.infeedMm > 0))
        return fail("infeed (R11) must be positive, got " + num(p.infeedMm) + " mm");
    if (!(p.stepFactor > 0 && p.stepFactor <= 1))
        return fail("step factor (R10) must be above 0 and at most 1 (a larger step leaves ribs), got " +
                    num(p.stepFactor));
    if (!(p.safetyMm >= 0))
        return fail("safety distance (R30) must not be negative, got " + num(p.safetyMm) + " mm");
    if (!(g.r7 >= 0))
        return fail("bottom allowance (R7) must not be negative, got " + num(g.r7) + " mm");
    if (!(g.r8 >= 0))
        return fail("flank allowance (R8) must not be negative, got " + num(g.r8) + " mm");
    if (!(g.r3 > 0))
        return fail("groove depth (R3) must be positive, got " + num(g.r3) + " mm");
    if (!(g.r3 < g.r0))
        return fail("groove depth (R3) must be less than the start point's radius (R0 = " + num(g.r0) + "), got " +
                    num(g.r3) + " mm");
    if (!(g.r4 > 0))
        return fail("bottom width (R4) must be positive, got " + num(g.r4) + " mm");
    if (!(std::isfinite(g.r1)))
        return fail("start point Z (R1) must be a number");
    for (const auto& [value, name] : {std::pair{g.r2, "cone angle (R2)"}, std::pair{g.r5, "right flank angle (R5)"},
                                      std::pair{g.r6, "left flank angle (R6)"}})
        if (!(value >= 0 && value < 90))
            return fail(std::string(name) + " must be at least 0 and below 90 degrees, got " + num(value));
    if (!(g.r2 + g.r5 < 90))
        return fail("cone angle (R2) plus right flank angle (R5) must be below 90 degrees (the flank must meet "
                    "the surface), got " +
                    num(g.r2 + g.r5));
    if (!(p.finalRetractMm > 0))
        return fail("final retract must be positive, got " + num(p.finalRetractMm) + " mm");
    if (!(p.feedMmPerRev > 0))
        return fail("feed must be positive, got " + num(p.feedMmPerRev) + " mm/rev");
    if (!(p.maxRpm > 0) || !(p.surfaceSpeedMPerMin > 0))
        return fail("cutting speed and speed limit must be positive");
    // Fix V1 (docs/groove-strategy.md): each plunge of a sweep is R9*R10 further along and R11 deeper;
    // where the flank is flatter than that staircase the plunges go through it.
    const double step = w * p.stepFactor;
    for (const auto& [angle, name] :
         {std::pair{g.r5, "right flank angle (R5)"}, std::pair{g.r6, "left flank angle (R6)"}})
        if (!(p.infeedMm * std::tan(angle * std::numbers::pi / 180) <= step))
            return fail("the staircase of plunges (R11 = " + num(p.infeedMm) +
                        " mm deeper every R9*R10 = " + num(step) + " mm) is steeper than the " + name +
                        ": the plunges would cut the flank; take a smaller infeed (R11 <= " +
                        num(step / std::tan(angle * std::numbers::pi / 180)) + " mm) or a larger step (R10)");
    sim::GrooveParameters withWidth = g;
    withWidth.r9 = w;
    const sim::GrooveGeometry geo = sim::grooveGeometry(withWidth);
    if (!(geo.u.y > geo.t.y))
        return fail("the right flank's offset (R8) meets the surface at X " + num(geo.u.y) +
                    ", not above the bottom's offset (R0 - R3 + R7 = " + num(geo.t.y) +
                    "): the groove is too shallow for its allowances (R3, R7, R8)");
    if (!(geo.r.y > geo.s.y))
        return fail("the left flank's offset (R8) meets the surface at X " + num(geo.r.y) +
                    ", not above the bottom's offset (R0 - R3 + R7 = " + num(geo.s.y) +
                    "): the groove is too shallow on the left for its allowances (R3, R6, R7, R8)");
    if (!(geo.t.x - geo.s.x >= w))
        return fail("the bottom's offset is " + num(geo.t.x - geo.s.x) + " mm wide, narrower than the " + num(w) +
                    " mm insert (R9): widen the groove (R4) or take a narrower insert");
    return base::Status::success();
}

}  // namespace

base::Result<OpResult> computeGroove(const GrooveParams& params, const ToolController& tc, int operationIndex,
                                     const Progress& progress)
{
    const std::string what = "groove \"" + params.name + "\"";
    if (base::Status status = checkInputs(what, params, tc); !status)
        return status.error();
    sim::GrooveParameters g = params.groove;
    g.r9 = tc.tool.diameterMm;
    turning::GrooveSetup setup{sim::grooveGeometry(g), g.r9, params.stepFactor, params.infeedMm, params.safetyMm};
    auto moves = turning::grooveMoves(setup, what, [&](double fraction) { return progress.step(fraction); });
    if (!moves)
        return moves.error();

    OpResult result;
    int index = 0;
    auto add = [&](toolpath::Record r) { result.toolpath.add(std::move(r), {operationIndex, index++}); };
    toolpath::SectionBegin begin;
    begin.operationName = params.name;
    begin.strategy = "groove-roughing";
    begin.toolNumber = tc.tool.number;
    begin.feeds.cuttingMmPerMin = params.feedMmPerRev;  // per revolution: the FeedModeChange below
    begin.strategyParameters = {{"R0", g.r0},
                                {"R1", g.r1},
                                {"R2", g.r2},
                                {"R3", g.r3},
                                {"R4", g.r4},
                                {"R5", g.r5},
                                {"R6", g.r6},
                                {"R7", g.r7},
                                {"R8", g.r8},
                                {"R9", g.r9},
                                {"R10", params.stepFactor},
                                {"R11", params.infeedMm},
                                {"R30", params.safetyMm},
                                {"fallback", moves->fallback ? 1.0 : 0.0}};
    add(std::move(begin));
    add(toolpath::FeedModeChange{toolpath::FeedMode::PerRevolution});
    add(toolpath::Spindle{params.maxRpm, true, params.surfaceSpeedMPerMin});
    if (params.coolant)
        add(toolpath::Coolant{toolpath::CoolantMode::Flood});
    const double safeX = g.r0 + params.finalRetractMm;
    add(toolpath::Rapid({safeX, 0, 0}, AxisMask{AxisMask::kX}));
    double z = 0;  // known from the strategy's first move on (a G0 Z)
    for (const turning::GrooveMove& m : moves->moves) {
        switch (m.kind) {
        case turning::GrooveMove::Kind::RapidX:
            add(toolpath::Rapid({m.x, 0, z}, AxisMask{AxisMask::kX}));
            break;
        case turning::GrooveMove::Kind::RapidZ:
            z = m.z;
            add(toolpath::Rapid({0, 0, m.z}, AxisMask{AxisMask::kZ}));
            break;
        case turning::GrooveMove::Kind::Feed:
            z = m.z;
            add(toolpath::Linear({m.x, 0, m.z}, params.feedMmPerRev, AxisMask{AxisMask::kX | AxisMask::kZ},
                                 toolpath::FeedKind::Cutting));
            break;
        }
    }
    add(toolpath::Rapid({safeX, 0, z}, AxisMask{AxisMask::kX}));
    add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    // The strategy programs the sharp left corner (seed REQ-07); a rounded corner cuts inside the
    // sharp one, so nothing is gouged, but the groove's corners and the staircase keep a fillet.
    if (tc.tool.cornerRadiusMm > 0)
        result.warn(what + ": the path is for a sharp insert; its corner radius of " + num(tc.tool.cornerRadiusMm) +
                    " mm leaves fillets of that radius in the groove's bottom corners and under the plunges "
                    "for the finishing operation");
    return result;
}

}  // namespace camwb::ops
