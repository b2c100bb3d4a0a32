#include "ops/surface/RestMaterial.h"

#include "ops/surface/MeshShadow.h"
#include "sim/StockRun.h"
#include "sim/ToolShape.h"

#include "geom/ClipperAdapter.h"

#include <algorithm>
#include <cmath>

namespace camwb::ops::surface {

std::vector<geom::Region> restRegion(const sim::HeightField& rest, double level, double reach,
                                     const std::vector<geom::Region>& toolCentre, double tolerance)
{
    // Each row's runs of columns still above the level, as rectangles of their cells.
    const base::Box3 box = rest.bounds();
    const double dx = (box.max.x - box.min.x) / rest.columnsX(), dy = (box.max.y - box.min.y) / rest.columnsY();
    const auto at = [](double x, double y) {
        return ClipperLib::IntPoint{ClipperLib::cInt(std::llround(x * geom::kClipperScale)),
                                    ClipperLib::cInt(std::llround(y * geom::kClipperScale))};
    };
    ClipperLib::Paths cells;
    for (int j = 0; j < rest.columnsY(); ++j) {
        for (int i = 0; i < rest.columnsX();) {
            if (!(rest.top(i, j) > level + tolerance)) {
                ++i;
                continue;
            }
            const int first = i;
            while (i < rest.columnsX() && rest.top(i, j) > level + tolerance)
                ++i;
            const double x0 = rest.columnX(first) - dx / 2, x1 = rest.columnX(i - 1) + dx / 2;
            const double y0 = rest.columnY(j) - dy / 2, y1 = rest.columnY(j) + dy / 2;
            cells.push_back({at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)});
        }
    }
    if (cells.empty())
        return {};
    // Only material the tool can reach at this level counts: columns over the part (its walls,
    // with the stock left on them) stand above the level too, but lie outside the footprint of
    // the tool-centre region (less a column's half diagonal, so that a cell the footprint only
    // grazes at the wall's stock does not count).
    const ClipperLib::Paths centre = toPaths(toolCentre, tolerance / 4);
    const double margin = 0.75 * std::max(dx, dy) + tolerance;
    const ClipperLib::Paths reachable = growPaths(centre, std::max(reach - margin, tolerance), tolerance / 4);
    const ClipperLib::Paths material = clipPaths(unitePaths(cells), reachable, ClipperLib::ctIntersection);
    if (material.empty())
        return {};
    const ClipperLib::Paths near = growPaths(material, reach + tolerance, tolerance / 4);
    return toRegions(clipPaths(centre, near, ClipperLib::ctIntersection), tolerance / 2);
}

std::vector<pocket::Cut> cutsThatCut(std::vector<pocket::Cut> cuts, sim::HeightField& stock, double level,
                                     const toolpath::Tool& tool, double tolerance)
{
    const sim::ToolShape shape(tool);
    const double r = stock.resolutionMm();
    const double worth = r * r * tolerance;
    std::vector<pocket::Cut> kept;
    std::size_t index = 0;
    for (pocket::Cut& cut : cuts) {
        const std::vector<base::Vec2> points = pocket::samplePath(cut.path, tolerance);
        double removed = 0;
        for (std::size_t i = 1; i < points.size(); ++i) {
            sim::Move move;
            move.from = {points[i - 1].x, points[i - 1].y, level};
            move.to = {points[i].x, points[i].y, level};
            move.tool = tool.number;
            removed += stock.cut(move, index++, shape).removedMm3;
        }
        if (removed > worth)
            kept.push_back(std::move(cut));
    }
    return kept;
}

StockFigures simulateOn(const sim::HeightField& rest, const toolpath::Toolpath& section, const toolpath::Tool& tool)
{
    toolpath::Toolpath program;
    program.add(toolpath::ToolChange{tool});
    program.add(toolpath::Spindle{1000, true});
    program.append(section);
    const sim::MoveList moves = sim::buildMoves(program);
    sim::HeightField stock(rest);
    sim::StockRun run(moves, stock);
    run.cutTo(moves.moves.size());
    return {run.cuttingMm(), run.airCuttingMm(), run.removedMm3()};
}

}  // namespace camwb::ops::surface
