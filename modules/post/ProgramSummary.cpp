#include "post/ProgramSummary.h"

#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"

#include <algorithm>
#include <optional>

namespace camwb::post {

using namespace toolpath;

namespace {

// Grows a box over tool positions axis by axis: a move that gives only Z widens only Z, and an
// axis no move gave has no extent (base::Box3 knows only all three or none).
// Points in a tilted working plane's frame count in the workpiece frame, and only when the move
// gives all three axes (one axis of the plane is no axis of the workpiece).
struct AxisExtents {
    AxisMask seen{0};
    Vec3 min, max;
    WorkingPlane plane;
    bool any() const { return !seen.none(); }
    void add(Vec3 p, AxisMask axes = {})
    {
        if (plane.tilted()) {
            if (!axes.all())
                return;
            p = plane.toWorkpiece(p);
        }
        for (int axis = 0; axis < 3; ++axis) {
            if (!axes.has(axis))
                continue;
            const double v = axisValue(p, axis);
            const bool first = !seen.has(axis);
            setAxisValue(min, axis, first ? v : std::min(axisValue(min, axis), v));
            setAxisValue(max, axis, first ? v : std::max(axisValue(max, axis), v));
        }
        seen.bits |= axes.bits;
    }
};

}  // namespace

ProgramSummary summarizeProgram(const Toolpath& toolpath)
{
    ProgramSummary summary;
    AxisExtents extents;
    KnownPosition position;
    bool offsetSeen = false;
    for (const Record& record : toolpath.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            extents.add(r->to, r->axes);
            position.moveTo(*r);
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            extents.add(l->to, l->axes);
            position.moveTo(*l);
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            if (const std::optional<Vec3> start = position.point()) {
                Vec3 min = *start, max = *start;
                extendByArc(min, max, *start, *a);
                for (const Vec3& corner : base::boxCorners(min, max))  // in any frame the arc lies within them
                    extents.add(corner);
            } else {
                extents.add(a->to);
            }
            position.set(a->to);
        } else if (const auto* m = std::get_if<ToolAxisMove>(&record)) {
            extents.add(m->tip);
            position.set(m->tip);
        } else if (const auto* c = std::get_if<Cycle>(&record)) {
            for (const Vec3& hole : c->holes) {
                extents.add({hole.x, hole.y, std::max(cycleReturnZ(*c), c->retractZ)});
                extents.add({hole.x, hole.y, c->bottomZ});
            }
            if (!c->holes.empty())
                position.set({c->holes.back().x, c->holes.back().y, cycleReturnZ(*c)});
        } else if (const auto* unknown = std::get_if<UnknownAxes>(&record)) {
            position.forget(unknown->axes);
        } else if (const auto* plane = std::get_if<WorkingPlane>(&record)) {
            const std::optional<Vec3> at = position.point();
            position = KnownPosition{};
            if (at)
                position.set(plane->toLocal(extents.plane.toWorkpiece(*at)));
            extents.plane = *plane;
        } else if (const auto* w = std::get_if<WorkOffset>(&record)) {
            if (!offsetSeen && !extents.any())
                summary.firstWorkOffset = w->index;
            offsetSeen = true;
        } else if (const auto* t = std::get_if<ToolChange>(&record)) {
            const bool known = std::any_of(summary.tools.begin(), summary.tools.end(),
                                           [&](const Tool& tool) { return tool.number == t->tool.number; });
            if (!known)
                summary.tools.push_back(t->tool);
        }
    }
    summary.hasMotion = extents.any();
    summary.extentAxes = extents.seen;
    summary.min = extents.min;
    summary.max = extents.max;
    return summary;
}

}  // namespace camwb::post
