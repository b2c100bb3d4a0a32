#include "ops/HelixOp.h"

#include "ops/HoleOrder.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace camwb::ops {

namespace {

using toolpath::FeedKind;
using toolpath::Vec3;

// One hole as the helix mills it.
struct HelixHole {
    geom::Hole hole;
    Heights heights;
    double radius = 0;        // of the tool centre's circle
    bool coreStands = false;  // the tool leaves a core standing in the hole: no move to the centre
};

std::string operationName(const HelixParams& params) { return "helix \"" + params.name + "\""; }

base::Status checkParams(const std::string& what, const std::vector<geom::Hole>& holes, const HelixParams& p,
                         const ToolController& tc)
{
    if (base::Status status = checkHolesAndTool(what, holes, tc); !status)
        return status;
    if (!(p.pitchMm > 0))
        return opError(what, "pitch must be positive, got " + formatMm(p.pitchMm) + " mm");
    if (tc.tool.fluteLengthMm > 0 && p.pitchMm > tc.tool.fluteLengthMm)
        return opError(what, "pitch " + formatMm(p.pitchMm) + " mm is more than the cutting length " +
                                 formatMm(tc.tool.fluteLengthMm) + " mm of tool " + std::to_string(tc.tool.number));
    if (!(p.radialStockMm >= 0))
        return opError(what, "radial stock must not be negative, got " + formatMm(p.radialStockMm) + " mm");
    if (!(p.breakthroughMm >= 0))
        return opError(what, "breakthrough must not be negative, got " + formatMm(p.breakthroughMm) + " mm");
    return base::Status::success();
}

base::Result<HelixHole> planHole(const std::string& what, const geom::Hole& hole, const HelixParams& p,
                                 const ToolController& tc, OpResult& result)
{
    HelixHole plan;
    plan.hole = hole;
    plan.heights = holeHeights(hole, p.heights, p.depthsFromHoles, p.breakthroughMm);
    const std::string holeWhat = what + ": " + describeHole(hole);
    if (base::Status status = checkHeights(holeWhat, plan.heights); !status)
        return status.error();
    if (base::Status status = checkCuttingLength(holeWhat, plan.heights, tc.tool); !status)
        return status.error();
    if (base::Status status =
            checkRepeats(holeWhat, "pitch", p.pitchMm, plan.heights.startZ - plan.heights.finalZ, "turns");
        !status)
        return status.error();
    const double toolRadius = tc.tool.diameterMm / 2;
    plan.radius = (hole.diameterMm - tc.tool.diameterMm) / 2 - p.radialStockMm;
    if (!(plan.radius > 0))
        return opError(what,
                       "the " + formatMm(tc.tool.diameterMm) + " mm tool does not fit the " + describeHole(hole) +
                           (p.radialStockMm > 0 ? " with " + formatMm(p.radialStockMm) + " mm radial stock" : ""));
    // A tool narrower than half the hole never crosses the axis: a core stays unless it falls out
    // of a through hole cut below its bottom.
    const bool coreLeft = plan.radius > toolRadius;
    plan.coreStands = coreLeft && (!hole.through || plan.heights.finalZ > hole.bottomZ);
    if (plan.coreStands)
        result.warn(holeWhat + ": the " + formatMm(tc.tool.diameterMm) + " mm tool leaves a core of " +
                    formatMm(2 * (plan.radius - toolRadius)) +
                    " mm diameter standing (tool narrower than half the hole)");
    return plan;
}

// Writes the motion inside one hole, from the helix start at safe height to the bottom and back to
// the point where the tool leaves upwards (returned).
class HelixWriter {
public:
    HelixWriter(const HelixHole& plan, const HelixParams& p, const ToolController& tc,
                const std::function<void(toolpath::Record)>& add) :
        m_plan(plan),
        m_params(p),
        m_tc(tc),
        m_add(add),
        m_center(plan.hole.center),
        m_direction(p.climb ? 1.0 : -1.0)
    {
    }

    base::Vec2 startPoint() const { return {m_center.x + m_plan.radius, m_center.y}; }

    // Helix from startZ to finalZ, one Arc per half turn with the lead exactly the pitch: the
    // last one shortened to end at finalZ, or, when that piece would be shorter than the
    // tolerance (a post would write an arc whose end is its start: a full circle), the last half
    // turn lengthened instead. Then the flat circle(s). Ends on the circle at finalZ.
    void cut()
    {
        const double startZ = m_plan.heights.startZ;
        const double finalZ = m_plan.heights.finalZ;
        const double halfDrop = m_params.pitchMm / 2;
        const Feed ramp = feedOf(m_tc, FeedKind::Entry);  // the helix is the way in
        m_at = startPoint();
        m_z = startZ;
        const double depth = startZ - finalZ;
        const int wholeHalfTurns = static_cast<int>(std::floor(depth / halfDrop + 1e-9));
        const double rest = std::max(0.0, depth - wholeHalfTurns * halfDrop);
        const double restSweep = std::numbers::pi * rest / halfDrop;
        const bool restTooShort = 2 * m_plan.radius * std::sin(restSweep / 2) < std::max(m_params.toleranceMm, 1e-6);
        const int plainHalfTurns = restTooShort && wholeHalfTurns > 0 ? wholeHalfTurns - 1 : wholeHalfTurns;
        for (int k = 1; k <= plainHalfTurns; ++k)
            halfTurn(startZ - k * halfDrop, ramp);
        if (!restTooShort)
            arcTo(pointAt(angleOf(m_at) + m_direction * restSweep), finalZ, ramp);
        else if (wholeHalfTurns > 0 && rest == 0)
            halfTurn(finalZ, ramp);
        else if (wholeHalfTurns > 0)
            arcTo(pointAt(angleOf(m_at) + m_direction * (std::numbers::pi + restSweep)), finalZ, ramp);
        else if (m_z != finalZ)  // a cut too shallow for any helix
            m_add(feedMove({m_at.x, m_at.y, finalZ}, feedOf(m_tc, FeedKind::Plunge)));
        m_z = finalZ;
        fullCircle(feedOf(m_tc, FeedKind::Cutting));
        if (m_params.finishingCircle)
            fullCircle(feedOf(m_tc, FeedKind::Finishing));
    }

    base::Vec2 at() const { return m_at; }

private:
    double angleOf(base::Vec2 p) const { return std::atan2(p.y - m_center.y, p.x - m_center.x); }
    base::Vec2 pointAt(double angle) const
    {
        return {m_center.x + m_plan.radius * std::cos(angle), m_center.y + m_plan.radius * std::sin(angle)};
    }
    // The point opposite `p` on the circle (exact for the first half turns: no trigonometry).
    base::Vec2 opposite(base::Vec2 p) const
    {
        return {m_center.x - (p.x - m_center.x), m_center.y - (p.y - m_center.y)};
    }

    void halfTurn(double toZ, Feed feed) { arcTo(opposite(m_at), toZ, feed); }

    void fullCircle(Feed feed)
    {
        const base::Vec2 from = m_at;
        halfTurn(m_z, feed);
        arcTo(from, m_z, feed);
    }

    // The CL convention (toolpath/ClArcs.h): the centre lies in the start's plane, so the Z change
    // shows in `to` alone.
    void arcTo(base::Vec2 to, double toZ, Feed feed)
    {
        toolpath::Arc arc;
        arc.to = {to.x, to.y, toZ};
        arc.center = {m_center.x, m_center.y, m_z};
        arc.normal = {0, 0, 1};
        arc.clockwise = m_direction < 0;
        arc.feedMmPerMin = feed.mmPerMin;
        arc.feedKind = feed.kind;
        m_add(arc);
        m_at = to;
        m_z = toZ;
    }

    const HelixHole& m_plan;
    const HelixParams& m_params;
    const ToolController& m_tc;
    const std::function<void(toolpath::Record)>& m_add;
    base::Vec2 m_center;
    // Climb milling inside a hole with a clockwise spindle: counter-clockwise travel.
    double m_direction;
    base::Vec2 m_at;
    double m_z = 0;
};

}  // namespace

base::Result<OpResult> computeHelix(const std::vector<geom::Hole>& holes, const HelixParams& params,
                                    const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = operationName(params);
    if (base::Status status = checkParams(what, holes, params, tc); !status)
        return status.error();
    OpResult result;
    auto planned = planHoles<HelixHole>(
        holes, false, [&](const geom::Hole& hole) { return planHole(what, hole, params, tc, result); });
    if (!planned)
        return planned.error();
    const std::vector<HelixHole>& plans = planned.value();

    int index = 0;
    const std::function<void(toolpath::Record)> add = [&](toolpath::Record r) {
        result.toolpath.add(std::move(r), {operationIndex, index++});
    };
    add(params.finishingCircle
            ? sectionBegin(params.name, "helix", tc, {FeedKind::Entry, FeedKind::Exit, FeedKind::Finishing})
            : sectionBegin(params.name, "helix", tc, {FeedKind::Entry, FeedKind::Exit}));

    const double clearance = params.heights.clearanceZ;
    const double safe = params.heights.safeZ;
    for (std::size_t i = 0; i < plans.size(); ++i) {
        if (!progress.step(static_cast<double>(i) / plans.size()))
            return cancelledError(what);
        const HelixHole& plan = plans[i];
        HelixWriter writer(plan, params, tc, add);
        const base::Vec2 start = writer.startPoint();
        if (i == 0)
            add(toolpath::Rapid{{start.x, start.y, clearance}});
        add(toolpath::Rapid{{start.x, start.y, safe}});
        add(feedMove({start.x, start.y, plan.heights.startZ}, feedOf(tc, FeedKind::Plunge)));
        writer.cut();
        // Off the wall along the radius, unless a core stands there: then straight up.
        base::Vec2 exit = writer.at();
        if (!plan.coreStands) {
            exit = plan.hole.center;
            add(feedMove({exit.x, exit.y, plan.heights.finalZ}, feedOf(tc, FeedKind::Exit)));
        }
        add(toolpath::Rapid{{exit.x, exit.y, i + 1 == plans.size() ? clearance : safe}});
    }
    if (!progress.step(1))
        return cancelledError(what);
    add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
