#include "post/ProgramSummary.h"

#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"

#include <algorithm>
#include <optional>

namespace camwb::post {

using namespace toolpath;

ProgramSummary summarizeProgram(const Toolpath& toolpath)
{
    ProgramSummary summary;
    base::Box3 extents;
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
            if (!offsetSeen && extents.empty)
                summary.firstWorkOffset = w->index;
            offsetSeen = true;
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            const bool known = std::any_of(summary.tools.begin(), summary.tools.end(),
                                           [&](const Tool& tool) { return tool.number == t->tool.number; });
            if (!known)
                summary.tools.push_back(t->tool);
        }
    }
    summary.hasMotion = !extents.empty;
    summary.min = extents.min;
    summary.max = extents.max;
    return summary;
}

}  // namespace camwb::post
