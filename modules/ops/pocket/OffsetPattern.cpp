// Offset pattern: rings from the walls inward, each region's children cut depth first, and the
// shared wall-loop ordering (also the zig-zag's wall pass and the finishing pass).
#include "geom/RegionOps.h"
#include "ops/pocket/Patterns.h"

#include <limits>

namespace camwb::ops::pocket {

namespace {

// The region's loops in the milling direction: climb = outer ccw, holes cw.
std::vector<std::vector<Segment>> millingLoops(const geom::Region& region, bool climb)
{
    std::vector<std::vector<Segment>> loops;
    auto add = [&](const geom::Profile& loop, bool wantCcw) {
        if (loop.segments.empty())
            return;
        const bool isCcw = loop.signedArea() > 0;
        loops.push_back(isCcw == wantCcw ? loop.segments : loop.reversed().segments);
    };
    add(region.outer, climb);
    for (const geom::Profile& hole : region.holes)
        add(hole, !climb);
    return loops;
}

struct OffsetWalker {
    const PatternInput& in;
    const Progress& progress;
    double totalArea = 0;
    double doneArea = 0;
    double ringDelta = 0;
    std::vector<Cut> cuts;
    std::optional<Vec2> at;

    bool cutRegion(const geom::Region& region)
    {
        for (Cut& cut : wallLoops({region}, in.climb, at))
            cuts.push_back(std::move(cut));
        if (!cuts.empty())
            at = cuts.back().end();
        std::vector<geom::Region> children = geom::offsetRegions({region}, -ringDelta, in.toleranceMm);
        doneArea += region.area() - geom::totalArea(children);
        if (!progress.step(0.5 * std::min(1.0, doneArea / totalArea)))
            return false;
        // Depth first: the nearest child next, its whole branch, then the next nearest.
        while (!children.empty()) {
            std::size_t best = 0;
            double bestDistance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < children.size(); ++i) {
                const double d = at ? nearestOnPath(children[i].outer.segments, *at).distance : 0.0;
                if (d < bestDistance) {
                    best = i;
                    bestDistance = d;
                }
            }
            const geom::Region child = std::move(children[best]);
            children.erase(children.begin() + static_cast<std::ptrdiff_t>(best));
            if (!cutRegion(child))
                return false;
        }
        return true;
    }
};

}  // namespace

std::vector<Cut> wallLoops(const std::vector<geom::Region>& regions, bool climb, std::optional<Vec2> from)
{
    std::vector<std::vector<Segment>> loops;
    for (const geom::Region& region : regions)
        for (std::vector<Segment>& loop : millingLoops(region, climb))
            loops.push_back(std::move(loop));
    std::vector<Cut> cuts;
    std::vector<bool> done(loops.size(), false);
    for (std::size_t n = 0; n < loops.size(); ++n) {
        if (!from) {
            // No previous position: the first region's outer loop from its longest side.
            done[0] = true;
            cuts.push_back({loopAtLongest(loops[0]), true});
            from = cuts.back().end();
            continue;
        }
        std::size_t best = 0;
        PathPoint bestPoint;
        bestPoint.distance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < loops.size(); ++i) {
            if (done[i])
                continue;
            const PathPoint p = nearestOnPath(loops[i], *from);
            if (p.distance < bestPoint.distance) {
                best = i;
                bestPoint = p;
            }
        }
        done[best] = true;
        cuts.push_back({loopFrom(loops[best], bestPoint.segment, bestPoint.t), true});
        from = cuts.back().end();
    }
    return cuts;
}

std::optional<std::vector<Cut>> offsetPattern(const PatternInput& in, const Progress& progress)
{
    // Shrinking adds a safety margin to the offset; ask for that much less so that the rings lie a
    // stepover apart, and keep them a little closer than the diameter so that neighbouring
    // footprints overlap rather than touch (a 100 % stepover would leave hairlines).
    const double spacing = std::min(in.stepover, 2 * in.radius - 2 * in.toleranceMm);
    const double ringDelta = std::max(spacing - geom::offsetSafetyMargin(in.toleranceMm), 0.5 * spacing);
    OffsetWalker walker{in, progress, 0, 0, ringDelta, {}, {}};
    walker.totalArea = std::max(geom::totalArea(*in.toolCentre), 1e-12);
    std::vector<geom::Region> roots = *in.toolCentre;
    while (!roots.empty()) {
        std::size_t best = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < roots.size() && walker.at; ++i) {
            const double d = nearestOnPath(roots[i].outer.segments, *walker.at).distance;
            if (d < bestDistance) {
                best = i;
                bestDistance = d;
            }
        }
        const geom::Region root = std::move(roots[best]);
        roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(best));
        if (!walker.cutRegion(root))
            return std::nullopt;
    }
    return std::move(walker.cuts);
}

}  // namespace camwb::ops::pocket
