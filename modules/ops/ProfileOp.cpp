#include "ops/ProfileOp.h"

#include "base/NumberFormat.h"
#include "geom/Offset.h"

#include <cmath>
#include <numbers>

namespace camwb::ops {

namespace {

using geom::Segment;
using toolpath::Vec3;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

base::Error opError(const ProfileParams& params, const std::string& what)
{
    return base::makeError("profile operation \"" + params.name + "\": " + what);
}

base::Status validate(const geom::Profile& boundary, const ProfileParams& p, const ToolController& tc)
{
    if (!(tc.tool.diameterMm > 0))
        return opError(p, "tool diameter must be positive, got " + fmt(tc.tool.diameterMm) + " mm");
    if (!(tc.cuttingFeedMmPerMin > 0))
        return opError(p, "cutting feed must be positive, got " + fmt(tc.cuttingFeedMmPerMin) + " mm/min");
    if (!(tc.plungeFeedMmPerMin > 0))
        return opError(p, "plunge feed must be positive, got " + fmt(tc.plungeFeedMmPerMin) + " mm/min");
    if (!(tc.spindleRpm > 0))
        return opError(p, "spindle speed must be positive, got " + fmt(tc.spindleRpm) + " rpm");
    if (!(p.clearanceZ >= p.safeZ))
        return opError(p, "clearance height " + fmt(p.clearanceZ) + " is below the safe height " + fmt(p.safeZ));
    if (!(p.safeZ > p.finalDepthZ))
        return opError(p, "safe height " + fmt(p.safeZ) + " must be above the final depth " + fmt(p.finalDepthZ));
    if (boundary.empty())
        return opError(p, "the boundary is empty");
    return base::Status::success();
}

// The loop rotated to begin at the midpoint of its longest line (split there), else unchanged.
std::vector<Segment> rotateToStart(const std::vector<Segment>& loop)
{
    std::size_t best = loop.size();
    double bestLength = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        if (!loop[i].isArc() && loop[i].length() > bestLength) {
            best = i;
            bestLength = loop[i].length();
        }
    if (best == loop.size())
        return loop;
    const Segment& split = loop[best];
    const base::Vec2 mid = (split.start + split.end) * 0.5;
    std::vector<Segment> out;
    out.push_back(Segment::line(mid, split.end));
    for (std::size_t k = 1; k < loop.size(); ++k)
        out.push_back(loop[(best + k) % loop.size()]);
    out.push_back(Segment::line(split.start, mid));
    return out;
}

}  // namespace

base::Result<toolpath::Toolpath> computeOuterProfile(const geom::Profile& boundary, const ProfileParams& params,
                                                     const ToolController& tc, int operationIndex)
{
    if (base::Status status = validate(boundary, params, tc); !status)
        return status.error();

    // Work counter-clockwise so "outside" and the milling direction do not depend on the input.
    const geom::Profile ccwBoundary = boundary.signedArea() < 0 ? boundary.reversed() : boundary;
    auto offset = geom::offsetOutside(ccwBoundary, tc.tool.diameterMm / 2);
    if (!offset)
        return opError(params, offset.error().message);
    // With a clockwise-turning cutter, climb milling keeps the material on the right of travel:
    // around an outside boundary that is clockwise, so the ccw offset is reversed.
    const geom::Profile path = params.climb ? offset.value().reversed() : offset.value();
    const std::vector<Segment> loop = rotateToStart(path.segments);

    toolpath::Toolpath tp;
    int index = 0;
    auto add = [&](toolpath::Record r) { tp.add(std::move(r), {operationIndex, index++}); };
    const double z = params.finalDepthZ;
    const double cut = tc.cuttingFeedMmPerMin;
    const base::Vec2 start = loop.front().start;

    toolpath::SectionBegin begin;
    begin.operationName = params.name;
    begin.strategy = "profile";
    begin.toolNumber = tc.tool.number;
    begin.feeds.cuttingMmPerMin = cut;
    begin.feeds.plungeMmPerMin = tc.plungeFeedMmPerMin;
    add(begin);
    add(toolpath::Rapid{{start.x, start.y, params.clearanceZ}});
    add(toolpath::Rapid{{start.x, start.y, params.safeZ}});
    add(toolpath::Linear{{start.x, start.y, z}, tc.plungeFeedMmPerMin});

    auto addArc = [&](base::Vec2 to, const Segment& s) {
        toolpath::Arc arc;
        arc.to = {to.x, to.y, z};
        arc.center = {s.center.x, s.center.y, z};
        arc.normal = {0, 0, 1};
        arc.clockwise = !s.ccw;
        arc.feedMmPerMin = cut;
        add(arc);
    };
    for (const Segment& s : loop) {
        if (!s.isArc()) {
            add(toolpath::Linear{{s.end.x, s.end.y, z}, cut});
        } else if (std::abs(s.sweep()) > 2 * std::numbers::pi - 1e-9) {
            // A full circle as one record would have its end on its start; split it in halves.
            addArc(s.pointAt(0.5), s);
            addArc(s.end, s);
        } else {
            addArc(s.end, s);
        }
    }
    add(toolpath::Rapid{{start.x, start.y, params.clearanceZ}});
    add(toolpath::SectionEnd{});
    return tp;
}

}  // namespace camwb::ops
