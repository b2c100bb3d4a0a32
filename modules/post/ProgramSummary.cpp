#include "post/ProgramSummary.h"

#include "base/NumberFormat.h"
#include "post/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/RecordNames.h"

#include <algorithm>
#include <map>
#include <optional>

namespace camwb::post {

using namespace toolpath;

namespace {

std::string mm(double value) { return base::NumberFormat{3, true}.format(value); }

// Grows a box over tool positions.
struct Extents {
    bool any = false;
    Vec3 min, max;
    void add(const Vec3& p)
    {
        if (!any) {
            min = max = p;
            any = true;
            return;
        }
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
};

// Collects the violations of one limit: the first record and the count make one message.
struct Violations {
    struct Entry {
        std::string text;
        std::size_t firstRecord = 0;
        int count = 0;
    };
    std::map<std::string, Entry> byKey;  // ordered: messages come out in a stable order
    void add(const std::string& key, std::size_t record, const std::string& text)
    {
        Entry& entry = byKey[key];
        if (entry.count++ == 0) {
            entry.text = text;
            entry.firstRecord = record;
        }
    }
};

}  // namespace

ProgramSummary summarizeProgram(const Toolpath& toolpath)
{
    ProgramSummary summary;
    Extents extents;
    std::optional<Vec3> position;
    bool offsetSeen = false;
    for (const Record& record : toolpath.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            extents.add(r->to);
            position = r->to;
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            extents.add(l->to);
            position = l->to;
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            if (position) {
                Vec3 min = *position, max = *position;
                extendByArc(min, max, *position, *a);
                extents.add(min);
                extents.add(max);
            } else {
                extents.add(a->to);
            }
            position = a->to;
        } else if (const auto* m = std::get_if<ToolAxisMove>(&record)) {
            extents.add(m->tip);
            position = m->tip;
        } else if (const auto* c = std::get_if<Cycle>(&record)) {
            for (const Vec3& hole : c->holes) {
                extents.add({hole.x, hole.y, std::max(cycleReturnZ(*c), c->retractZ)});
                extents.add({hole.x, hole.y, c->bottomZ});
            }
            if (!c->holes.empty())
                position = Vec3{c->holes.back().x, c->holes.back().y, cycleReturnZ(*c)};
        } else if (const auto* w = std::get_if<WorkOffset>(&record)) {
            if (!offsetSeen && !extents.any)
                summary.firstWorkOffset = w->index;
            offsetSeen = true;
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            const bool known = std::any_of(summary.tools.begin(), summary.tools.end(),
                                           [&](const Tool& tool) { return tool.number == t->tool.number; });
            if (!known)
                summary.tools.push_back(t->tool);
        }
    }
    summary.hasMotion = extents.any;
    summary.min = extents.min;
    summary.max = extents.max;
    return summary;
}

std::vector<PostMessage> checkMachineLimits(const Toolpath& toolpath, const ProgramSummary& summary,
                                            const kinematics::Machine& machine)
{
    Violations v;
    const std::string& name = machine.name.empty() ? machine.id : machine.name;
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        const Record& record = toolpath.record(i);
        if (const auto* s = std::get_if<Spindle>(&record); s && s->rpm > 0) {
            if (machine.spindleMaxRpm > 0 && s->rpm > machine.spindleMaxRpm)
                v.add("spindle max", i,
                      "spindle speed " + mm(s->rpm) + " rpm is above the " + name + "'s maximum of " +
                          mm(machine.spindleMaxRpm) + " rpm");
            if (s->rpm < machine.spindleMinRpm)
                v.add("spindle min", i,
                      "spindle speed " + mm(s->rpm) + " rpm is below the " + name + "'s minimum of " +
                          mm(machine.spindleMinRpm) + " rpm");
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            const Tool& tool = t->tool;
            if (machine.toolStations > 0 && (tool.number < 1 || tool.number > machine.toolStations))
                v.add("tool station", i,
                      "tool T" + std::to_string(tool.number) + " has no station: the " + name + " has stations 1.." +
                          std::to_string(machine.toolStations));
            if (machine.maxToolDiameterMm > 0 && tool.diameterMm > machine.maxToolDiameterMm)
                v.add("tool diameter", i,
                      "tool T" + std::to_string(tool.number) + " is " + mm(tool.diameterMm) + " mm in diameter; the " +
                          name + " takes at most " + mm(machine.maxToolDiameterMm) + " mm");
            if (machine.maxToolLengthMm > 0 && tool.lengthMm > machine.maxToolLengthMm)
                v.add("tool length", i,
                      "tool T" + std::to_string(tool.number) + " is " + mm(tool.lengthMm) + " mm long; the " + name +
                          " takes at most " + mm(machine.maxToolLengthMm) + " mm");
        } else if (const auto* c = std::get_if<Coolant>(&record); c && c->mode != CoolantMode::Off) {
            if (!machine.hasCoolant(toolpath::name(c->mode)))
                v.add(std::string("coolant ") + toolpath::name(c->mode), i,
                      std::string("coolant ") + toolpath::name(c->mode) + " is not available on the " + name);
        } else if (machine.maxCuttingFeedMmPerMin > 0) {
            double feed = 0;
            if (const auto* l = std::get_if<Linear>(&record))
                feed = l->feedMmPerMin;
            else if (const auto* a = std::get_if<Arc>(&record))
                feed = a->feedMmPerMin;
            else if (const auto* cy = std::get_if<Cycle>(&record))
                feed = cy->feedMmPerMin;
            if (feed > machine.maxCuttingFeedMmPerMin)
                v.add("feed", i,
                      "feed " + mm(feed) + " mm/min is above the " + name + "'s maximum cutting feed of " +
                          mm(machine.maxCuttingFeedMmPerMin) + " mm/min");
        }
    }

    std::vector<PostMessage> messages;
    if (summary.hasMotion) {
        const double spans[3] = {summary.max.x - summary.min.x, summary.max.y - summary.min.y,
                                 summary.max.z - summary.min.z};
        const char* axes[3] = {"X", "Y", "Z"};
        for (int k = 0; k < 3; ++k) {
            const kinematics::Axis* axis = machine.axis(axes[k]);
            if (axis && spans[k] > axis->max - axis->min + 1e-6)
                messages.push_back({PostMessage::Severity::Warning,
                                    std::string("the program spans ") + mm(spans[k]) + " mm in " + axes[k] + "; the " +
                                        name + " travels " + mm(axis->max - axis->min) + " mm",
                                    {},
                                    0});
        }
    }
    for (const auto& [key, entry] : v.byKey) {
        std::string text = entry.text + " (CL record " + std::to_string(entry.firstRecord);
        if (entry.count > 1)
            text += "; " + std::to_string(entry.count) + " records in all";
        messages.push_back({PostMessage::Severity::Warning, text + ")", {}, 0});
    }
    return messages;
}

}  // namespace camwb::post
