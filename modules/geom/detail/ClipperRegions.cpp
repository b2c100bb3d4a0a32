#include "geom/detail/ClipperRegions.h"

#include "geom/ArcFit.h"

#include <algorithm>
#include <cmath>

namespace camwb::geom::detail {

ClipperLib::IntPoint toClipper(Vec2 p)
{
    return {static_cast<ClipperLib::cInt>(std::llround(p.x * kClipperScale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y * kClipperScale))};
}

Vec2 fromClipper(const ClipperLib::IntPoint& p)
{
    return {static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale};
}

bool inRange(const std::vector<Vec2>& points)
{
    for (const Vec2& p : points)
        if (!(std::abs(p.x) < kMaxCoordinate) || !(std::abs(p.y) < kMaxCoordinate))
            return false;
    return true;
}

namespace {

void addLoop(const Profile& loop, bool counterClockwise, double chordTolerance, ClipperLib::Paths& paths, bool& ok)
{
    if (loop.segments.empty())
        return;
    std::vector<Vec2> points = discretize(loop, chordTolerance);
    if (!inRange(points)) {
        ok = false;
        return;
    }
    if ((polygonArea(points) > 0) != counterClockwise)
        std::reverse(points.begin(), points.end());
    ClipperLib::Path& path = paths.emplace_back();
    path.reserve(points.size());
    for (const Vec2& p : points)
        path.push_back(toClipper(p));
}

void collectOuter(const ClipperLib::PolyNode& node, const ContourToLoop& toLoop, std::vector<Region>& out)
{
    Region region;
    region.outer = toLoop(node.Contour);
    for (const ClipperLib::PolyNode* hole : node.Childs) {
        Profile loop = toLoop(hole->Contour);
        if (!loop.empty())
            region.holes.push_back(std::move(loop));
        for (const ClipperLib::PolyNode* island : hole->Childs)
            collectOuter(*island, toLoop, out);
    }
    if (!region.outer.empty())
        out.push_back(region.normalized());
}

}  // namespace

ClipperLib::Paths regionPaths(const std::vector<Region>& regions, double chordTolerance, bool& ok)
{
    ClipperLib::Paths paths;
    for (const Region& region : regions) {
        addLoop(region.outer, true, chordTolerance, paths, ok);
        for (const Profile& hole : region.holes)
            addLoop(hole, false, chordTolerance, paths, ok);
    }
    return paths;
}

std::vector<Region> regionsFromTree(const ClipperLib::PolyTree& tree, double fitTolerance)
{
    return regionsFromTree(
        tree, [fitTolerance](const ClipperLib::Path& contour) { return fitContour(contour, fitTolerance); });
}

std::vector<Region> regionsFromTree(const ClipperLib::PolyTree& tree, const ContourToLoop& toLoop)
{
    std::vector<Region> out;
    for (const ClipperLib::PolyNode* outer : tree.Childs)
        collectOuter(*outer, toLoop, out);
    return out;
}

Profile fitContour(const ClipperLib::Path& contour, double fitTolerance)
{
    std::vector<Vec2> points;
    points.reserve(contour.size());
    for (const ClipperLib::IntPoint& p : contour)
        points.push_back(fromClipper(p));
    return fitLinesAndArcs(points, true, fitTolerance);
}

}  // namespace camwb::geom::detail
