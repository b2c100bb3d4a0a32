#include "PocketTestSupport.h"

#include "../../geom/GeomTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace camwb::ops::pocket::test {

using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

geom::Region withHoles(geom::Profile outer, std::vector<geom::Profile> islands)
{
    geom::Region r{std::move(outer), {}};
    for (geom::Profile& island : islands)
        r.holes.push_back(island.signedArea() > 0 ? island.reversed() : island);
    return r;
}

// A star-shaped polygon round `centre`: n corners at jittered angles, radii in [rMin, rMax].
geom::Profile randomPolygon(unsigned seed, Vec2 centre, int n, double rMin, double rMax)
{
    std::mt19937 gen(seed);
    auto unit = [&] { return static_cast<double>(gen()) / static_cast<double>(std::mt19937::max()); };
    std::vector<Vec2> pts;
    for (int i = 0; i < n; ++i) {
        const double angle = 2 * kPi * (i + 0.8 * (unit() - 0.5)) / n;
        const double r = rMin + (rMax - rMin) * unit();
        pts.push_back(centre + Vec2{std::cos(angle), std::sin(angle)} * r);
    }
    return polygon(pts);
}

}  // namespace

geom::Region rectRegion(double x0, double y0, double w, double h) { return {rectangle(x0, y0, w, h), {}}; }

std::vector<Shape> shapeCorpus()
{
    return {
        {"rectangle", {rectRegion(0, 0, 40, 30)}},
        {"rounded rectangle", {{roundedRectangle(0, 0, 50, 35, 6), {}}}},
        {"L shape", {{polygon({{0, 0}, {40, 0}, {40, 15}, {18, 15}, {18, 35}, {0, 35}}), {}}}},
        {"U shape", {{polygon({{0, 0}, {45, 0}, {45, 35}, {32, 35}, {32, 12}, {13, 12}, {13, 35}, {0, 35}}), {}}}},
        {"rectangle with circular island", {withHoles(rectangle(0, 0, 60, 40), {circle({30, 20}, 7)})}},
        {"rounded rectangle with two islands",
         {withHoles(roundedRectangle(0, 0, 70, 45, 5), {roundedRectangle(10, 10, 16, 12, 3), circle({50, 25}, 6)})}},
        {"random polygon 1", {{randomPolygon(7, {0, 0}, 11, 15, 30), {}}}},
        {"random polygon 2", {{randomPolygon(2024, {5, -3}, 14, 14, 28), {}}}},
        {"random polygon with island", {withHoles(randomPolygon(99, {0, 0}, 9, 18, 30), {circle({0, 0}, 4)})}},
        {"two pockets", {rectRegion(0, 0, 25, 20), {roundedRectangle(35, 0, 30, 22, 4), {}}}},
    };
}

ToolController toolOf(double diameter, bool centreCutting)
{
    ToolController tc;
    tc.tool.number = 4;
    tc.tool.name = "Flat " + std::to_string(diameter);
    tc.tool.diameterMm = diameter;
    tc.tool.centreCutting = centreCutting;
    tc.spindleRpm = 12000;
    tc.cuttingFeedMmPerMin = 1500;
    tc.plungeFeedMmPerMin = 300;
    tc.rampFeedMmPerMin = 700;
    return tc;
}

PocketParams baseParams()
{
    PocketParams p;
    p.name = "Pocket 1";
    p.heights = {20, 3, 0, -4};
    p.stepDownMm = 2;
    return p;
}

namespace {

// Samples of one move from `from`, at most `step` apart, ends included.
void sampleMove(const Vec3& from, const toolpath::Record& r, double step, std::size_t index,
                std::vector<MovePoint>& out)
{
    if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
        const int n = std::max(1, static_cast<int>(std::ceil(distance(from, l->to) / step)));
        for (int i = 0; i <= n; ++i)
            out.push_back({from + (l->to - from) * (static_cast<double>(i) / n), index});
    } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
        const geom::Segment s = geom::Segment::arc(from.xy(), a->to.xy(), a->center.xy(), !a->clockwise);
        const int n = std::max(1, static_cast<int>(std::ceil(s.length() / step)));
        for (int i = 0; i <= n; ++i) {
            const double t = static_cast<double>(i) / n;
            const Vec2 p = s.pointAt(t);
            out.push_back({{p.x, p.y, from.z + (a->to.z - from.z) * t}, index});
        }
    }
}

}  // namespace

std::vector<MovePoint> sampleFeedMoves(const toolpath::Toolpath& tp, double step)
{
    std::vector<MovePoint> out;
    Vec3 pos;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const toolpath::Record& r = tp.record(i);
        sampleMove(pos, r, step, i, out);
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r))
            pos = rapid->to;
        else if (const auto* l = std::get_if<toolpath::Linear>(&r))
            pos = l->to;
        else if (const auto* a = std::get_if<toolpath::Arc>(&r))
            pos = a->to;
    }
    return out;
}

std::vector<Vec2> sampleFlatMovesAt(const toolpath::Toolpath& tp, double z, double step)
{
    std::vector<MovePoint> all;
    Vec3 pos;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const toolpath::Record& r = tp.record(i);
        const Vec3* to = nullptr;
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r))
            to = &rapid->to;
        else if (const auto* l = std::get_if<toolpath::Linear>(&r))
            to = &l->to;
        else if (const auto* a = std::get_if<toolpath::Arc>(&r))
            to = &a->to;
        if (!to)
            continue;
        if (!std::holds_alternative<toolpath::Rapid>(r) && pos.z == z && to->z == z)
            sampleMove(pos, r, step, i, all);
        pos = *to;
    }
    std::vector<Vec2> out;
    out.reserve(all.size());
    for (const MovePoint& m : all)
        out.push_back(m.p.xy());
    return out;
}

double distanceToLoops(const std::vector<geom::Region>& regions, Vec2 p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const geom::Region& r : regions) {
        best = std::min(best, geom::distanceToProfile(p, r.outer));
        for (const geom::Profile& hole : r.holes)
            best = std::min(best, geom::distanceToProfile(p, hole));
    }
    return best;
}

Loops sampledLoops(const std::vector<geom::Region>& regions, double tolerance)
{
    std::vector<std::vector<Vec2>> loops;
    for (const geom::Region& r : regions) {
        loops.push_back(geom::discretize(r.outer, tolerance));
        for (const geom::Profile& hole : r.holes)
            loops.push_back(geom::discretize(hole, tolerance));
    }
    return loops;
}

namespace {

// x where the loops' edges cross the horizontal line at y, sorted (even-odd spans).
std::vector<double> crossings(const std::vector<std::vector<Vec2>>& loops, double y)
{
    std::vector<double> xs;
    for (const std::vector<Vec2>& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
            if ((a.y <= y) != (b.y <= y))
                xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
        }
    std::sort(xs.begin(), xs.end());
    return xs;
}

}  // namespace

bool insideLoops(const Loops& loops, Vec2 p)
{
    const std::vector<double> xs = crossings(loops, p.y);
    return std::count_if(xs.begin(), xs.end(), [&](double x) { return x < p.x; }) % 2 == 1;
}

Coverage rasterCoverage(const std::vector<geom::Region>& area, const std::vector<Vec2>& centres, double radius,
                        double cell)
{
    const std::vector<std::vector<Vec2>> loops = sampledLoops(area, 1e-3);
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const auto& loop : loops)
        for (const Vec2& p : loop) {
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
    const long nx = static_cast<long>(std::ceil((x1 - x0) / cell)) + 1;
    const long ny = static_cast<long>(std::ceil((y1 - y0) / cell)) + 1;
    std::vector<char> covered(static_cast<std::size_t>(nx * ny), 0);
    auto cx = [&](long i) { return x0 + (i + 0.5) * cell; };
    auto cy = [&](long j) { return y0 + (j + 0.5) * cell; };
    for (const Vec2& c : centres) {
        const long j0 = std::max(0L, static_cast<long>(std::floor((c.y - radius - y0) / cell)));
        const long j1 = std::min(ny - 1, static_cast<long>(std::ceil((c.y + radius - y0) / cell)));
        for (long j = j0; j <= j1; ++j) {
            const double dy = cy(j) - c.y;
            if (dy * dy > radius * radius)
                continue;
            const double half = std::sqrt(radius * radius - dy * dy);
            const long i0 = std::max(0L, static_cast<long>(std::ceil((c.x - half - x0) / cell - 0.5)));
            const long i1 = std::min(nx - 1, static_cast<long>(std::floor((c.x + half - x0) / cell - 0.5)));
            for (long i = i0; i <= i1; ++i)
                covered[static_cast<std::size_t>(j * nx + i)] = 1;
        }
    }
    Coverage result;
    for (long j = 0; j < ny; ++j) {
        const std::vector<double> xs = crossings(loops, cy(j));
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
            for (long i = std::max(0L, static_cast<long>(std::ceil((xs[k] - x0) / cell - 0.5)));
                 i < nx && cx(i) < xs[k + 1]; ++i) {
                ++result.machinable;
                if (!covered[static_cast<std::size_t>(j * nx + i)])
                    ++result.uncut;
            }
    }
    return result;
}

}  // namespace camwb::ops::pocket::test
