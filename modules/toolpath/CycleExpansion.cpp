#include "toolpath/CycleExpansion.h"

#include "base/RepeatLimit.h"

#include <algorithm>

namespace camwb::toolpath {

double cycleReturnZ(const Cycle& cycle)
{
    return cycle.returnToClearance ? std::max(cycle.clearanceZ, cycle.retractZ) : cycle.retractZ;
}

std::optional<std::string> tooManyPecks(const Cycle& cycle)
{
    if (cycle.kind != CycleKind::Peck && cycle.kind != CycleKind::ChipBreak)
        return std::nullopt;
    // As expandCycleHole pecks: from the hole's top (or the R plane below it) to the bottom.
    return base::tooManyRepeats("peck depth", cycle.peckMm, std::min(cycle.topZ, cycle.retractZ) - cycle.bottomZ,
                                "pecks", "a cycle");
}

std::vector<Record> expandCycleHole(const Cycle& cycle, const Vec3& hole, const Vec3& from, const SpindleState& spindle)
{
    return expandCycleHole(cycle, hole, KnownPosition(from), spindle);
}

std::vector<Record> expandCycleHole(const Cycle& cycle, const Vec3& hole, const KnownPosition& from,
                                    const SpindleState& spindle)
{
    std::vector<Record> out;
    Vec3 at = from.value();
    auto rapid = [&](const Vec3& to) {
        if (!(to == at))
            out.push_back(Rapid{to});
        at = to;
    };
    // Into the hole: Plunge; back out at feed (tapping, boring): Exit. Both at the cycle's feed.
    auto feed = [&](double z, FeedKind kind) {
        at = {hole.x, hole.y, z};
        out.push_back(Linear{at, cycle.feedMmPerMin, {}, kind});
    };
    auto dwellAtBottom = [&] {
        if (cycle.dwellSeconds > 0)
            out.push_back(Dwell{cycle.dwellSeconds});
    };

    const double r = cycle.retractZ;
    const double bottom = cycle.bottomZ;
    if (at.z < r) {
        if (from.complete()) {
            rapid({at.x, at.y, r});
        } else {
            out.push_back(Rapid{{0, 0, r}, AxisMask{AxisMask::kZ}});
            at.z = r;
        }
    }
    const Vec3 over{hole.x, hole.y, at.z};
    if (from.complete()) {
        rapid(over);
    } else {
        out.push_back(Rapid{over});  // from an X/Y nobody knows: always written
        at = over;
    }
    rapid({hole.x, hole.y, r});

    switch (cycle.kind) {
    case CycleKind::Drill:
    case CycleKind::DrillDwell:
        feed(bottom, FeedKind::Plunge);
        dwellAtBottom();
        break;
    case CycleKind::Peck:
    case CycleKind::ChipBreak: {
        if (tooManyPecks(cycle))
            break;  // no motion into the hole: its source reports the error (header)
        const bool fullRetract = cycle.kind == CycleKind::Peck;
        // A peck of 0 (or less) would never reach the bottom: drill in one go.
        const double step = cycle.peckMm > 0 ? cycle.peckMm : r - bottom;
        double depth = std::min(cycle.topZ, r);
        while (true) {
            depth = std::max(depth - step, bottom);
            feed(depth, FeedKind::Plunge);
            if (depth <= bottom)
                break;
            if (fullRetract) {
                rapid({hole.x, hole.y, r});
                rapid({hole.x, hole.y, std::min(depth + kPeckClearanceMm, r)});
            } else {
                rapid({hole.x, hole.y, std::min(depth + kPeckClearanceMm, r)});
            }
        }
        dwellAtBottom();
        break;
    }
    case CycleKind::Tap:
        feed(bottom, FeedKind::Plunge);
        dwellAtBottom();
        out.push_back(Spindle{spindle.rpm, !spindle.clockwise});
        feed(r, FeedKind::Exit);
        out.push_back(Spindle{spindle.rpm, spindle.clockwise});
        break;
    case CycleKind::Bore:
        feed(bottom, FeedKind::Plunge);
        dwellAtBottom();
        feed(r, FeedKind::Exit);
        break;
    }
    rapid({hole.x, hole.y, cycleReturnZ(cycle)});
    return out;
}

}  // namespace camwb::toolpath
