// Feeds and speeds from a tool's cutting data (ops::CuttingData: vc, fz per material) and the
// job's stock material: n = vc·1000/(π·D), vf = fz·z·n, plunge and ramp feeds as fractions of vf,
// the spindle speed clamped to the machine's range (and the feed scaled with it) when a machine
// is given. Pure functions; the GUI's "Compute feeds and speeds" applies them to a job tool.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "kinematics/Machine.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::document {

// What was computed, and what the user should be told about it (a clamped spindle speed).
struct FeedsAndSpeeds {
    double spindleRpm = 0;
    double cuttingFeedMmPerMin = 0;
    double plungeFeedMmPerMin = 0;
    double rampFeedMmPerMin = 0;  // 0: the cutting feed
    std::vector<std::string> notes;
};

// The tool's cutting data for `material` (compared without case), nullptr when it has none.
const ops::CuttingData* cuttingDataFor(const ops::ToolController& tc, const std::string& material);

// Computes from `data` for `tool`; `machine` (may be null) limits the spindle speed. Errors name
// the tool: no diameter, no flutes, no vc or fz.
base::Result<FeedsAndSpeeds> computeFeeds(const toolpath::Tool& tool, const ops::CuttingData& data,
                                          const kinematics::Machine* machine);

// `tc` with its speeds and feeds computed for `material` from its own cutting data; an error when
// no material is given or the tool has no cutting data for it (naming the materials it has).
base::Result<FeedsAndSpeeds> feedsFor(const ops::ToolController& tc, const std::string& material,
                                      const kinematics::Machine* machine);
void applyFeeds(ops::ToolController& tc, const FeedsAndSpeeds& feeds);

// Computes the feeds of the job's tool `number` (0: of every tool with cutting data for the job's
// material; the others are named in the notes) and applies them. An error, and the job unchanged,
// when nothing could be computed or the one tool asked for cannot be.
base::Result<std::vector<std::string>> computeJobFeeds(Job& job, int number, const kinematics::Machine* machine);

}  // namespace camwb::document
