// Shared by the pocket tests: a corpus of generated pocket shapes (rectangles, rounded
// rectangles, L and U shapes, circular and rounded-rectangle islands, random polygons), a walk
// over a toolpath that samples every cutting move exactly (arcs and helices on their circles) and
// a raster of the tool footprint to measure what is left uncut.
#pragma once

#include "geom/Region.h"
#include "ops/PocketOp.h"

#include <string>
#include <vector>

namespace camwb::ops::pocket::test {

using base::Vec2;
using toolpath::Vec3;

struct Shape {
    std::string name;
    std::vector<geom::Region> regions;
};
std::vector<Shape> shapeCorpus();

geom::Region rectRegion(double x0, double y0, double w, double h);
ToolController toolOf(double diameter, bool centreCutting = true);
PocketParams baseParams();

// One sampled point of a feed move (Linear or Arc) with the index of its record.
struct MovePoint {
    Vec3 p;
    std::size_t record = 0;
};
// Every feed move sampled at most `step` mm apart (ends included); arcs on their exact circle.
std::vector<MovePoint> sampleFeedMoves(const toolpath::Toolpath& tp, double step);
// Points of the flat feed moves at exactly z (for the cleared-area raster).
std::vector<Vec2> sampleFlatMovesAt(const toolpath::Toolpath& tp, double z, double step);

// Distance from p to the nearest loop of the regions, exact for lines and arcs.
double distanceToLoops(const std::vector<geom::Region>& regions, Vec2 p);
// Every loop of the regions sampled within the tolerance, and the even-odd inside test on them.
using Loops = std::vector<std::vector<Vec2>>;
Loops sampledLoops(const std::vector<geom::Region>& regions, double tolerance);
bool insideLoops(const Loops& loops, Vec2 p);

struct Coverage {
    long machinable = 0, uncut = 0;
};
// Cells of `cell` mm whose centre lies in `area` and outside every disc of `radius` round the points.
Coverage rasterCoverage(const std::vector<geom::Region>& area, const std::vector<Vec2>& centres, double radius,
                        double cell);

}  // namespace camwb::ops::pocket::test
