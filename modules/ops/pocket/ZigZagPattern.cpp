// Zig-zag pattern: parallel lines at the angle, stepover apart, clipped to the tool-centre region
// and joined back and forth while the connector stays inside; then the wall pass round the
// outer loops and the islands.
#include "geom/RegionIndex.h"
#include "geom/RegionOps.h"
#include "ops/pocket/Patterns.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::ops::pocket {

namespace {

struct Piece {
    Vec2 a, b;  // a before b along the line direction
    bool used = false;
};

}  // namespace

std::optional<std::vector<Cut>> zigZagPattern(const PatternInput& in, const Progress& progress)
{
    const std::vector<geom::Region>& region = *in.toolCentre;
    const double angle = in.zigZagAngleDeg * std::numbers::pi / 180.0;
    const Vec2 along{std::cos(angle), std::sin(angle)};
    const Vec2 across = along.leftNormal();

    double uMin = std::numeric_limits<double>::infinity(), uMax = -uMin;
    double vMin = uMin, vMax = -uMin;
    for (const geom::Region& r : region)
        for (const Vec2& p : samplePath(r.outer.segments, in.toleranceMm)) {
            uMin = std::min(uMin, p.dot(along));
            uMax = std::max(uMax, p.dot(along));
            vMin = std::min(vMin, p.dot(across));
            vMax = std::max(vMax, p.dot(across));
        }
    const double width = vMax - vMin;
    // Equal spacing no wider than the stepover; the outermost lines would run on the wall pass.
    // (Never a whole diameter apart: neighbouring footprints overlap rather than touch.)
    const double maxSpacing = std::min(in.stepover, 2 * in.radius - 2 * in.toleranceMm);
    const int count = std::max(2, static_cast<int>(std::ceil(width / maxSpacing - 1e-9)));
    const double spacing = width / count;
    std::vector<std::vector<Vec2>> lines;
    for (int j = 1; j < count; ++j) {
        const double v = vMin + spacing * j;
        lines.push_back({along * (uMin - 1) + across * v, along * (uMax + 1) + across * v});
    }
    // Clipped a tolerance inside the region, so that the line ends and the connectors between
    // them never rely on the clipper's rounding at the boundary.
    const std::vector<geom::Region> inner = geom::offsetRegions(region, -in.toleranceMm, in.toleranceMm);
    const std::vector<std::vector<Vec2>> clipped = geom::clipPolylines(lines, inner, in.toleranceMm);
    if (!progress.step(0.25))
        return std::nullopt;

    std::vector<std::vector<Piece>> byLine(lines.size());
    for (const std::vector<Vec2>& piece : clipped) {
        if (piece.size() < 2 || distance(piece.front(), piece.back()) < in.toleranceMm)
            continue;
        const double v = piece.front().dot(across);
        const long j = std::lround((v - vMin) / spacing) - 1;
        if (j < 0 || j >= static_cast<long>(lines.size()))
            continue;
        Piece p{piece.front(), piece.back()};
        if (p.a.dot(along) > p.b.dot(along))
            std::swap(p.a, p.b);
        byLine[static_cast<std::size_t>(j)].push_back(p);
    }
    for (std::vector<Piece>& pieces : byLine)
        std::sort(pieces.begin(), pieces.end(),
                  [&](const Piece& x, const Piece& y) { return x.a.dot(along) < y.a.dot(along); });

    const geom::RegionIndex links(region);
    std::vector<Cut> cuts;
    for (std::size_t j = 0; j < byLine.size(); ++j)
        for (Piece& first : byLine[j]) {
            if (first.used)
                continue;
            first.used = true;
            Cut chain;
            chain.path.push_back(Segment::line(first.a, first.b));
            // Back and forth: the nearest free end on the next line whose connector stays inside
            // (a nearer piece may lie beyond an island or a bay of the wall).
            for (std::size_t next = j + 1; next < byLine.size(); ++next) {
                const Vec2 end = chain.end();
                std::vector<std::pair<double, std::pair<Piece*, bool>>> candidates;
                for (Piece& p : byLine[next])
                    if (!p.used)
                        for (const bool a : {true, false})
                            candidates.push_back({distance(end, a ? p.a : p.b), {&p, a}});
                std::sort(candidates.begin(), candidates.end(),
                          [](const auto& x, const auto& y) { return x.first < y.first; });
                const auto linkable = std::find_if(candidates.begin(), candidates.end(), [&](const auto& c) {
                    return links.segmentInside(end, c.second.second ? c.second.first->a : c.second.first->b);
                });
                if (linkable == candidates.end())
                    break;
                auto [best, fromA] = linkable->second;
                const Vec2 s = fromA ? best->a : best->b;
                const Vec2 e = fromA ? best->b : best->a;
                best->used = true;
                appendLine(chain.path, end, s);
                chain.path.push_back(Segment::line(s, e));
            }
            cuts.push_back(std::move(chain));
        }
    if (!progress.step(0.4))
        return std::nullopt;

    std::optional<Vec2> from;
    if (!cuts.empty())
        from = cuts.back().end();
    for (Cut& wall : wallLoops(region, in.climb, from))
        cuts.push_back(std::move(wall));
    return cuts;
}

}  // namespace camwb::ops::pocket
