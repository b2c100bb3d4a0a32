#include "ops/ParallelOp.h"

#include "base/NumberFormat.h"
#include "ops/ParallelGrid.h"
#include "ops/pocket/PathWriter.h"
#include "ops/surface/AllCores.h"
#include "ops/surface/CutLine.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops {

namespace {

using base::Vec3;

std::string fmt(double v) { return base::NumberFormat{4, true}.format(v); }

base::Status checkParams(const std::string& what, const SurfaceInput& input, const ParallelParams& p,
                         const ToolController& tc)
{
    if (auto status = checkToolController(what, tc); !status)
        return status;
    if (!(p.heights.clearanceZ >= p.heights.safeZ))
        return opError(what, "clearance height " + fmt(p.heights.clearanceZ) + " is below the safe height " +
                                 fmt(p.heights.safeZ));
    if (!(p.stepoverMm > 0) || !(p.stepoverMm <= tc.tool.diameterMm))
        return opError(what, "stepover must be above 0 and at most the tool diameter " + fmt(tc.tool.diameterMm) +
                                 " mm, got " + fmt(p.stepoverMm) + " mm");
    if (base::Status s = checkRepeats(
            what, "stepover", p.stepoverMm,
            std::hypot(input.stock.max.x - input.stock.min.x, input.stock.max.y - input.stock.min.y), "passes");
        !s)
        return s;
    if (!std::isfinite(p.angleDeg))
        return opError(what, "the raster angle must be a number of degrees");
    if (!(p.maxSlopeDeg > 0 && p.maxSlopeDeg <= 90))
        return opError(what, "the slope limit must be above 0 and at most 90 degrees, got " + fmt(p.maxSlopeDeg) +
                                 " degrees");
    if (!(p.stockMm >= 0) || !std::isfinite(p.stockMm))
        return opError(what, "stock to leave must not be negative, got " + fmt(p.stockMm) + " mm");
    if (!(p.toleranceMm >= 1e-4 && p.toleranceMm <= 1))
        return opError(what, "tolerance must be from 0.0001 to 1 mm, got " + fmt(p.toleranceMm) + " mm");
    if (!input.model || input.model->empty())
        return opError(what, "no model to finish");
    const base::Box3& s = input.stock;
    if (!(s.max.x > s.min.x && s.max.y > s.min.y))
        return opError(what, "the stock box is empty");
    return base::Status::success();
}

// One cut: the points along a line between two steep or outside parts, in cutting order.
using Cut = std::vector<Vec3>;

// The CL points of the straight link from a to b following the surface, if it stays shallow
// enough and inside the area; empty where the link must go over the top instead.
std::vector<Vec3> surfaceLink(const surface::DropCutter& cutter, const ParallelGrid& grid, const Vec3& a, const Vec3& b,
                              double maxSlope, double tolerance)
{
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, int(std::ceil(length / grid.sampleStep())));
    std::vector<Vec3> points{a};
    for (int i = 1; i < n; ++i) {
        const base::Vec2 p{a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n};
        if (!grid.inside(p))
            return {};
        points.push_back({p.x, p.y, cutter.dropZ(p)});
    }
    points.push_back(b);
    for (std::size_t i = 1; i < points.size(); ++i)
        if (!std::isfinite(points[i].z) || std::abs(points[i].z - points[i - 1].z) > maxSlope * length / n + tolerance)
            return {};
    return surface::refineCut(cutter, points, tolerance);
}

// The cuts of one line, from its first sample to its last: each run of cutting samples with the
// points where the line crosses the area's edge, refined and thinned.
std::vector<Cut> lineCuts(const ParallelGrid& grid, const surface::DropCutter& cutter, const ParallelParams& params,
                          int line)
{
    std::vector<Cut> out;
    for (const ParallelGrid::Run& run : grid.cutRuns(line)) {
        Cut dense;
        // Where the model is not under the tool at the edge, the run ends at its last sample.
        auto edgePoint = [&](const std::optional<base::Vec2>& p) {
            if (const double z = p ? cutter.dropZ(*p) : 0; p && std::isfinite(z))
                dense.push_back({p->x, p->y, z});
        };
        edgePoint(run.before);
        for (int m = run.from; m <= run.to; ++m)
            if (const Vec3 q = grid.point(line, m);
                dense.empty() || std::hypot(q.x - dense.back().x, q.y - dense.back().y) > 1e-6)
                dense.push_back(q);
        if (run.after && std::hypot(run.after->x - dense.back().x, run.after->y - dense.back().y) > 1e-6)
            edgePoint(run.after);
        if (dense.size() >= 2)
            out.push_back(surface::thinCut(surface::refineCut(cutter, dense, params.toleranceMm), params.toleranceMm));
    }
    return out;
}

}  // namespace

base::Result<OpResult> computeParallel(const SurfaceInput& input, const ParallelParams& params,
                                       const ToolController& tc, int operationIndex, const Progress& progress)
{
    const std::string what = "parallel \"" + params.name + "\"";
    if (auto status = checkParams(what, input, params, tc); !status)
        return status.error();
    const surface::DropCutter cutter(*input.model, tc.tool, params.stockMm);
    const double radius = tc.tool.diameterMm / 2;
    ParallelGrid grid(input, params, radius);
    if (!grid.drop(cutter, [&](double f) { return progress.step(0.9 * f); }))
        return cancelledError(what);
    if (grid.topZ() > params.heights.safeZ)
        return opError(what, "the safe height " + fmt(params.heights.safeZ) + " is below the top of the model " +
                                 fmt(grid.topZ()) + " (with the stock to leave)");

    // The cuts line by line, every other line reversed when zig-zag.
    std::vector<std::vector<Cut>> byLine(grid.lines());
    const auto lineAt = [&](std::size_t line) { byLine[line] = lineCuts(grid, cutter, params, int(line)); };
    if (!surface::forEachOnAllCores(std::size_t(grid.lines()), lineAt, progress, 0.9, 1.0))
        return cancelledError(what);
    std::vector<Cut> cuts;
    for (int line = 0; line < grid.lines(); ++line) {
        std::vector<Cut>& onLine = byLine[line];
        if (params.zigZag && line % 2 == 1) {
            std::reverse(onLine.begin(), onLine.end());
            for (Cut& cut : onLine)
                std::reverse(cut.begin(), cut.end());
        }
        for (Cut& cut : onLine)
            cuts.push_back(std::move(cut));
    }

    OpResult result;
    pocket::PathWriter out(result.toolpath, operationIndex);
    out.add(sectionBegin(params.name, "parallel", tc));
    const Feed cutting = feedOf(tc, toolpath::FeedKind::Cutting), plunge = feedOf(tc, toolpath::FeedKind::Plunge);
    const double maxSlope = std::tan(std::min(params.maxSlopeDeg, 89.9) * 3.14159265358979323846 / 180);
    const Heights& h = params.heights;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        const Cut& cut = cuts[i];
        std::vector<Vec3> link;
        if (i > 0 && params.zigZag) {
            const Vec3 a = cuts[i - 1].back(), b = cut.front();
            if (std::hypot(b.x - a.x, b.y - a.y) <= 2 * params.stepoverMm + 1e-9)
                link = surfaceLink(cutter, grid, a, b, maxSlope, params.toleranceMm);
        }
        if (!link.empty()) {
            const std::vector<Vec3> thin = surface::thinCut(link, params.toleranceMm);
            for (std::size_t k = 1; k < thin.size(); ++k)  // thin[0] is where the tool is
                out.feed(thin[k], cutting);
        } else {
            if (i == 0)
                out.rapid({cut.front().x, cut.front().y, h.clearanceZ});
            else
                out.rapid({out.position().x, out.position().y, h.safeZ});
            out.rapid({cut.front().x, cut.front().y, h.safeZ});
            out.feed(cut.front(), plunge);
        }
        for (std::size_t k = 1; k < cut.size(); ++k)
            out.feed(cut[k], cutting);
    }
    if (cuts.empty())
        result.warn(what + ": nothing to cut: the model is steeper than " + fmt(params.maxSlopeDeg) +
                    " degrees or absent everywhere in the area");
    else
        out.rapid({out.position().x, out.position().y, h.clearanceZ});
    out.add(toolpath::SectionEnd{});
    result.counts = countMotions(result.toolpath);
    return result;
}

}  // namespace camwb::ops
