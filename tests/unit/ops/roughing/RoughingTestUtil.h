// What the 3D pocket and waterline tests share: closed meshes of height-function parts (a block
// with a drafted, filleted cavity, a drafted boss, a sphere on a plate, random mixes), tools, and
// the oracles: the toolpath cut through the simulator's z-map (gouge, material left per column)
// and a direct check of the tool's shape against the mesh at CL points along every feed move.
#pragma once

#include "ops/OpCommon.h"
#include "sim/HeightField.h"
#include "sim/TriangleMesh.h"

#include <functional>
#include <memory>
#include <random>

namespace camwb::ops::test {

using HeightFn = std::function<double(double x, double y)>;

// A closed mesh: the surface z = f(x, y) over [x0, x1] x [y0, y1] on an n x n grid, vertical
// sides down to z = bottom and a flat bottom.
sim::TriangleMesh heightMesh(const HeightFn& f, double x0, double y0, double x1, double y1, int n, double bottom);

// Signed distance to a rounded rectangle centred at (cx, cy) (negative inside).
double roundedRectDistance(double x, double y, double cx, double cy, double halfW, double halfH, double corner);

// A 60 x 50 block, top at 20, with a cavity `depth` deep, walls drafted by `draftDeg`, corners of
// radius `corner` and a floor fillet of radius `fillet`; the floor is flat at 20 - depth.
HeightFn draftedCavity(double depth, double draftDeg, double corner, double fillet);
// A boss `height` high with drafted walls on a plate at `base`.
HeightFn draftedBoss(double base, double height, double draftDeg, double corner);
// A sphere of radius r centred at (30, 25, centreZ) sticking out of a plate at `base`.
HeightFn sphereOnPlate(double base, double r, double centreZ);
// A random mix of the above (cavity + boss inside it, or sphere) from a seed.
HeightFn randomPart(std::mt19937& rng);

ToolController toolController(const std::string& kind, double diameter, double corner = 0);

struct StockCheck {
    double maxGougeMm = 0;
    std::unique_ptr<sim::HeightField> stock;  // as the toolpath left it, with the design set
    double airMm = 0, cuttingMm = 0;
    int rapidsInStock = 0;  // rapids that removed material (an error in the simulator)
};
// Cuts the section (with its tool) through a z-map of `box` (from `start` when given).
StockCheck cutThrough(const toolpath::Toolpath& section, const toolpath::Tool& tool, const sim::TriangleMesh& model,
                      const base::Box3& box, double resolution, const sim::HeightField* start = nullptr);

// The deepest the tool (its true shape, grown by the stocks) reaches into the mesh at points every
// `step` mm along the feed moves (vertices and triangle centres of the mesh are tested).
double deepestPenetration(const toolpath::Toolpath& section, const toolpath::Tool& tool, const sim::TriangleMesh& model,
                          double sideStock, double bottomStock, double step = 0.25);
// The same with the tool grown by `stock` all round (the Minkowski sum with a ball: the finishing
// operations' stock, measured along the model's normal), by the finishing tests' own reference.
double deepestPenetrationGrown(const toolpath::Toolpath& section, const toolpath::Tool& tool,
                               const sim::TriangleMesh& model, double stock, double step = 0.25);

base::Box3 box3(base::Vec3 lo, base::Vec3 hi);

}  // namespace camwb::ops::test
