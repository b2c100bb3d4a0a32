#include "ops/OpCommon.h"

#include "base/NumberFormat.h"
#include "base/RepeatLimit.h"

#include <cmath>
#include <variant>

namespace camwb::ops {

namespace {
std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }
}  // namespace

MotionCounts countMotions(const toolpath::Toolpath& toolpath)
{
    MotionCounts counts;
    for (const toolpath::Record& r : toolpath.records()) {
        if (std::holds_alternative<toolpath::Rapid>(r))
            ++counts.rapids;
        else if (std::holds_alternative<toolpath::Linear>(r))
            ++counts.lines;
        else if (const auto* arc = std::get_if<toolpath::Arc>(&r))
            ++(arc->turns > 0 || std::abs((arc->to - arc->center).dot(arc->normal)) > 1e-9 ? counts.helices
                                                                                           : counts.arcs);
        else if (std::holds_alternative<toolpath::Cycle>(r))
            ++counts.cycles;
        else if (const auto* move = std::get_if<toolpath::ToolAxisMove>(&r))
            ++(move->feedMmPerMin > 0 ? counts.lines : counts.rapids);
    }
    return counts;
}

Feed feedOf(const ToolController& tc, toolpath::FeedKind kind)
{
    using toolpath::FeedKind;
    switch (kind) {
    case FeedKind::Plunge:
        return {tc.plungeFeedMmPerMin, kind};
    case FeedKind::Entry:
        return {tc.rampFeed(), kind};
    case FeedKind::Cutting:
    case FeedKind::Exit:
    case FeedKind::Finishing:
        return {tc.cuttingFeedMmPerMin, kind};
    case FeedKind::Unspecified:
        break;
    }
    return {};  // no kind, no feed: a move that asks for none is warned about when posted
}

toolpath::SectionBegin sectionBegin(const std::string& name, const std::string& strategy, const ToolController& tc,
                                    std::initializer_list<toolpath::FeedKind> alsoUses)
{
    using toolpath::FeedKind;
    toolpath::SectionBegin begin;
    begin.operationName = name;
    begin.strategy = strategy;
    begin.toolNumber = tc.tool.number;
    begin.feeds.cuttingMmPerMin = feedOf(tc, FeedKind::Cutting).mmPerMin;
    begin.feeds.plungeMmPerMin = feedOf(tc, FeedKind::Plunge).mmPerMin;
    for (FeedKind kind : alsoUses) {
        const double feed = feedOf(tc, kind).mmPerMin;
        if (kind == FeedKind::Entry)
            begin.feeds.entryMmPerMin = feed;
        else if (kind == FeedKind::Exit)
            begin.feeds.exitMmPerMin = feed;
        else if (kind == FeedKind::Finishing)
            begin.feeds.finishingMmPerMin = feed;
    }
    return begin;
}

std::vector<double> stepDownLevels(double startZ, double finalZ, double stepDown)
{
    const double depth = startZ - finalZ;
    if (!(stepDown > 0) || stepDown >= depth - 1e-9)
        return {finalZ};
    // Equal steps: the fewest that keep each one within stepDown (1e-9 absorbs 6.0/2.0 rounding).
    const int count = static_cast<int>(std::ceil(depth / stepDown - 1e-9));
    std::vector<double> levels;
    for (int i = 1; i < count; ++i)
        levels.push_back(startZ - depth * i / count);
    levels.push_back(finalZ);
    return levels;
}

base::Error opError(const std::string& what, const std::string& message)
{
    return base::makeError(what + ": " + message);
}

base::Error cancelledError(const std::string& what) { return opError(what, "cancelled"); }

base::Status checkRepeats(const std::string& what, const std::string& parameter, double valueMm, double spanMm,
                          const std::string& repeats)
{
    if (std::optional<std::string> why = base::tooManyRepeats(parameter, valueMm, spanMm, repeats, "an operation"))
        return opError(what, *why);
    return base::Status::success();
}

base::Status checkToolController(const std::string& what, const ToolController& tc)
{
    if (!(tc.tool.diameterMm > 0))
        return opError(what, "tool diameter must be positive, got " + fmt(tc.tool.diameterMm) + " mm");
    if (!(tc.cuttingFeedMmPerMin > 0))
        return opError(what, "cutting feed must be positive, got " + fmt(tc.cuttingFeedMmPerMin) + " mm/min");
    if (!(tc.plungeFeedMmPerMin > 0))
        return opError(what, "plunge feed must be positive, got " + fmt(tc.plungeFeedMmPerMin) + " mm/min");
    if (tc.rampFeedMmPerMin < 0)
        return opError(what, "ramp feed must not be negative, got " + fmt(tc.rampFeedMmPerMin) + " mm/min");
    if (!(tc.spindleRpm > 0))
        return opError(what, "spindle speed must be positive, got " + fmt(tc.spindleRpm) + " rpm");
    return base::Status::success();
}

base::Status checkHeights(const std::string& what, const Heights& h)
{
    if (!(h.clearanceZ >= h.safeZ))
        return opError(what, "clearance height " + fmt(h.clearanceZ) + " is below the safe height " + fmt(h.safeZ));
    if (!(h.safeZ > h.startZ))
        return opError(what, "safe height " + fmt(h.safeZ) + " must be above the start depth " + fmt(h.startZ));
    if (!(h.startZ >= h.finalZ))
        return opError(what, "start depth " + fmt(h.startZ) + " is below the final depth " + fmt(h.finalZ));
    return base::Status::success();
}

base::Status checkCuttingLength(const std::string& what, const Heights& h, const toolpath::Tool& tool)
{
    const double depth = h.startZ - h.finalZ;
    if (tool.fluteLengthMm > 0 && depth > tool.fluteLengthMm + 1e-9)
        return opError(what, "cut depth " + fmt(depth) + " mm is beyond the cutting length " + fmt(tool.fluteLengthMm) +
                                 " mm of tool " + std::to_string(tool.number));
    return base::Status::success();
}

}  // namespace camwb::ops
