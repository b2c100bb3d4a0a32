#include "RoughingTestUtil.h"

#include "../finishing/GrownProfile.h"

#include "sim/Moves.h"
#include "sim/StockRun.h"
#include "sim/ToolShape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace camwb::ops::test {

namespace {

constexpr double kPi = std::numbers::pi;

// min(a, b) with the corner rounded over a width k (a polynomial smooth minimum).
double smoothMin(double a, double b, double k)
{
    if (k <= 0)
        return std::min(a, b);
    const double h = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k / 4;
}

}  // namespace

base::Box3 box3(base::Vec3 lo, base::Vec3 hi)
{
    base::Box3 b;
    b.add(lo);
    b.add(hi);
    return b;
}

sim::TriangleMesh heightMesh(const HeightFn& f, double x0, double y0, double x1, double y1, int n, double bottom)
{
    sim::TriangleMesh m;
    const auto vertex = [&](double x, double y, double z) {
        m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
    };
    const auto id = [n](int i, int j, bool top) {
        return std::uint32_t((top ? 0 : (n + 1) * (n + 1)) + j * (n + 1) + i);
    };
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = x0 + (x1 - x0) * i / n, y = y0 + (y1 - y0) * j / n;
                vertex(x, y, layer == 0 ? f(x, y) : bottom);
            }
    const auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.triangles.insert(m.triangles.end(), {a, b, c});
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            tri(id(i, j, true), id(i + 1, j, true), id(i + 1, j + 1, true));
            tri(id(i, j, true), id(i + 1, j + 1, true), id(i, j + 1, true));
            tri(id(i, j, false), id(i + 1, j + 1, false), id(i + 1, j, false));
            tri(id(i, j, false), id(i, j + 1, false), id(i + 1, j + 1, false));
        }
    // The border counter-clockwise seen from above, each edge walled down to the bottom.
    std::vector<std::pair<int, int>> border;
    for (int i = 0; i < n; ++i)
        border.push_back({i, 0});
    for (int j = 0; j < n; ++j)
        border.push_back({n, j});
    for (int i = n; i > 0; --i)
        border.push_back({i, n});
    for (int j = n; j > 0; --j)
        border.push_back({0, j});
    for (std::size_t k = 0; k < border.size(); ++k) {
        const auto [ui, uj] = border[k];
        const auto [vi, vj] = border[(k + 1) % border.size()];
        tri(id(ui, uj, false), id(vi, vj, false), id(vi, vj, true));
        tri(id(ui, uj, false), id(vi, vj, true), id(ui, uj, true));
    }
    return m;
}

double roundedRectDistance(double x, double y, double cx, double cy, double halfW, double halfH, double corner)
{
    const double qx = std::abs(x - cx) - (halfW - corner), qy = std::abs(y - cy) - (halfH - corner);
    const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
    return outside + std::min(std::max(qx, qy), 0.0) - corner;
}

HeightFn draftedCavity(double depth, double draftDeg, double corner, double fillet)
{
    const double cot = 1 / std::tan(std::max(draftDeg, 0.5) * kPi / 180);
    return [=](double x, double y) {
        const double d = roundedRectDistance(x, y, 30, 25, 20, 16, corner);
        return d >= 0 ? 20.0 : 20.0 - smoothMin(depth, -d * cot, fillet);
    };
}

HeightFn draftedBoss(double base, double height, double draftDeg, double corner)
{
    const double cot = 1 / std::tan(std::max(draftDeg, 0.5) * kPi / 180);
    return [=](double x, double y) {
        const double d = roundedRectDistance(x, y, 30, 25, 8, 6, corner);
        return base + std::min(height, std::max(0.0, -d) * cot);
    };
}

HeightFn sphereOnPlate(double base, double r, double centreZ)
{
    return [=](double x, double y) {
        const double rho2 = (x - 30) * (x - 30) + (y - 25) * (y - 25);
        return rho2 < r * r ? std::max(base, centreZ + std::sqrt(r * r - rho2)) : base;
    };
}

HeightFn randomPart(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    const double depth = 6 + 6 * u(rng), draft = 3 + 17 * u(rng), corner = 2 + 6 * u(rng), fillet = 3 * u(rng);
    const HeightFn cavity = draftedCavity(depth, draft, corner, fillet);
    const int inner = int(u(rng) * 3);
    if (inner == 0)
        return cavity;
    const double floor = 20 - depth;
    const HeightFn island = inner == 1
                                ? draftedBoss(floor, depth * (0.3 + 0.6 * u(rng)), 5 + 20 * u(rng), 1 + 3 * u(rng))
                                : sphereOnPlate(floor, 4 + 3 * u(rng), floor - 2 * u(rng));
    return [=](double x, double y) { return std::max(cavity(x, y), island(x, y)); };
}

ToolController toolController(const std::string& kind, double diameter, double corner)
{
    ToolController tc;
    tc.tool.number = 3;
    tc.tool.kind = kind;
    tc.tool.diameterMm = diameter;
    tc.tool.cornerRadiusMm = kind == "ball" ? diameter / 2 : corner;
    tc.tool.fluteLengthMm = 30;
    tc.tool.lengthMm = 50;
    tc.spindleRpm = 8000;
    tc.cuttingFeedMmPerMin = 1200;
    tc.plungeFeedMmPerMin = 300;
    return tc;
}

namespace {

sim::MoveList movesOf(const toolpath::Toolpath& section, const toolpath::Tool& tool)
{
    toolpath::Toolpath program;
    program.add(toolpath::ToolChange{tool});
    program.add(toolpath::Spindle{8000, true});
    program.append(section);
    return sim::buildMoves(program);
}

}  // namespace

StockCheck cutThrough(const toolpath::Toolpath& section, const toolpath::Tool& tool, const sim::TriangleMesh& model,
                      const base::Box3& box, double resolution, const sim::HeightField* start)
{
    StockCheck out;
    out.stock =
        start ? std::make_unique<sim::HeightField>(*start) : std::make_unique<sim::HeightField>(box, resolution);
    out.stock->setDesign(model, 0.01);
    const sim::MoveList moves = movesOf(section, tool);
    sim::StockRun run(moves, *out.stock);
    run.cutTo(moves.moves.size());
    out.maxGougeMm = out.stock->compare().maxGougeMm;
    out.airMm = run.airCuttingMm();
    out.cuttingMm = run.cuttingMm();
    for (const sim::Check& check : run.checks())
        out.rapidsInStock += check.kind == sim::CheckKind::RapidInStock;
    return out;
}

namespace {

// `surface(d)`: the grown tool's lower surface above its tip at radial distance d <= reach.
double deepestPenetrationOf(const toolpath::Toolpath& section, const toolpath::Tool& tool,
                            const sim::TriangleMesh& model, double reach, const std::function<double(double)>& surface,
                            double step)
{
    // The mesh's vertices and triangle centres, bucketed by millimetre cells.
    std::unordered_map<long long, std::vector<base::Vec3>> cells;
    const auto key = [](long long i, long long j) { return i * 1000003LL + j; };
    const auto add = [&](const base::Vec3& p) {
        cells[key(std::llround(std::floor(p.x)), std::llround(std::floor(p.y)))].push_back(p);
    };
    for (std::size_t v = 0; v < model.vertexCount(); ++v)
        add(model.vertex(v));
    for (std::size_t t = 0; t < model.triangleCount(); ++t) {
        const base::Vec3 a = model.vertex(model.triangles[3 * t]), b = model.vertex(model.triangles[3 * t + 1]),
                         c = model.vertex(model.triangles[3 * t + 2]);
        add({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3});
    }
    double deepest = -1e9;
    const auto probe = [&](const base::Vec3& tip) {
        for (long long i = std::llround(std::floor(tip.x - reach)); i <= std::llround(std::floor(tip.x + reach)); ++i)
            for (long long j = std::llround(std::floor(tip.y - reach)); j <= std::llround(std::floor(tip.y + reach));
                 ++j) {
                const auto it = cells.find(key(i, j));
                if (it == cells.end())
                    continue;
                for (const base::Vec3& p : it->second) {
                    const double d = std::hypot(p.x - tip.x, p.y - tip.y);
                    if (d > reach)
                        continue;
                    deepest = std::max(deepest, p.z - (tip.z + surface(d)));
                }
            }
    };
    const sim::MoveList moves = movesOf(section, tool);
    for (const sim::Move& m : moves.moves) {
        if (!m.moves())
            continue;
        const double len = std::sqrt((m.to - m.from).dot(m.to - m.from));
        const int n = std::max(1, int(std::ceil(len / step)));
        for (int k = 0; k <= n; ++k)
            probe(m.from + (m.to - m.from) * (double(k) / n));
    }
    return deepest;
}

}  // namespace

double deepestPenetration(const toolpath::Toolpath& section, const toolpath::Tool& tool, const sim::TriangleMesh& model,
                          double sideStock, double bottomStock, double step)
{
    const sim::ToolShape shape(tool);
    return deepestPenetrationOf(
        section, tool, model, shape.radiusMm() + sideStock,
        [&](double d) { return shape.lowerSurface(std::max(0.0, d - sideStock)) - bottomStock; }, step);
}

double deepestPenetrationGrown(const toolpath::Toolpath& section, const toolpath::Tool& tool,
                               const sim::TriangleMesh& model, double stock, double step)
{
    const sim::ToolShape shape(tool);
    const ProfileTable grown(GrownProfile{shape, stock});
    return deepestPenetrationOf(section, tool, model, grown.radius, grown, step);
}

}  // namespace camwb::ops::test
