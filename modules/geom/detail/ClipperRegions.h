// Private bridge between regions and Clipper 6.4 (integer paths, kClipperScale units per mm):
// discretised region loops in, PolyTree nesting back to fitted line/arc regions.
#pragma once

#include "geom/ClipperAdapter.h"
#include "geom/Region.h"

#include <polyclipping/clipper.hpp>

#include <functional>
#include <vector>

namespace camwb::geom::detail {

// Coordinates beyond this (mm) are refused (Clipper throws past its 64-bit range).
inline constexpr double kMaxCoordinate = 1e9;

ClipperLib::IntPoint toClipper(Vec2 p);
Vec2 fromClipper(const ClipperLib::IntPoint& p);
// False when a point is not finite or beyond kMaxCoordinate.
bool inRange(const std::vector<Vec2>& points);

// Every loop of the regions discretised with chord error `chordTolerance`, outer loops
// counter-clockwise and holes clockwise (so non-zero filling gives the regions' union).
// `ok` turns false when a coordinate is out of range.
ClipperLib::Paths regionPaths(const std::vector<Region>& regions, double chordTolerance, bool& ok);

// Regions from the outer/hole nesting of a PolyTree, each loop fitted with `fitTolerance`.
std::vector<Region> regionsFromTree(const ClipperLib::PolyTree& tree, double fitTolerance);
// The same with each contour turned into a loop by `toLoop` (an empty loop is left out).
using ContourToLoop = std::function<Profile(const ClipperLib::Path&)>;
std::vector<Region> regionsFromTree(const ClipperLib::PolyTree& tree, const ContourToLoop& toLoop);
// A contour as lines and arcs fitted within `fitTolerance` (ArcFit.h).
Profile fitContour(const ClipperLib::Path& contour, double fitTolerance);

}  // namespace camwb::geom::detail
