// Waterline: per level, the loops round where the tool with its tip at the level touches the model
// (DropContours: the drop-cutter's heights contoured), fitted with lines and arcs and grown by the
// errors of the chords, the fit and the points cut along them, are the contours. Their points are
// kept where the wall is steep: the contour a little higher (dz) lies within dz / tan(minSlope)
// inward of them (on a wall of slope a the contour moves dz / tan(a) per dz, for the tool-centre
// surface as for the model), which one drop there tells. Each steep run is cut in the milling
// direction, entered and left by a short lead where it stays clear, retracting to the safe height
// between runs.
#include "ops/WaterlineOp.h"

#include "base/NumberFormat.h"
#include "geom/ArcFit.h"
#include "geom/RegionIndex.h"
#include "geom/RegionOps.h"
#include "ops/pocket/PathWriter.h"
#include "ops/surface/AllCores.h"
#include "ops/surface/DropContours.h"
#include "ops/surface/DropCutter.h"
#include "ops/surface/ToolCentre.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::ops {

namespace {

using base::Vec2;
constexpr double kPi = std::numbers::pi;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

double stepFor(const WaterlineParams& p, const toolpath::Tool& tool);

// The area's box: where the contours are looked for.
std::pair<Vec2, Vec2> boundsOf(const std::vector<geom::Region>& area, double tol)
{
    Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    for (const geom::Region& region : area)
        for (const Vec2& p : geom::discretize(region.outer, tol)) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
    return {lo, hi};
}

// Drop heights the contours' grid may take: more is a tolerance too fine for the area.
constexpr double kMaxGridPoints = 16e6;

base::Status check(const std::string& what, const SurfaceInput& in, const WaterlineParams& p, const ToolController& tc)
{
    if (base::Status s = checkToolController(what, tc); !s)
        return s;
    if (base::Status s = checkHeights(what, p.heights); !s)
        return s;
    if (base::Status s = surface::checkSurfaceInput(what, in, "finish"); !s)
        return s;
    if (!(p.scallopMm > 0))
        return opError(what, "scallop height must be positive, got " + fmt(p.scallopMm) + " mm");
    if (!(p.maxStepDownMm > 0))
        return opError(what, "largest step-down must be positive, got " + fmt(p.maxStepDownMm) + " mm");
    if (!(p.minSlopeDeg >= 0) || p.minSlopeDeg >= 90)
        return opError(what, "slope limit must be in [0, 90) degrees, got " + fmt(p.minSlopeDeg));
    if (!(p.stockMm >= 0))
        return opError(what, "stock to leave must not be negative, got " + fmt(p.stockMm) + " mm");
    if (!(p.toleranceMm > 0) || p.toleranceMm > 1)
        return opError(what, "tolerance must be in (0, 1] mm, got " + fmt(p.toleranceMm) + " mm");
    if (base::Status s = checkRepeats(what, "step-down (from the scallop height)", stepFor(p, tc.tool),
                                      p.heights.startZ - p.heights.finalZ, "levels");
        !s)
        return s;
    const double grid = surface::DropContours::step(tc.tool, p.stockMm, p.toleranceMm);
    if (!(grid > 0))
        return opError(what, "a pointed " + tc.tool.kind +
                                 " cannot follow a waterline within a tolerance: use a flat, ball or bull-nose cutter");
    const auto [lo, hi] = boundsOf(surface::toolCentreArea(in), p.toleranceMm);
    const double points = ((hi.x - lo.x) / grid + 5) * ((hi.y - lo.y) / grid + 5);
    if (points > kMaxGridPoints)
        return opError(what, "the tolerance " + base::NumberFormat{8, true}.format(p.toleranceMm) + " mm needs " +
                                 fmt(std::round(points / 1e6)) + " million drops over the area (at most " +
                                 fmt(kMaxGridPoints / 1e6) + " million): raise the tolerance or narrow the boundary");
    return base::Status::success();
}

// The vertical step between contours that keeps the scallop on walls at the slope limit (the
// flattest walls cut; steeper ones get less) below h. A round cutter (ball, bull-nose corner of
// radius c) leaves c - sqrt(c^2 - (w/2)^2) between passes w apart along the wall, w = step / sin(a);
// a flat end leaves a stair step * cos(a). Below 5 degrees the wall is taken as 5 degrees.
double stepFor(const WaterlineParams& p, const toolpath::Tool& tool)
{
    const double a = std::max(p.minSlopeDeg, 5.0) * kPi / 180, h = p.scallopMm;
    const double c = tool.kind == "ball" ? tool.diameterMm / 2 : tool.cornerRadiusMm;
    double step = h / std::cos(a);
    if (c > h)
        step = 2 * std::sin(a) * std::sqrt(c * c - (c - h) * (c - h));
    return std::min(step, p.maxStepDownMm);
}

std::vector<double> levelsOf(const WaterlineParams& p, const toolpath::Tool& tool)
{
    std::vector<double> levels{p.heights.startZ};
    for (double z : stepDownLevels(p.heights.startZ, p.heights.finalZ, stepFor(p, tool)))
        levels.push_back(z);
    return levels;
}

struct Contour {
    std::vector<Vec2> points;
    bool closed = false;
};

// The runs of each obstacle loop (material on its left) that lie on steep walls, in the loop's
// direction; a loop steep all round stays closed. `steepAt(p, inward)` tells a point.
template <class Steep>
std::vector<Contour> steepRuns(const std::vector<geom::Region>& obstacle, double tol, const Steep& steepAt)
{
    std::vector<Contour> out;
    const auto runsOf = [&](const geom::Profile& loop) {
        // The grown loop's round joins (one at every corner of the fit) would double its points:
        // fitted again, nearly straight runs through them become single lines.
        const std::vector<Vec2> pts =
            geom::discretize(geom::fitLinesAndArcs(geom::discretize(loop, tol / 16), true, tol / 16), tol / 8);
        const std::size_t n = pts.size();
        if (n < 3)
            return;
        std::vector<char> steep(n);
        for (std::size_t i = 0; i < n; ++i)
            steep[i] = steepAt(pts[i], (pts[(i + 1) % n] - pts[(i + n - 1) % n]).normalized().leftNormal());
        if (std::all_of(steep.begin(), steep.end(), [](char s) { return s; })) {
            out.push_back({pts, true});
            return;
        }
        // Start after a shallow point so that no run wraps round the loop's start.
        std::size_t first = 0;
        while (steep[first])
            ++first;
        Contour run;
        for (std::size_t k = 1; k <= n; ++k) {
            const std::size_t i = (first + k) % n;
            if (steep[i]) {
                run.points.push_back(pts[i]);
                continue;
            }
            if (run.points.size() >= 2)
                out.push_back(run);
            run.points.clear();
        }
    };
    for (const geom::Region& region : obstacle) {
        runsOf(region.outer);
        for (const geom::Profile& hole : region.holes)
            runsOf(hole);
    }
    return out;
}

// What the contours are grown by: what the chords between crossings (tol / 2 at most), the fit
// (tol / 4) and the points the passes take along the grown loops (a quarter: their points and
// the refit at a sixteenth each, the points along the refit's arcs an eighth) may bring the tool
// closer.
double growthFor(double tol) { return tol / 2 + tol / 4 + tol / 4; }

// The loops round where the tool touches at z as regions of material, fitted with lines and arcs
// and grown by growthFor(tol).
std::vector<geom::Region> obstacleAt(const surface::DropContours& contours, double z, double tol)
{
    std::vector<geom::Profile> loops;
    for (const std::vector<Vec2>& loop : contours.loopsAt(z))
        if (geom::Profile fitted = geom::fitLinesAndArcs(loop, true, tol / 4); !fitted.empty())
            loops.push_back(std::move(fitted));
    return geom::offsetRegions(geom::regionsFromLoops(loops, tol), growthFor(tol), tol);
}

}  // namespace

base::Result<OpResult> computeWaterline(const SurfaceInput& input, const WaterlineParams& params,
                                        const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = "waterline \"" + params.name + "\"";
    if (base::Status s = check(what, input, params, tc); !s)
        return s.error();
    const double tol = params.toleranceMm;
    const surface::DropCutter cutter(*input.model, tc.tool, params.stockMm);
    const std::vector<geom::Region> area = surface::toolCentreArea(input);
    const auto [lo, hi] = boundsOf(area, tol);
    const surface::DropContours contours(cutter, lo, hi, surface::DropContours::step(tc.tool, params.stockMm, tol),
                                         tol / 4, tol, progress, 0, 0.3);
    if (!contours.complete())
        return cancelledError(what);
    const std::vector<double> levels = levelsOf(params, tc.tool);
    const std::vector<geom::Region> grownAreaRegions = geom::offsetRegions(area, tc.tool.diameterMm, tol);
    const geom::RegionIndex grownArea(grownAreaRegions);  // shared by the levels' workers
    const double dz = std::max(0.25, 10 * tol);
    const double reach = params.minSlopeDeg > 0 ? dz / std::tan(params.minSlopeDeg * kPi / 180) : INFINITY;
    const double lead = std::min(tc.tool.diameterMm / 4, 2.0);
    const Feed finishing = feedOf(tc, toolpath::FeedKind::Finishing);
    const Feed plunge = feedOf(tc, toolpath::FeedKind::Plunge);
    const Feed exit = feedOf(tc, toolpath::FeedKind::Exit);

    // Each level's passes on all cores (they depend only on the model), then written in order.
    struct Pass {
        std::vector<Vec2> points;
        Vec2 in, out;  // lead in and out: off the material where that stays clear, else the ends
    };
    std::vector<std::vector<Pass>> passes(levels.size());
    const auto passesAt = [&](std::size_t l) {
        const double z = levels[l];
        // Steep where the tool dz higher, dz / tan(minSlope) further in from the contact (the
        // contour stands growthFor(tol) off it), still stands higher (no floor to ignore there:
        // the slope alone decides); without a slope limit every wall is.
        const auto steepAt = [&](Vec2 p, Vec2 inward) {
            return std::isinf(reach) || cutter.dropZ(p + inward * (reach + growthFor(tol))) > z + dz;
        };
        // Leads off the material (to the left of travel in climb, right otherwise) where clear:
        // inside the area grown by the tool and touching nowhere along the way.
        const auto leadPoint = [&](Vec2 at, Vec2 dir) {
            const double len = dir.length();
            if (!(len > 0))
                return at;
            const double side = params.climb ? 1 : -1;
            const Vec2 q = at + dir.leftNormal() * (side * lead / len);
            if (!grownArea.segmentInside(at, q))
                return at;
            const int n = std::max(4, int(std::ceil(lead / contours.gridStep())));
            for (int k = 1; k <= n; ++k)
                if (contours.touches(at + (q - at) * (double(k) / n), z))
                    return at;
            return q;
        };
        for (Contour& c : steepRuns(obstacleAt(contours, z, tol), tol, steepAt)) {
            // Material on the left as found; climb milling keeps it on the right.
            if (params.climb)
                std::reverse(c.points.begin(), c.points.end());
            if (c.closed)
                c.points.push_back(c.points.front());
            for (std::vector<Vec2>& piece : geom::clipPolylines({c.points}, area, tol)) {
                if (piece.size() < 2)
                    continue;
                const Vec2 in = leadPoint(piece.front(), piece[1] - piece[0]);
                const Vec2 out = leadPoint(piece.back(), piece.back() - piece[piece.size() - 2]);
                passes[l].push_back({std::move(piece), in, out});
            }
        }
    };
    if (!surface::forEachOnAllCores(levels.size(), passesAt, progress, 0.3, 0.95))
        return cancelledError(what);

    OpResult result;
    pocket::PathWriter out(result.toolpath, operationIndex);
    out.add(sectionBegin(params.name, "waterline", tc, {toolpath::FeedKind::Finishing, toolpath::FeedKind::Exit}));
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const double z = levels[l];
        for (const Pass& pass : passes[l]) {
            if (out.hasPosition())
                out.rapid({out.position().x, out.position().y, params.heights.safeZ});
            else
                out.rapid({pass.in.x, pass.in.y, params.heights.clearanceZ});
            out.rapid({pass.in.x, pass.in.y, params.heights.safeZ});
            out.feed({pass.in.x, pass.in.y, z}, plunge);
            for (const Vec2& p : pass.points)
                out.feed({p.x, p.y, z}, finishing);
            out.feed({pass.out.x, pass.out.y, z}, exit);
        }
    }
    if (out.hasPosition())
        out.rapid({out.position().x, out.position().y, params.heights.clearanceZ});
    else
        result.warn(what + ": no wall steeper than " + fmt(params.minSlopeDeg) + " degrees between " +
                    fmt(params.heights.startZ) + " and " + fmt(params.heights.finalZ) + ": nothing to cut");
    out.add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
