#include "ops/pocket/Program.h"

#include <cmath>

namespace camwb::ops::pocket {

Program makeProgram(std::vector<Cut> cuts, const geom::RegionIndex& region, EntryPlanner& planner)
{
    Program program;
    program.region = &region;
    program.cuts = std::move(cuts);
    for (std::size_t i = 0; i < program.cuts.size(); ++i) {
        const Cut& cut = program.cuts[i];
        program.linked.push_back(i > 0 && region.segmentInside(program.cuts[i - 1].end(), cut.start()));
        // Entries only where a cut may be entered (the first of each level, unlinked ones).
        program.entries.push_back(i == 0 || !program.linked.back() ? planner.plan(cut) : EntryPlan{});
    }
    return program;
}

void writeProgram(PathWriter& out, const Program& program, double top, double level, const Clearances& heights,
                  const EntrySettings& entry, Feed cutFeed)
{
    const Feed cutting = entry.cuttingFeed;
    for (std::size_t i = 0; i < program.cuts.size(); ++i) {
        const Cut& cut = program.cuts[i];
        const Vec2 start = cut.start();
        const bool atLevel = out.hasPosition() && std::abs(out.position().z - level) < 1e-9;
        if (atLevel && (program.linked[i] || (i == 0 && program.region->segmentInside(out.position().xy(), start)))) {
            out.feed({start.x, start.y, level}, cutting);
        } else {
            const Vec2 s = program.entries[i].start;
            const bool atTop = out.hasPosition() && std::abs(out.position().z - top) < 1e-9;
            if (atTop && program.region->segmentInside(out.position().xy(), s)) {
                out.feed({s.x, s.y, top}, cutting);  // across the level above, already cleared
            } else {
                if (out.hasPosition())
                    out.rapid({out.position().x, out.position().y, heights.safeZ});
                else
                    out.rapid({s.x, s.y, heights.clearanceZ});
                out.rapid({s.x, s.y, heights.safeZ});
                out.feed({s.x, s.y, top}, entry.plungeFeed);
            }
            writeEntry(out, program.entries[i], cut, top, level, entry);
        }
        out.path(cut.path, level, cutFeed);
    }
}

}  // namespace camwb::ops::pocket
