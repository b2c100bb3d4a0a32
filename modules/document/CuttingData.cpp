#include "document/CuttingData.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

namespace camwb::document {

namespace {

bool sameText(const std::string& a, const std::string& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](unsigned char x, unsigned char y) { return std::tolower(x) == std::tolower(y); });
}

std::string toolLabel(const toolpath::Tool& tool)
{
    return "tool T" + std::to_string(tool.number) + " \"" + tool.name + "\"";
}

std::string rpmText(double rpm) { return std::to_string(static_cast<long long>(rpm + 0.5)) + " rpm"; }

}  // namespace

const ops::CuttingData* cuttingDataFor(const ops::ToolController& tc, const std::string& material)
{
    for (const ops::CuttingData& data : tc.cuttingData)
        if (sameText(data.material, material))
            return &data;
    return nullptr;
}

base::Result<FeedsAndSpeeds> computeFeeds(const toolpath::Tool& tool, const ops::CuttingData& data,
                                          const kinematics::Machine* machine)
{
    const std::string what = toolLabel(tool);
    if (!(tool.diameterMm > 0))
        return base::makeError(what + ": the diameter must be positive to compute the spindle speed");
    if (tool.flutes < 1)
        return base::makeError(what + ": the number of flutes must be at least 1 to compute the feed");
    if (!(data.vcMPerMin > 0) || !(data.fzMm > 0))
        return base::makeError(what + ": the cutting data for \"" + data.material + "\" needs vc and fz above 0");

    FeedsAndSpeeds out;
    out.spindleRpm = data.vcMPerMin * 1000.0 / (std::numbers::pi * tool.diameterMm);
    if (machine) {
        // The chip load (fz) is what the tool can take, so the feed follows a clamped speed.
        const double wanted = out.spindleRpm;
        if (machine->spindleMaxRpm > 0 && wanted > machine->spindleMaxRpm) {
            out.spindleRpm = machine->spindleMaxRpm;
            out.notes.push_back(what + ": " + rpmText(wanted) + " is above the machine's spindle maximum; " +
                                rpmText(out.spindleRpm) + " used, the feed reduced with it");
        } else if (machine->spindleMinRpm > 0 && wanted < machine->spindleMinRpm) {
            out.spindleRpm = machine->spindleMinRpm;
            out.notes.push_back(what + ": " + rpmText(wanted) + " is below the machine's spindle minimum; " +
                                rpmText(out.spindleRpm) + " used, the feed raised with it");
        }
    }
    // Whole rpm and mm/min: what an operator reads on the setup sheet and types at the control.
    out.spindleRpm = std::round(out.spindleRpm);
    out.cuttingFeedMmPerMin = std::round(data.fzMm * tool.flutes * out.spindleRpm);
    // Not given: a drill plunges at its feed, a mill at half of it (textbook default).
    const double plunge = data.plungeFraction > 0 ? data.plungeFraction : tool.kind == "drill" ? 1.0 : 0.5;
    out.plungeFeedMmPerMin = std::round(out.cuttingFeedMmPerMin * plunge);
    out.rampFeedMmPerMin = data.rampFraction > 0 ? std::round(out.cuttingFeedMmPerMin * data.rampFraction) : 0;
    return out;
}

base::Result<FeedsAndSpeeds> feedsFor(const ops::ToolController& tc, const std::string& material,
                                      const kinematics::Machine* machine)
{
    const std::string what = toolLabel(tc.tool);
    if (material.empty())
        return base::makeError(what + ": the job gives no stock material to choose the cutting data by");
    if (const ops::CuttingData* data = cuttingDataFor(tc, material))
        return computeFeeds(tc.tool, *data, machine);
    std::string known;
    for (const ops::CuttingData& data : tc.cuttingData)
        known += (known.empty() ? "" : ", ") + data.material;
    return base::makeError(what + ": no cutting data for \"" + material + "\"" +
                           (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
}

void applyFeeds(ops::ToolController& tc, const FeedsAndSpeeds& feeds)
{
    tc.spindleRpm = feeds.spindleRpm;
    tc.cuttingFeedMmPerMin = feeds.cuttingFeedMmPerMin;
    tc.plungeFeedMmPerMin = feeds.plungeFeedMmPerMin;
    tc.rampFeedMmPerMin = feeds.rampFeedMmPerMin;
}

base::Result<std::vector<std::string>> computeJobFeeds(Job& job, int number, const kinematics::Machine* machine)
{
    Job edited = job;
    std::vector<std::string> notes;
    int computed = 0;
    for (ops::ToolController& tc : edited.tools) {
        if (number != 0 && tc.tool.number != number)
            continue;
        auto feeds = feedsFor(tc, edited.material, machine);
        if (!feeds) {
            if (number != 0)
                return feeds.error();
            notes.push_back(feeds.error().message + "; left as it was");
            continue;
        }
        applyFeeds(tc, feeds.value());
        notes.insert(notes.end(), feeds->notes.begin(), feeds->notes.end());
        ++computed;
    }
    if (number != 0 && computed == 0)
        return base::makeError("the job has no tool T" + std::to_string(number));
    if (computed == 0)
        return base::makeError(edited.material.empty()
                                   ? std::string("the job gives no stock material to choose the cutting data by")
                                   : "no tool of the job has cutting data for \"" + edited.material + "\"");
    job = std::move(edited);
    return notes;
}

}  // namespace camwb::document
