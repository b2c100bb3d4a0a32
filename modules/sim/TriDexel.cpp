#include "sim/TriDexel.h"

#include "sim/Capsule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::sim {

struct TriDexel::PoseCut {
    double removed = 0;  // length along the grid's rays
    double gouge = 0;
    Vec3 gougeAt;
    bool onAxis = false;
};

namespace {

double comp(const Vec3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
void setComp(Vec3& p, int a, double value) { (a == 0 ? p.x : a == 1 ? p.y : p.z) = value; }

// The spans inside a mesh along each ray: crossings sorted and walked with a winding count, so
// overlapping shells (a union given as separate bodies) still fill once.
std::vector<std::vector<TriDexel::Span>> insideSpans(const TriangleMesh& mesh, const RayGrid& grid)
{
    std::vector<std::vector<std::pair<float, int>>> hits(std::size_t(grid.nu) * grid.nv);
    forEachCrossing(mesh, grid, [&](int i, int j, double t, bool entering) {
        hits[std::size_t(j) * grid.nu + i].push_back({float(t), entering ? 1 : -1});
    });
    std::vector<std::vector<TriDexel::Span>> spans(hits.size());
    for (std::size_t k = 0; k < hits.size(); ++k) {
        std::sort(hits[k].begin(), hits[k].end());
        int winding = 0;
        float start = 0;
        for (const auto& [t, step] : hits[k]) {
            if (winding <= 0 && winding + step > 0)
                start = t;
            else if (winding > 0 && winding + step <= 0 && t > start)
                spans[k].push_back({start, t});
            winding += step;
        }
    }
    return spans;
}

}  // namespace

TriDexel::TriDexel(const base::Box3& box, double resolutionMm) : m_box(box)
{
    for (int k = 0; k < 3; ++k) {
        const double w = comp(box.max, k) - comp(box.min, k);
        m_cells[k] = int(cellsAcross(w, resolutionMm));
        m_cell[k] = w / m_cells[k];
    }
    // Spans end on floats: cutting again along a surface already cut finds its end a rounding
    // (half a float's step at the stock's largest coordinate, 1.5e-6 mm at 25 mm) inside, which
    // summed over the rays of a tool's wall read as a rapid "removing" 0.0005 mm³ when it retracts
    // along the path it just cut. Less than a few such steps is no material.
    const double largest = std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z), std::abs(box.max.x),
                                     std::abs(box.max.y), std::abs(box.max.z), 1.0});
    m_spanSlack = 4 * largest * std::numeric_limits<float>::epsilon();
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        Grid& g = m_grids[a];
        g.rays = {a, comp(box.min, u), comp(box.min, v), m_cell[u], m_cell[v], m_cells[u], m_cells[v]};
        const Span whole{float(comp(box.min, a)), float(comp(box.max, a))};
        g.spans.assign(std::size_t(g.rays.nu) * g.rays.nv, std::vector<Span>{whole});
        g.lastCut.assign(g.spans.size(), -1);
    }
}

std::size_t TriDexel::memoryBytes() const
{
    // A ray's spans are a heap block each: glibc gives at least 32 bytes, in steps of 16 with its
    // 8-byte header.
    auto block = [](std::size_t spans) {
        return spans == 0 ? 0 : std::max<std::size_t>(32, (spans * sizeof(Span) + 8 + 15) / 16 * 16);
    };
    std::size_t bytes = sizeof(*this);
    for (const Grid& g : m_grids) {
        bytes +=
            sizeof(std::vector<Span>) * (g.spans.size() + g.design.size()) + sizeof(std::int32_t) * g.lastCut.size();
        for (const auto* rays : {&g.spans, &g.design})
            for (const std::vector<Span>& ray : *rays)
                bytes += block(ray.size());
    }
    return bytes;
}

std::unique_ptr<TriDexel> TriDexel::fromMesh(const TriangleMesh& blank, double resolutionMm)
{
    auto stock = std::make_unique<TriDexel>(blank.bounds(), resolutionMm);
    for (Grid& g : stock->m_grids)
        g.spans = insideSpans(blank, g.rays);
    return stock;
}

void TriDexel::setDesign(const TriangleMesh& model, double toleranceMm)
{
    m_tolerance = toleranceMm;
    m_hasDesign = !model.empty();
    for (Grid& g : m_grids)
        g.design = m_hasDesign ? insideSpans(model, g.rays) : std::vector<std::vector<Span>>{};
    m_designDistance = m_hasDesign ? std::make_shared<MeshDistance>(model) : nullptr;
}

double TriDexel::trueDepth(const Vec3& p, double alongRays) const
{
    return m_designDistance ? m_designDistance->distance(p, alongRays) : alongRays;
}

double TriDexel::gridVolumeMm3(int axis) const
{
    const Grid& g = m_grids[axis];
    double length = 0;
    for (const auto& ray : g.spans)
        for (const Span& s : ray)
            length += double(s.hi) - s.lo;
    return length * g.rays.du * g.rays.dv;
}

double TriDexel::volumeMm3() const { return (gridVolumeMm3(0) + gridVolumeMm3(1) + gridVolumeMm3(2)) / 3; }

CutResult TriDexel::cut(const Move& move, std::size_t moveIndex, const ToolShape& tool)
{
    CutResult result;
    if (!move.moves() || !move.positionKnown || tool.radiusMm() <= 0)
        return result;
    const int poses = posesAlong(move, tool);
    const double r = tool.radiusMm();
    PoseCut seen[3];
    double nextHolderCheck = 0;
    // The move before ended where this one starts, with the same cutter: that pose is cut (the
    // pieces of an arc each start where the last ended).
    const LastPose start{move.from,        move.axisAt(0),      tool.radiusMm(), tool.cornerRadiusMm(),
                         tool.coneSlope(), tool.fluteLengthMm()};
    const bool startCut = m_lastPose == start;
    m_lastPose = {move.to, move.axisAt(1), start.radius, start.corner, start.coneSlope, start.flute};
    for (int p = 0; p <= poses; ++p) {
        const double t = double(p) / poses;
        const Vec3 tip = move.from + (move.to - move.from) * t;
        const Vec3 axis = move.axisAt(t);
        base::Box3 reach;  // the cutter's box: its axis segment grown by the radius
        reach.add(tip);
        reach.add(tip + axis * tool.fluteLengthMm());
        reach.min = reach.min - Vec3{r, r, r};
        reach.max = reach.max + Vec3{r, r, r};
        for (int a = 0; a < 3 && !(p == 0 && startCut); ++a)
            cutPose(a, tip, axis, reach, tool, moveIndex, seen[a]);
        // The shank and holder are wide and rarely touch: checked every millimetre of travel
        // and at the ends, not at every pose.
        if (p == 0 || p == poses || t * move.lengthMm() >= nextHolderCheck) {
            checkHolder(tip, axis, tool, result);
            nextHolderCheck = t * move.lengthMm() + 1;
        }
    }
    double removed = 0;
    result.gougeMm = 0;
    for (int a = 0; a < 3; ++a) {
        removed += seen[a].removed * m_grids[a].rays.du * m_grids[a].rays.dv;
        // Each grid measures a gouge along its own rays; the depth into the model is the
        // shortest of them (a wall's depth is across it, not along it).
        if (seen[a].gouge > 0 && (result.gougeMm == 0 || seen[a].gouge < result.gougeMm))
            result.gougeMm = seen[a].gouge, result.gougeAt = seen[a].gougeAt;
    }
    result.removedMm3 = removed / 3;
    const Vec3 d = move.to - move.from;
    const Vec3 a0 = move.fromAxis();
    const int aligned = std::abs(a0.x) >= std::max(std::abs(a0.y), std::abs(a0.z)) ? 0
                        : std::abs(a0.y) >= std::abs(a0.z)                         ? 1
                                                                                   : 2;
    result.removedOnAxis = seen[aligned].onAxis && -d.dot(a0) > d.length() * std::sqrt(0.5);
    return result;
}

int TriDexel::posesAlong(const Move& move, const ToolShape& tool) const
{
    const double halfCell = 0.5 * std::min({m_cell[0], m_cell[1], m_cell[2]});
    const double shortfall = halfCell / 10;
    // A turn moves the cutter's top (the point farthest from the tip) by this much.
    const double turn = move.fromAxis().angleTo(move.toAxis()) * tool.fluteLengthMm();
    // Along its own axis (a drill's plunge, a retract) a cutter whose radius never shrinks upwards
    // covers at each height what its lowest pose covers: poses half the flute apart overlap and
    // give the whole sweep, for every kind. A side step within the shortfall changes nothing.
    const Vec3 d = move.to - move.from;
    if (turn == 0 && (d - move.fromAxis() * d.dot(move.fromAxis())).length() <= shortfall)
        return std::max(1, int(std::ceil(move.lengthMm() / (0.5 * tool.fluteLengthMm()))));
    // A point's curvature has no bound (it grows without end towards the tip): half a cell.
    if (tool.coneSlope() > 0)
        return std::max(1, int(std::ceil(std::max(move.lengthMm(), turn) / halfCell)));
    // The largest curvature of the cutter's surface is 1/rho: a flat end mill's side (rho: its
    // radius), a ball's or bull-nose's corner (rho: the corner radius).
    const double rho = tool.cornerRadiusMm() > 0 ? tool.cornerRadiusMm() : tool.radiusMm();
    const double step = std::max(halfCell, std::sqrt(8 * shortfall * rho));
    // The rims, a flat end's bottom edge and the cutter's top edge where it can reach the stock:
    // copies leave notches step * sin(a) * cos(a) deep where the move rises at a to the tool's
    // radial plane. A turn about the tip moves the top rim across the axis and tilts the bottom
    // about its centre, where the extremes are the poses themselves: no notch.
    double moveStep = step;
    if (const double len = move.lengthMm(); len > 0 && (tool.flatBottomed() || topRimMayCut(move, tool))) {
        double sinCos = 0;
        for (const Vec3& axis : {move.fromAxis(), move.axisAt(0.5), move.toAxis()}) {
            const double sinA = std::min(1.0, std::abs(d.dot(axis)) / len);
            sinCos = std::max(sinCos, sinA * std::sqrt(1 - sinA * sinA));
        }
        if (sinCos > 0)
            moveStep = std::max(halfCell, std::min(step, shortfall / sinCos));
    }
    // A point of the cutter moves by at most the sum of the two per pose.
    return std::max(1, int(std::ceil(move.lengthMm() / moveStep + turn / step)));
}

bool TriDexel::topRimMayCut(const Move& move, const ToolShape& tool) const
{
    // The rim stays within its centre's path grown by the radius; the path within the box of its
    // ends grown by how far the turn moves the top.
    const double flute = tool.fluteLengthMm();
    const double grow = tool.radiusMm() + move.fromAxis().angleTo(move.toAxis()) * flute;
    base::Box3 rim;
    rim.add(move.from + move.fromAxis() * flute);
    rim.add(move.to + move.toAxis() * flute);
    rim.min = rim.min - Vec3{grow, grow, grow};
    rim.max = rim.max + Vec3{grow, grow, grow};
    return rim.min.x < m_box.max.x && rim.max.x > m_box.min.x && rim.min.y < m_box.max.y && rim.max.y > m_box.min.y &&
           rim.min.z < m_box.max.z && rim.max.z > m_box.min.z;
}

void TriDexel::cutPose(int a, const Vec3& tip, const Vec3& toolAxis, const base::Box3& reach, const ToolShape& tool,
                       std::size_t moveIndex, PoseCut& seen)
{
    Grid& g = m_grids[a];
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const RayGrid& rg = g.rays;
    const int i0 = std::max(0, int(std::ceil((comp(reach.min, u) - rg.u0) / rg.du - 0.5)));
    const int i1 = std::min(rg.nu - 1, int(std::floor((comp(reach.max, u) - rg.u0) / rg.du - 0.5)));
    const int j0 = std::max(0, int(std::ceil((comp(reach.min, v) - rg.v0) / rg.dv - 0.5)));
    const int j1 = std::min(rg.nv - 1, int(std::floor((comp(reach.max, v) - rg.v0) / rg.dv - 0.5)));
    const double lo = comp(reach.min, a), hi = comp(reach.max, a);
    const double axisBand = 0.75 * std::max(rg.du, rg.dv);
    Vec3 dir;
    setComp(dir, a, 1);
    // Only the rays within the cutter's radius of its axis segment can meet it.
    const Vec3 top = tip + toolAxis * tool.fluteLengthMm();
    const Capsule capsule({comp(tip, u), comp(tip, v)}, {comp(top, u), comp(top, v)},
                          tool.radiusMm() * (1 + 1e-9) + 1e-9);
    for (int j = j0; j <= j1; ++j) {
        double uLo, uHi;
        if (!capsule.row(rg.vAt(j), uLo, uHi))
            continue;
        const int iLo = std::max(i0, int(std::ceil((uLo - rg.u0) / rg.du - 0.5)));
        const int iHi = std::min(i1, int(std::floor((uHi - rg.u0) / rg.du - 0.5)));
        for (int i = iLo; i <= iHi; ++i) {
            const std::size_t k = g.at(i, j);
            std::vector<Span>& spans = g.spans[k];
            if (spans.empty() || spans.front().lo > hi || spans.back().hi < lo)
                continue;
            Vec3 origin;
            setComp(origin, a, comp(m_box.min, a));
            setComp(origin, u, rg.uAt(i));
            setComp(origin, v, rg.vAt(j));
            const LineSpan cutter = tool.intersect(ToolPart::Cutter, tip, toolAxis, origin, dir);
            if (cutter.empty())
                continue;
            const double c0 = comp(m_box.min, a) + cutter.s0, c1 = comp(m_box.min, a) + cutter.s1;
            if (spans.front().lo >= c1 || spans.back().hi <= c0)
                continue;
            // Most rays the cutter crosses were cut by the poses before: find out before copying.
            if (std::none_of(spans.begin(), spans.end(), [&](const Span& s) {
                    return std::min<double>(s.hi, c1) - std::max<double>(s.lo, c0) > m_spanSlack;
                }))
                continue;
            double removed = 0;
            std::vector<Span> kept;
            kept.reserve(spans.size() + 1);
            for (const Span& s : spans) {
                const double r0 = std::max<double>(s.lo, c0), r1 = std::min<double>(s.hi, c1);
                if (r1 - r0 <= m_spanSlack) {
                    kept.push_back(s);
                    continue;
                }
                removed += r1 - r0;
                if (s.lo < r0)
                    kept.push_back({s.lo, float(r0)});
                if (s.hi > r1)
                    kept.push_back({float(r1), s.hi});
                if (!g.design.empty())  // the deepest removed point inside a design span, along the ray
                    for (const Span& d : g.design[k]) {
                        const double dlo = std::max<double>(r0, d.lo), dhi = std::min<double>(r1, d.hi);
                        if (dlo >= dhi)
                            continue;
                        const double x = std::clamp((double(d.lo) + d.hi) / 2, dlo, dhi);
                        double depth = std::min(x - d.lo, d.hi - x);
                        if (depth <= m_tolerance || depth <= seen.gouge)
                            continue;
                        // Along one ray, a point just under a surface the ray runs nearly along
                        // (a drill's tip on a tilted floor) reads as deep as the part is long:
                        // the depth is also at most what the other grids' rays through it say.
                        const Vec3 at = origin + dir * (x - comp(m_box.min, a));
                        depth = std::min({depth, depthInside((a + 1) % 3, at), depthInside((a + 2) % 3, at)});
                        if (depth > m_tolerance && depth > seen.gouge)
                            depth = trueDepth(at, depth);
                        if (depth > m_tolerance && depth > seen.gouge) {
                            seen.gouge = depth;
                            seen.gougeAt = at;
                        }
                    }
            }
            if (removed <= 0)
                continue;
            spans.swap(kept);
            g.lastCut[k] = std::int32_t(moveIndex);
            seen.removed += removed;
            if (std::hypot(rg.uAt(i) - comp(tip, u), rg.vAt(j) - comp(tip, v)) <= axisBand)
                seen.onAxis = true;
        }
    }
}

double TriDexel::depthInside(int axis, const Vec3& p) const
{
    if (m_grids[axis].design.empty())
        return std::numeric_limits<double>::infinity();
    const auto [i, j] = rayThrough(axis, p);
    return std::max(0.0, -alongRay(axis, i, j, comp(p, axis)));
}

std::pair<int, int> TriDexel::rayThrough(int axis, const Vec3& p) const
{
    const RayGrid& rg = m_grids[axis].rays;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    return {std::clamp(int(std::floor((comp(p, u) - rg.u0) / rg.du)), 0, rg.nu - 1),
            std::clamp(int(std::floor((comp(p, v) - rg.v0) / rg.dv)), 0, rg.nv - 1)};
}

// Shank and holder against the Z rays (at most 64 x 64 of them over their box): the length of
// remaining material along a ray inside either is how deep they reach into the stock.
void TriDexel::checkHolder(const Vec3& tip, const Vec3& toolAxis, const ToolShape& tool, CutResult& result) const
{
    const Grid& g = m_grids[2];
    const RayGrid& rg = g.rays;
    const double r = tool.boundingRadiusMm();
    base::Box3 reach;
    reach.add(tip + toolAxis * tool.fluteLengthMm());
    reach.add(tip + toolAxis * tool.totalLengthMm());
    if (reach.min.z > m_box.max.z)
        return;
    const int i0 = std::max(0, int(std::floor((reach.min.x - r - rg.u0) / rg.du)));
    const int i1 = std::min(rg.nu - 1, int(std::floor((reach.max.x + r - rg.u0) / rg.du)));
    const int j0 = std::max(0, int(std::floor((reach.min.y - r - rg.v0) / rg.dv)));
    const int j1 = std::min(rg.nv - 1, int(std::floor((reach.max.y + r - rg.v0) / rg.dv)));
    const int si = std::max(1, (i1 - i0) / 64), sj = std::max(1, (j1 - j0) / 64);
    const Vec3 up{0, 0, 1};
    for (int j = j0; j <= j1; j += sj)
        for (int i = i0; i <= i1; i += si) {
            const std::vector<Span>& spans = g.spans[g.at(i, j)];
            if (spans.empty())
                continue;
            const Vec3 origin{rg.uAt(i), rg.vAt(j), m_box.min.z};
            for (ToolPart part : {ToolPart::Shank, ToolPart::Holder}) {
                const LineSpan s = tool.intersect(part, tip, toolAxis, origin, up);
                if (s.empty())
                    continue;
                double inside = 0, top = 0;
                for (const Span& m : spans) {
                    const double lo = std::max<double>(m.lo, m_box.min.z + s.s0),
                                 hi = std::min<double>(m.hi, m_box.min.z + s.s1);
                    if (hi > lo)
                        inside += hi - lo, top = hi;
                }
                if (inside > result.holderInterferenceMm)
                    result.holderInterferenceMm = inside, result.holderAt = {origin.x, origin.y, top};
            }
        }
}

}  // namespace camwb::sim
