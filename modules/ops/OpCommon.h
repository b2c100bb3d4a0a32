// What every 2.5D operation shares: the tool controller (tool + speeds and feeds), the heights,
// progress and cancellation, the result (toolpath, warnings, arc/line counts) and the checks made
// before computing. Operations are pure functions of (geometry, parameters, tool controller):
// they never touch the model or the job, so they run on any thread.
#pragma once

#include "base/Diagnostic.h"
#include "base/Result.h"
#include "toolpath/Toolpath.h"

#include <atomic>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace camwb::ops {

// A tool's cutting data for one work material, as a tool library gives it (textbook or the maker's
// values): the cutting speed and feed per tooth the spindle speed and feeds are computed from
// (document/CuttingData.h). Plunge and ramp feeds as fractions of the cutting feed; 0 = not given.
struct CuttingData {
    std::string material;  // "aluminium", "steel", ...: matched to the job's stock material
    double vcMPerMin = 0;  // cutting speed
    double fzMm = 0;       // feed per tooth
    double plungeFraction = 0;
    double rampFraction = 0;
    bool operator==(const CuttingData&) const = default;
};

struct ToolController {
    toolpath::Tool tool;
    double spindleRpm = 0;
    double cuttingFeedMmPerMin = 0;
    double plungeFeedMmPerMin = 0;
    double rampFeedMmPerMin = 0;  // 0 = the cutting feed
    double rampFeed() const { return rampFeedMmPerMin > 0 ? rampFeedMmPerMin : cuttingFeedMmPerMin; }
    // Carried with the tool (copied from a library into the job) so that its feeds and speeds can
    // be computed again for another material; the operations never read it.
    std::vector<CuttingData> cuttingData{};
};

// A feed as an operation chooses it for a move: the value and which of its section's feeds it is,
// taken together from feedOf() so that the kind a move carries always agrees with its value.
struct Feed {
    double mmPerMin = 0;
    toolpath::FeedKind kind = toolpath::FeedKind::Unspecified;
};

// The tool controller's feed of each kind: Cutting and Plunge its own; Entry the ramp feed (ramps
// and helices down into the material); Exit and Finishing the cutting feed (leaving the cut and
// finishing passes have no feeds of their own).
Feed feedOf(const ToolController& tc, toolpath::FeedKind kind);
// A straight feed move to `to` (every axis) with the feed's value and kind.
inline toolpath::Linear feedMove(const toolpath::Vec3& to, Feed feed)
{
    return toolpath::Linear{to, feed.mmPerMin, {}, feed.kind};
}

// Resolved heights in workpiece Z (mm). clearance >= safe > start >= final.
// clearance: rapids between features/operations; safe: rapid down to here before feeding;
// start: top of the material to cut (first step-down starts below it); final: the bottom.
struct Heights {
    double clearanceZ = 0;
    double safeZ = 0;
    double startZ = 0;
    double finalZ = 0;
};

// Progress and cancellation for one computation. Operations call step() now and then; when it
// returns false (cancel requested) they stop and return the error "cancelled", producing nothing.
struct Progress {
    std::function<void(double fraction)> report;  // 0..1, may be empty
    const std::atomic<bool>* cancel = nullptr;    // may be null

    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
    bool step(double fraction) const
    {
        if (report)
            report(fraction);
        return !cancelled();
    }
};

// Motion counts of a computed toolpath, so the user sees that arcs stayed arcs.
struct MotionCounts {
    int rapids = 0, lines = 0, arcs = 0, helices = 0, cycles = 0;
};
MotionCounts countMotions(const toolpath::Toolpath& toolpath);

struct OpResult {
    toolpath::Toolpath toolpath;             // SectionBegin ... SectionEnd; ToolChange/Spindle are the caller's
    std::vector<base::Diagnostic> warnings;  // computed anyway, but the user should know (left corners, ...)
    MotionCounts counts;

    void warn(std::string message) { warnings.push_back(base::warningDiagnostic(std::move(message))); }
};

// The SectionBegin an operation opens its toolpath with: name, strategy ("contour", "pocket",
// "helix", "drilling"), tool number and the cutting and plunge feeds, and the feeds of the other
// kinds it uses (`alsoUses`: entry, exit, finishing), each as feedOf() gives it to the moves.
toolpath::SectionBegin sectionBegin(const std::string& name, const std::string& strategy, const ToolController& tc,
                                    std::initializer_list<toolpath::FeedKind> alsoUses = {});

// Z levels from start down to final in equal steps no deeper than stepDown (the last one at
// final). stepDown <= 0 or >= the whole depth: one level at final.
std::vector<double> stepDownLevels(double startZ, double finalZ, double stepDown);

// The checks every operation makes before computing; errors name the operation
// ("pocket \"Pocket 2\": tool diameter must be positive, got 0 mm").
base::Status checkToolController(const std::string& what, const ToolController& tc);
base::Status checkHeights(const std::string& what, const Heights& heights);
// The cut depth (start - final) must not exceed the tool's flute length (when the tool states it).
base::Status checkCuttingLength(const std::string& what, const Heights& heights, const toolpath::Tool& tool);
// `parameter` (its name) of `valueMm` repeated over `spanMm` (span / value repeats of `repeats`:
// "levels", "turns", "passes", "pecks") within base::kMaxRepeats (base/RepeatLimit.h: more is a slip of the
// keyboard); else an error naming the count and the least value.
base::Status checkRepeats(const std::string& what, const std::string& parameter, double valueMm, double spanMm,
                          const std::string& repeats);
base::Error opError(const std::string& what, const std::string& message);  // "what: message"
base::Error cancelledError(const std::string& what);                       // "what: cancelled"

}  // namespace camwb::ops
