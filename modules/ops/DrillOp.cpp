#include "ops/DrillOp.h"

#include "ops/HoleOrder.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::ops {

namespace {

using toolpath::CycleKind;

// A drill larger than the hole by more than this is an error (a drill of the hole's nominal size
// is often a hundredth over it in the model).
constexpr double kOversizeToleranceMm = 0.01;

// One hole as the cycle drills it.
struct DrillHole {
    base::Vec3 top;  // the hole's top centre: where the cycle's reference plane is
    double bottomZ = 0;
};

std::string operationName(const DrillParams& params) { return "drilling \"" + params.name + "\""; }

base::Status checkParams(const std::string& what, const std::vector<geom::Hole>& holes, const DrillParams& p,
                         const ToolController& tc)
{
    if (base::Status status = checkHolesAndTool(what, holes, tc); !status)
        return status;
    switch (p.cycle) {
    case CycleKind::Drill:
    case CycleKind::DrillDwell:
        break;
    case CycleKind::Peck:
    case CycleKind::ChipBreak:
        if (!(p.peckMm > 0))
            return opError(what, "peck depth must be positive for a " +
                                     std::string(p.cycle == CycleKind::Peck ? "peck" : "chip-breaking") +
                                     " cycle, got " + formatMm(p.peckMm) + " mm");
        break;
    default:
        return opError(what, "the cycle must be drill, drill with dwell, peck or chip breaking");
    }
    if (!(p.dwellSeconds >= 0))
        return opError(what, "dwell must not be negative, got " + formatMm(p.dwellSeconds) + " s");
    if (!(p.breakthroughMm >= 0))
        return opError(what, "breakthrough must not be negative, got " + formatMm(p.breakthroughMm) + " mm");
    if (p.depthAtShoulder && !(tc.tool.pointAngleDeg < 180))
        return opError(what, "point angle must be below 180 degrees, got " + formatMm(tc.tool.pointAngleDeg));
    return base::Status::success();
}

// How much deeper the tip goes than the full diameter: (D/2) / tan(angle/2); 0 for a flat tool.
double tipLength(const toolpath::Tool& tool)
{
    if (!(tool.pointAngleDeg > 0))
        return 0;
    return tool.diameterMm / 2 / std::tan(tool.pointAngleDeg / 2 * std::numbers::pi / 180);
}

base::Result<DrillHole> planHole(const std::string& what, const geom::Hole& hole, const DrillParams& p,
                                 const ToolController& tc, OpResult& result)
{
    Heights h = holeHeights(hole, p.heights, p.depthsFromHoles, p.breakthroughMm);
    if (p.depthAtShoulder)
        h.finalZ -= tipLength(tc.tool);
    const std::string holeWhat = what + ": " + describeHole(hole);
    if (base::Status status = checkHeights(holeWhat, h); !status)
        return status.error();
    if (base::Status status = checkCuttingLength(holeWhat, h, tc.tool); !status)
        return status.error();
    if (p.cycle == CycleKind::Peck || p.cycle == CycleKind::ChipBreak)
        if (base::Status status = checkRepeats(holeWhat, "peck depth", p.peckMm, h.startZ - h.finalZ, "pecks"); !status)
            return status.error();
    const double drill = tc.tool.diameterMm;
    if (drill > hole.diameterMm + kOversizeToleranceMm)
        return opError(what, "the " + formatMm(drill) + " mm drill is larger than the " + describeHole(hole));
    // Smaller by more than a tenth of a millimetre and 5 %: not a drill of the hole's size.
    if (hole.diameterMm - drill > std::max(0.1, 0.05 * hole.diameterMm))
        result.warn(holeWhat + ": the " + formatMm(drill) + " mm drill leaves it undersize");
    return DrillHole{{hole.center.x, hole.center.y, h.startZ}, h.finalZ};
}

}  // namespace

base::Result<OpResult> computeDrill(const std::vector<geom::Hole>& holes, const DrillParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = operationName(params);
    if (base::Status status = checkParams(what, holes, params, tc); !status)
        return status.error();
    OpResult result;
    auto planned = planHoles<DrillHole>(
        holes, params.keepOrder, [&](const geom::Hole& hole) { return planHole(what, hole, params, tc, result); });
    if (!planned)
        return planned.error();
    const std::vector<DrillHole>& plans = planned.value();

    int index = 0;
    auto add = [&](toolpath::Record r) { result.toolpath.add(std::move(r), {operationIndex, index++}); };
    add(sectionBegin(params.name, "drilling", tc));

    const double clearance = params.heights.clearanceZ;
    add(toolpath::Rapid{{plans.front().top.x, plans.front().top.y, clearance}});
    toolpath::Cycle cycle;
    // One Cycle record for each run of holes (in visiting order) with the same top and bottom.
    auto flush = [&] {
        if (!cycle.holes.empty())
            add(cycle);
        cycle.holes.clear();
    };
    for (std::size_t i = 0; i < plans.size(); ++i) {
        if (!progress.step(static_cast<double>(i) / plans.size()))
            return cancelledError(what);
        const DrillHole& plan = plans[i];
        if (!cycle.holes.empty() && (cycle.topZ != plan.top.z || cycle.bottomZ != plan.bottomZ))
            flush();
        if (cycle.holes.empty()) {
            cycle.kind = params.cycle;
            cycle.clearanceZ = clearance;
            cycle.retractZ = params.heights.safeZ;
            cycle.topZ = plan.top.z;
            cycle.bottomZ = plan.bottomZ;
            cycle.peckMm = params.cycle == CycleKind::Peck || params.cycle == CycleKind::ChipBreak ? params.peckMm : 0;
            // A plain drill cycle has no dwell (CYCLE81 has none); the others dwell at the bottom.
            cycle.dwellSeconds = params.cycle == CycleKind::Drill ? 0 : params.dwellSeconds;
            cycle.feedMmPerMin = tc.cuttingFeedMmPerMin;
            cycle.returnToClearance = params.retractToClearance;
        }
        cycle.holes.push_back(plan.top);
    }
    const bool endsAtClearance = toolpath::cycleReturnZ(cycle) == clearance;
    flush();
    if (!endsAtClearance)
        add(toolpath::Rapid{{plans.back().top.x, plans.back().top.y, clearance}});
    if (!progress.step(1))
        return cancelledError(what);
    add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
