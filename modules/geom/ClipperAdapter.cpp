#include "geom/ClipperAdapter.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>

namespace camwb::geom {

namespace {

ClipperLib::IntPoint toClipper(base::Vec2 p)
{
    return {static_cast<ClipperLib::cInt>(std::llround(p.x * kClipperScale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y * kClipperScale))};
}

base::Vec2 fromClipper(const ClipperLib::IntPoint& p)
{
    return {static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale};
}

std::vector<std::vector<base::Vec2>> fromClipper(const ClipperLib::Paths& paths)
{
    std::vector<std::vector<base::Vec2>> result;
    for (const ClipperLib::Path& path : paths) {
        std::vector<base::Vec2>& poly = result.emplace_back();
        poly.reserve(path.size());
        for (const ClipperLib::IntPoint& p : path)
            poly.push_back(fromClipper(p));
    }
    return result;
}

}  // namespace

std::vector<std::vector<base::Vec2>> clipperOffset(const std::vector<base::Vec2>& polygon, double delta,
                                                   double arcTolerance)
{
    ClipperLib::Path path;
    path.reserve(polygon.size());
    for (const base::Vec2& p : polygon)
        path.push_back(toClipper(p));

    ClipperLib::ClipperOffset offsetter;
    // Clipper clamps the tolerance to >= 0.25 units; keep it meaningful for tiny requests.
    offsetter.ArcTolerance = std::max(arcTolerance * kClipperScale, 0.25);
    offsetter.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    ClipperLib::Paths solution;
    offsetter.Execute(solution, delta * kClipperScale);

    return fromClipper(solution);
}

std::vector<std::vector<base::Vec2>> clipperUnion(const std::vector<std::vector<base::Vec2>>& polygons)
{
    ClipperLib::Paths paths;
    paths.reserve(polygons.size());
    for (const std::vector<base::Vec2>& polygon : polygons) {
        ClipperLib::Path& path = paths.emplace_back();
        path.reserve(polygon.size());
        for (const base::Vec2& p : polygon)
            path.push_back(toClipper(p));
        // Nonzero fill counts orientation: every piece counter-clockwise so that none cancels another.
        if (!ClipperLib::Orientation(path))
            ClipperLib::ReversePath(path);
    }
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    ClipperLib::Paths solution;
    clipper.Execute(ClipperLib::ctUnion, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return fromClipper(solution);
}

double polygonArea(const std::vector<base::Vec2>& polygon)
{
    double twice = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        twice += polygon[i].cross(polygon[(i + 1) % polygon.size()]);
    return 0.5 * twice;
}

}  // namespace camwb::geom
