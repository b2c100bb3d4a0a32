#include "ops/HoleOrder.h"

#include "base/NumberFormat.h"
#include "ops/DrillOp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace camwb::ops {

namespace {

// A bound on 2-opt sweeps so that a pathological point set cannot keep the operation busy; on
// real hole patterns 2-opt settles in a handful of sweeps.
constexpr int kMaxTwoOptSweeps = 200;

// An exchange must shorten the path by more than this, so rounding cannot make 2-opt cycle.
constexpr double kMinGainMm = 1e-9;

// Distances this close count as equal: grid patterns have many equally near holes.
constexpr double kTieMm = 1e-6;

// Nearest neighbour. Ties (a grid's neighbours) go to the hole that lies most nearly along the
// first step between two holes, in either sense: on a grid that keeps the tool on its row until
// the row ends, so the result is a serpentine (2-opt alone cannot untangle a path that ties
// broke at random). Remaining ties go to the lower index.
std::vector<int> nearestNeighbourOrder(const std::vector<base::Vec2>& points, base::Vec2 start)
{
    const int n = static_cast<int>(points.size());
    std::vector<int> order;
    order.reserve(n);
    std::vector<bool> used(n, false);
    base::Vec2 at = start;
    base::Vec2 rowDirection;  // zero until the first step between two holes
    for (int k = 0; k < n; ++k) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int i = 0; i < n; ++i)
            if (!used[i])
                nearest = std::min(nearest, base::distance(at, points[i]));
        int best = -1;
        double bestAlignment = -1;
        for (int i = 0; i < n; ++i) {
            if (used[i] || base::distance(at, points[i]) > nearest + kTieMm)
                continue;
            const double alignment = std::abs((points[i] - at).normalized().dot(rowDirection));
            if (alignment > bestAlignment + 1e-9) {
                best = i;
                bestAlignment = alignment;
            }
        }
        if (!order.empty() && rowDirection == base::Vec2{})
            rowDirection = (points[best] - at).normalized();
        used[best] = true;
        order.push_back(best);
        at = points[best];
    }
    return order;
}

// 2-opt on the open path start -> order[0] -> ... -> order[n-1]: reverse order[i..j] whenever that
// shortens the path (the path's end is free, so a reversal that reaches the end has one new edge).
void twoOpt(const std::vector<base::Vec2>& points, base::Vec2 start, std::vector<int>& order)
{
    const int n = static_cast<int>(order.size());
    auto at = [&](int k) { return k < 0 ? start : points[order[k]]; };
    for (int sweep = 0; sweep < kMaxTwoOptSweeps; ++sweep) {
        bool improved = false;
        for (int i = 0; i + 1 < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                const bool atEnd = j + 1 == n;
                const double before =
                    base::distance(at(i - 1), at(i)) + (atEnd ? 0.0 : base::distance(at(j), at(j + 1)));
                const double after =
                    base::distance(at(i - 1), at(j)) + (atEnd ? 0.0 : base::distance(at(i), at(j + 1)));
                if (after < before - kMinGainMm) {
                    std::reverse(order.begin() + i, order.begin() + j + 1);
                    improved = true;
                }
            }
        if (!improved)
            return;
    }
}

}  // namespace

std::vector<int> shortRapidOrder(const std::vector<base::Vec2>& points, base::Vec2 start)
{
    std::vector<int> order = nearestNeighbourOrder(points, start);
    twoOpt(points, start, order);
    return order;
}

std::vector<int> holeVisitingOrder(const std::vector<geom::Hole>& holes, bool keepOrder)
{
    std::vector<int> order(holes.size());
    std::iota(order.begin(), order.end(), 0);
    if (keepOrder || holes.size() < 3)
        return order;
    std::vector<base::Vec2> centres;
    for (const geom::Hole& hole : holes)
        centres.push_back(hole.center);
    return shortRapidOrder(centres, holes.front().center);
}

Heights holeHeights(const geom::Hole& hole, const Heights& heights, bool depthsFromHoles, double breakthroughMm)
{
    Heights h = heights;
    if (depthsFromHoles) {
        h.startZ = hole.topZ;
        h.finalZ = hole.through ? hole.bottomZ - breakthroughMm : hole.bottomZ;
    }
    return h;
}

std::string formatMm(double value) { return base::NumberFormat{4, true}.format(value); }

base::Status checkHolesAndTool(const std::string& what, const std::vector<geom::Hole>& holes, const ToolController& tc)
{
    if (holes.empty())
        return opError(what, "no holes selected");
    return checkToolController(what, tc);
}

std::string describeHole(const geom::Hole& hole)
{
    return "hole at (" + formatMm(hole.center.x) + ", " + formatMm(hole.center.y) + ") of " +
           formatMm(hole.diameterMm) + " mm diameter";
}

}  // namespace camwb::ops
