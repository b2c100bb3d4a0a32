#include "ops/ContourOp.h"

#include "ops/contour/Checks.h"
#include "ops/contour/Plan.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::ops {

namespace {

using namespace contour;

// Writes one loop: every level, every radial pass (outermost first), staying down between them
// where the link is clear of the part, else retracting to the safe height.
class LoopWriter {
public:
    LoopWriter(Emitter& out, const ContourParams& params, const ToolController& tc) :
        m_out(out),
        m_params(params),
        m_tc(tc),
        m_feeds{feedOf(tc, toolpath::FeedKind::Cutting), feedOf(tc, toolpath::FeedKind::Plunge),
                feedOf(tc, toolpath::FeedKind::Entry)},
        m_exit(feedOf(tc, toolpath::FeedKind::Exit))
    {
    }

    // Cuts pass `pass` at level z, the level above at zTop; `fromAbove`: the tool is at clearance
    // over the previous loop (or nowhere yet).
    void cut(const LoopPlan& plan, const PassPlan& pass, double zTop, double z, bool fromAbove)
    {
        const Cut& cut = pass.cut;
        const Heights& h = m_params.heights;
        std::optional<Helix> helix;
        if (pass.helix)
            helix = helixTo(cut.entryPoint(), cut.entryDirection(), pass.helixLeft, pass.helix->circle().radius(),
                            m_params.helixPitchMm, zTop, z);
        const Vec2 descent = helix ? helix->start : cut.entryPoint();

        if (fromAbove) {
            m_out.rapid({descent.x, descent.y, h.clearanceZ});
            m_out.rapid({descent.x, descent.y, h.safeZ});
        } else if (m_closed && linkIsClear(plan, m_out.position().xy(), descent, m_tc.tool.diameterMm / 2, m_params)) {
            m_out.linear({descent.x, descent.y, m_out.position().z}, m_feeds.cut);
        } else {
            m_out.rapid({m_out.position().x, m_out.position().y, h.safeZ});
            m_out.rapid({descent.x, descent.y, h.safeZ});
        }

        const bool ramp = m_params.entry == EntryKind::Ramp && m_params.rampAngleDeg < 90;
        const double entryZ = ramp || helix ? zTop : z;
        if (m_out.position().z > entryZ)
            m_out.vertical(entryZ, m_feeds.plunge);
        if (helix)
            for (const auto& [arc, zEnd] : helix->arcs)
                m_out.piece(arc, zEnd, m_feeds.ramp);
        if (m_out.position().z > z && !ramp)  // a 90 degree ramp goes straight down
            m_out.vertical(z, m_feeds.ramp);

        // Approach and lead-in run at the cutting feed, so they are Cutting moves: Entry is the
        // ramp feed's kind (the helix and ramps above), and a kind never disagrees with its feed.
        const double levelZ = m_out.position().z;
        if (cut.approach) {
            m_out.add(toolpath::CutterComp{plan.compSide});
            const Vec2 to = cut.leadIn.empty() ? cut.path.start() : cut.leadIn.front().start;
            m_out.linear({to.x, to.y, levelZ}, m_feeds.cut);
        }
        for (const Segment& s : cut.leadIn)
            m_out.piece(s, levelZ, m_feeds.cut);
        if (ramp)
            rampDown(pass, zTop, z);
        cutAlong(m_out, cut.path, 0, cut.path.length(), z, z, &pass.tabs, m_feeds);
        for (const Segment& s : cut.leadOut)
            m_out.piece(s, z, m_exit);
        if (cut.departure) {
            m_out.add(toolpath::CutterComp{toolpath::CutterCompSide::Off});
            m_out.linear({cut.departure->x, cut.departure->y, z}, m_exit);
        }
    }

    void setClosed(bool closed) { m_closed = closed; }

private:
    // Down along the path at the ramp angle or shallower: whole laps of a loop, so the ramp ends
    // where the loop starts; back and forth along a chain's beginning.
    void rampDown(const PassPlan& pass, double zTop, double z)
    {
        const Path& path = pass.cut.path;
        const double length = path.length();
        const double rampLength = (zTop - z) / std::tan(m_params.rampAngleDeg * std::numbers::pi / 180);
        if (path.closed) {
            const double laps = std::max(1.0, std::ceil(rampLength / length - 1e-9));
            cutAlong(m_out, path, 0, laps * length, zTop, z, &pass.tabs, m_feeds);
            return;
        }
        const int trips = std::max(1, static_cast<int>(std::ceil(rampLength / (2 * length) - 1e-9)));
        const double leg = std::min(length, rampLength / (2 * trips));
        const double drop = (zTop - z) / (2 * trips);
        for (int i = 0; i < trips; ++i) {
            const double za = zTop - drop * 2 * i;
            cutAlong(m_out, path, 0, leg, za, za - drop, &pass.tabs, m_feeds);
            cutAlong(m_out, path, leg, 0, za - drop, za - 2 * drop, &pass.tabs, m_feeds);
        }
    }

    Emitter& m_out;
    const ContourParams& m_params;
    const ToolController& m_tc;
    Feeds m_feeds;
    Feed m_exit;  // lead-out and departure
    bool m_closed = true;
};

// Input order from the first contour, then always the nearest next start.
std::vector<std::size_t> cuttingOrder(const std::vector<LoopPlan>& plans)
{
    std::vector<std::size_t> order;
    std::vector<bool> used(plans.size(), false);
    Vec2 at = plans.front().passes.front().cut.entryPoint();
    for (std::size_t n = 0; n < plans.size(); ++n) {
        std::size_t best = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < plans.size(); ++i)
            if (!used[i] && distance(at, plans[i].passes.front().cut.entryPoint()) < bestDistance) {
                best = i;
                bestDistance = distance(at, plans[i].passes.front().cut.entryPoint());
            }
        used[best] = true;
        order.push_back(best);
        at = plans[best].passes.back().cut.exitPoint();
    }
    return order;
}

}  // namespace

base::Result<OpResult> computeContour(const std::vector<geom::Profile>& contours, const ContourParams& params,
                                      const ToolController& tc, int operationIndex, const Progress& progress)
{
    if (base::Status s = checkContourInput(contours, params, tc); !s)
        return s.error();
    const std::string w = what(params);
    OpResult result;
    if (params.side == ContourSide::On && (params.radialStockMm > 0 || params.radialPasses > 1))
        result.warn(w + ": radial stock and radial passes do not apply on the contour; ignored");

    const Heights& h = params.heights;
    const std::vector<double> levels = stepDownLevels(h.startZ, h.finalZ + params.axialStockMm, params.stepDownMm);
    const double tabTop = h.finalZ + params.tabHeightMm;

    std::vector<LoopPlan> plans;
    for (std::size_t i = 0; i < contours.size(); ++i) {
        auto plan = planLoop(contours[i], i, params, tc);
        if (!plan)
            return plan.error();
        for (PassPlan& pass : plan.value().passes)
            pass.tabs.topZ = tabTop;
        plans.push_back(std::move(plan.value()));
        if (!progress.step(0))
            return cancelledError(w);
    }

    Emitter out(result.toolpath, operationIndex);
    out.add(sectionBegin(params.name, "contour", tc, {toolpath::FeedKind::Entry, toolpath::FeedKind::Exit}));

    LoopWriter writer(out, params, tc);
    const double steps = static_cast<double>(plans.size() * levels.size());
    int done = 0;
    for (std::size_t index : cuttingOrder(plans)) {
        const LoopPlan& plan = plans[index];
        writer.setClosed(contours[index].closed);
        bool fromAbove = true;
        for (std::size_t l = 0; l < levels.size(); ++l) {
            const double zTop = l == 0 ? h.startZ : levels[l - 1];
            for (const PassPlan& pass : plan.passes) {
                writer.cut(plan, pass, zTop, levels[l], fromAbove);
                fromAbove = false;
            }
            if (!progress.step(++done / steps))
                return cancelledError(w);
        }
        out.rapid({out.position().x, out.position().y, h.clearanceZ});
    }
    out.add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
