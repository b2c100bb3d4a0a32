#include "sim/HeightField.h"

#include "sim/Capsule.h"
#include "sim/MeshRays.h"
#include "sim/detail/HeightFieldRows.h"

#include "base/Prefault.h"

#include <algorithm>
#include <cmath>

namespace camwb::sim {

using detail::kEps;

namespace {

bool vertical(const Vec3& axis) { return std::abs(axis.x) < 1e-9 && std::abs(axis.y) < 1e-9 && axis.z > 0; }

// The minimum of a convex function on [lo, hi] by golden section (one evaluation per step).
template <class F> double convexMin(F f, double lo, double hi)
{
    constexpr double g = 0.6180339887498949;
    double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    double f1 = f(m1), f2 = f(m2);
    for (int i = 0; i < 40; ++i) {
        if (f1 < f2) {
            hi = m2, m2 = m1, f2 = f1, m1 = hi - g * (hi - lo), f1 = f(m1);
        } else {
            lo = m1, m1 = m2, f1 = f2, m2 = lo + g * (hi - lo), f2 = f(m2);
        }
    }
    return std::min({f1, f2, f(lo), f(hi)});
}

}  // namespace

void ColumnRect::add(const ColumnRect& r)
{
    if (!r.empty())
        add(r.i0, r.j0), add(r.i1, r.j1);
}

HeightField::HeightField(const base::Box3& box, double resolutionMm) : m_box(box)
{
    m_nx = int(cellsAcross(box.max.x - box.min.x, resolutionMm));
    m_ny = int(cellsAcross(box.max.y - box.min.y, resolutionMm));
    m_dx = (box.max.x - box.min.x) / m_nx;
    m_dy = (box.max.y - box.min.y) / m_ny;
    const std::size_t columns = std::size_t(m_nx) * m_ny;
    m_top.reserve(columns);
    base::prefault(m_top, columns);  // megabytes at 0.1 mm, written whole: one call, not a fault per page
    m_top.assign(columns, float(box.max.z));
    m_floor = float(box.min.z);
    m_tilesX = (m_nx + kTile - 1) / kTile;
    m_tilesY = (m_ny + kTile - 1) / kTile;
    m_tileTop.assign(std::size_t(m_tilesX) * m_tilesY, float(box.max.z));
    m_tileStale.assign(m_tileTop.size(), 0);
}

void HeightField::refreshTiles(const ColumnRect& rect)
{
    if (rect.empty())
        return;
    for (int tj = rect.j0 / kTile; tj <= rect.j1 / kTile; ++tj)
        for (int ti = rect.i0 / kTile; ti <= rect.i1 / kTile; ++ti)
            m_tileStale[std::size_t(tj) * m_tilesX + ti] = 1;
}

float HeightField::tileTop(int ti, int tj) const
{
    const std::size_t t = std::size_t(tj) * m_tilesX + ti;
    if (m_tileStale[t]) {
        float high = -std::numeric_limits<float>::infinity();
        for (int j = tj * kTile; j < std::min(m_ny, (tj + 1) * kTile); ++j)
            for (int i = ti * kTile; i < std::min(m_nx, (ti + 1) * kTile); ++i)
                high = std::max(high, m_top[index(i, j)]);
        m_tileTop[t] = high;
        m_tileStale[t] = 0;
    }
    return m_tileTop[t];
}

std::unique_ptr<HeightField> HeightField::fromMesh(const TriangleMesh& blank, double resolutionMm)
{
    auto field = std::make_unique<HeightField>(blank.bounds(), resolutionMm);
    HeightField& f = *field;
    std::fill(f.m_top.begin(), f.m_top.end(), kNone);
    f.m_bottom.assign(f.m_top.size(), -kNone);
    const RayGrid grid{2, f.m_box.min.x, f.m_box.min.y, f.m_dx, f.m_dy, f.m_nx, f.m_ny};
    forEachCrossing(blank, grid, [&](int i, int j, double z, bool) {
        const std::size_t k = f.index(i, j);
        f.m_top[k] = std::max(f.m_top[k], float(z));
        f.m_bottom[k] = std::min(f.m_bottom[k], float(z));
    });
    for (std::size_t k = 0; k < f.m_top.size(); ++k)
        if (f.m_top[k] == kNone)  // no blank over this column: an empty column at the blank's foot
            f.m_top[k] = f.m_bottom[k] = float(f.m_box.min.z);
    f.refreshTiles({0, 0, f.m_nx - 1, f.m_ny - 1});
    return field;
}

double HeightField::volumeMm3() const
{
    double sum = 0;
    if (m_bottom.empty())
        for (const float top : m_top)
            sum += double(top) - m_floor;
    else
        for (std::size_t k = 0; k < m_top.size(); ++k)
            sum += double(m_top[k]) - m_bottom[k];
    return sum * m_dx * m_dy;
}

std::size_t HeightField::memoryBytes() const
{
    return sizeof(*this) +
           sizeof(float) * (m_top.capacity() + m_bottom.capacity() + m_design.capacity() + m_designNear.capacity() +
                            m_tileTop.capacity()) +
           sizeof(std::int32_t) * m_lastCut.capacity() + m_tileStale.capacity() +
           sizeof(double) * (m_endChords.half.capacity() + m_spareChords.half.capacity());
}

ColumnRect HeightField::takeChanged() { return std::exchange(m_changed, ColumnRect{}); }

CutResult HeightField::cut(const Move& move, std::size_t moveIndex, const ToolShape& tool)
{
    CutResult result;
    if (!move.moves() || !move.positionKnown || tool.radiusMm() <= 0)
        return result;
    m_cutNow = {};
    if (vertical(move.fromAxis()) && vertical(move.toAxis())) {
        // The cutter leads: the shank and holder meet what it left (a shank as wide as the
        // cutter rides in its own slot), so they are checked against the stock after the cut.
        if (!clearOfStock(move, tool.radiusMm() + arcBulge(move)))
            cutVertical(move, moveIndex, tool, result);
        checkHolder(move, tool, result);
    } else {
        cutTilted(move, moveIndex, tool, result);
    }
    refreshTiles(m_cutNow);
    m_changed.add(m_cutNow);
    m_lastEnd = move.to;
    m_lastRadius = tool.radiusMm();
    m_lastFlatVertical = tool.flatBottomed() && vertical(move.toAxis());
    return result;
}

// The cutter's lowest point over a vertical move is its tip's lowest height: where no column
// within its reach rises above that, the move cuts nothing. Most rapids and many links run above
// the stock or over cleared ground; this spares them the sweep. The tiles' bounds are looked at
// only for moves long enough that a sweep costs more than reading a tile afresh.
bool HeightField::clearOfStock(const Move& move, double reach) const
{
    const double zLow = std::min(move.from.z, move.to.z);
    if (zLow >= m_box.max.z)  // above the highest the stock ever was
        return true;
    const double cell = std::max(m_dx, m_dy);
    if (move.lengthMm() < kTile * cell)
        return false;
    return tilesBelow(columnsWithin(move.from.xy(), move.to.xy(), reach), zLow + kEps);
}

bool HeightField::tilesBelow(const ColumnRect& near, double z) const
{
    if (near.empty())
        return true;
    for (int tj = near.j0 / kTile; tj <= near.j1 / kTile; ++tj)
        for (int ti = near.i0 / kTile; ti <= near.i1 / kTile; ++ti)
            if (tileTop(ti, tj) > z)  // a column here may rise above z
                return false;
    return true;
}

ColumnRect HeightField::columnsWithin(base::Vec2 a, base::Vec2 b, double reach) const
{
    ColumnRect rect;
    rect.i0 = std::max(0, int(std::floor((std::min(a.x, b.x) - reach - m_box.min.x) / m_dx)));
    rect.i1 = std::min(m_nx - 1, int(std::floor((std::max(a.x, b.x) + reach - m_box.min.x) / m_dx)));
    rect.j0 = std::max(0, int(std::floor((std::min(a.y, b.y) - reach - m_box.min.y) / m_dy)));
    rect.j1 = std::min(m_ny - 1, int(std::floor((std::max(a.y, b.y) + reach - m_box.min.y) / m_dy)));
    return rect;
}

[[gnu::noinline]] void HeightField::lowerLongSpan(int j, int i0, int i1, double height, std::size_t moveIndex,
                                                  CutResult& result)
{
    lowerSpan(j, i0, i1, height, moveIndex, result);
}

// One column: lowerSpan's loop over it (the one place that lowers a column, counts its volume,
// marks its move and looks for a gouge).
inline void HeightField::lower(int i, int j, double height, std::size_t moveIndex, CutResult& result)
{
    lowerSpan(j, i, i, height, moveIndex, result);
}

void HeightField::noteGouge(int i, int j, double z, CutResult& result) const
{
    const double depth = depthInDesign(i, j, z);
    if (depth > m_tolerance && depth > result.gougeMm) {
        result.gougeMm = depth;
        result.gougeAt = {columnX(i), columnY(j), z};
    }
}

const HeightField::DiscChords& HeightField::computeEndChords(base::Vec2 b, double r, int j0, int j1)
{
    DiscChords& end = m_spareChords;
    end.centre = b, end.radius = r, end.j0 = j0;
    end.half.resize(std::size_t(std::max(0, j1 - j0 + 1)));
    for (int j = j0; j <= j1; ++j)
        end.half[std::size_t(j - j0)] = Capsule::halfChord(b, r, columnY(j));
    return end;
}

double HeightField::startChord(base::Vec2 a, double r, int j) const
{
    const DiscChords& kept = m_endChords;
    const int k = j - kept.j0;
    if (kept.radius == r && kept.centre == a && k >= 0 && k < int(kept.half.size()))
        return kept.half[std::size_t(k)];
    return Capsule::halfChord(a, r, columnY(j));
}

// The vertical tool's sweep. At a column q the cutter's lower surface over the move is
// f(t) = z(t) + L(d(t)) with d(t) = |q - c(t)| the distance to the tool's centre: d is convex
// in t (the norm of an affine function), L is convex and non-decreasing for every profile here
// (ToolShape::lowerSurface), so L(d(t)) is convex and f, adding the linear z(t), is convex too.
// Its minimum over the t where the column is under the cutter is exact for level moves (the
// nearest point of the segment) and for flat tools (an end of the interval, f being linear),
// and found by golden section otherwise. The shank's and the holder's lowest points over the
// move are at an end of their intervals (their bottoms are flat).
void HeightField::cutVertical(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result,
                              bool discCovered)
{
    const base::Vec2 c0 = move.from.xy(), c1 = move.to.xy(), v = c1 - c0;
    const double z0 = move.from.z, dz = move.to.z - move.from.z, vv = v.dot(v), perVv = vv < 1e-18 ? 0 : 1 / vv;
    const double r = tool.radiusMm(), reach = r;
    const bool flat = tool.flatBottomed();
    const bool plunge = move.plunges();
    const double axisBand = 0.75 * std::max(m_dx, m_dy);
    auto zAt = [&](double t) { return z0 + t * dz; };
    // The parameters [ta, tb] where the column lies within `radius` of the centre.
    auto under = [&](double e2, double tStar, double radius, double& ta, double& tb) {
        if (e2 > radius * radius)
            return false;
        if (vv < 1e-18) {
            ta = 0, tb = 1;
            return true;
        }
        const double half = std::sqrt((radius * radius - e2) * perVv);
        ta = std::max(0.0, tStar - half), tb = std::min(1.0, tStar + half);
        return ta <= tb;
    };
    const ColumnRect near = columnsWithin(c0, c1, reach);
    const int j0 = near.j0, j1 = near.j1;
    const detail::ColumnIndex column(m_box.min.x, m_dx);
    const Capsule capsule(c0, c1, r);
    const double lowest = std::min(z0, z0 + dz) + kEps;
    if (flat && std::abs(dz) < 1e-12 && !plunge) {
        // A flat tool moving level: every column under the capsule goes down to z, so a row is
        // one span of columns (those whose centres lie in it) and a tight loop over it. When the
        // last cut left this tool standing at the start, its disc there is already at z or
        // below: only the columns beyond it are looked at (short arc pieces sweep a crescent).
        const bool startDone = m_lastFlatVertical && m_lastRadius == r && m_lastEnd == move.from;
        if (move.arcRadius > 0) {  // a piece of an arc: the arc's own sweep, as cutArcRun() makes it
            sweepLevelArc(c0, c1, move.arcCentre, move.arcRadius, z0, r, startDone, moveIndex, result);
            return;
        }
        auto sweep = [&](int j, int i0, int i1) {
            lowerSpan(j, std::max(0, i0), std::min(m_nx - 1, i1), z0, moveIndex, result);
        };
        // The end disc's chords are kept for the next move: a chain of arc pieces then takes one
        // root a row instead of two.
        const DiscChords& end = computeEndChords(c1, r, j0, j1);
        for (int j = j0; j <= j1; ++j) {
            const double y = columnY(j);
            const double half = startChord(c0, r, j);  // the start disc's chord on this row, -1 off it
            double xlo, xhi;
            if (!capsule.rowFromChords(y, half, end.half[std::size_t(j - j0)], xlo, xhi))
                continue;
            const int i0 = column.atOrRight(xlo), i1 = column.atOrLeft(xhi);
            if (!startDone || half <= 0) {
                sweep(j, i0, i1);
                continue;
            }
            const int s0 = column.atOrRight(c0.x - half), s1 = column.atOrLeft(c0.x + half);
            sweep(j, i0, std::min(i1, s0 - 1));
            sweep(j, std::max(i0, s1 + 1), i1);
        }
        keepEndChords();
        return;
    }
    for (int j = j0; j <= j1; ++j) {
        const double y = columnY(j);
        double xlo, xhi;
        if (!capsule.row(y, xlo, xhi))
            continue;
        // Rounded outwards (at most a column beyond each end): each column is tested below.
        const int i0 = std::max(0, column.atOrLeft(xlo)), i1 = std::min(m_nx - 1, column.atOrRight(xhi));
        // A flat tool ramping: its lowest point over a column is where the column last (going
        // down) or first (going up) lies under it, so the disc at that end of the move is at that
        // end's height, without a root per column. Going up from where the last cut left this
        // tool, that disc is already cut.
        int k0 = 1, k1 = 0;
        const bool down = dz < 0;
        const base::Vec2 disc = down ? c1 : c0;
        const double discZ = down ? z0 + dz : z0;
        const bool discDone =
            discCovered || (!down && m_lastFlatVertical && m_lastRadius == r && m_lastEnd == move.from);
        if (flat && !plunge && vv >= 1e-18 && std::abs(y - disc.y) < r) {
            const double half = std::sqrt(r * r - (y - disc.y) * (y - disc.y));
            k0 = column.atOrRight(disc.x - half), k1 = column.atOrLeft(disc.x + half);
        }
        const float* top = &m_top[index(0, j)];
        for (int i = i0; i <= i1; ++i) {
            if (i >= k0 && i <= k1) {  // the end disc's span of this row, in one go
                if (!discDone)
                    lowerLongSpan(j, i, std::min(k1, i1), discZ, moveIndex, result);
                i = std::min(k1, i1);
                continue;
            }
            // No part of the cutter comes lower than the tip's lowest height: a column at or below
            // it is left without its geometry (most of a helix's, cut from its last piece back).
            if (top[i] <= lowest)
                continue;
            const base::Vec2 w = base::Vec2{columnX(i), y} - c0;
            const double tStar = w.dot(v) * perVv;
            const double e2 = std::max(0.0, w.dot(w) - tStar * tStar * vv);  // squared distance to the line
            double ta, tb;
            if (!under(e2, tStar, r, ta, tb))
                continue;
            double f;
            if (std::abs(dz) < 1e-12) {
                const double tc = std::clamp(tStar, ta, tb);
                f = z0 + tool.lowerSurface(std::sqrt(e2 + (tc - tStar) * (tc - tStar) * vv));
            } else if (vv < 1e-18) {
                f = std::min(z0, z0 + dz) + tool.lowerSurface(std::sqrt(w.dot(w)));
            } else if (flat) {
                f = std::min(zAt(ta), zAt(tb));
            } else {
                f = convexMin(
                    [&](double t) {
                        return zAt(t) + tool.lowerSurface(std::min(r, std::sqrt(e2 + (t - tStar) * (t - tStar) * vv)));
                    },
                    ta, tb);
            }
            if (f >= m_top[index(i, j)] - kEps)
                continue;
            const double before = result.removedMm3;
            lower(i, j, f, moveIndex, result);
            if (plunge && result.removedMm3 > before && e2 <= axisBand * axisBand)
                result.removedOnAxis = true;
        }
    }
}

// The shank (from the flute length up) and the holder (from the stick-out up) have flat bottoms:
// over the move a column within their radius meets them lowest at an end of the parameter
// interval where it is under them; stock above that is how deep they reach. Only tiles whose
// highest top rises above the lowest such bottom are looked at.
void HeightField::checkHolder(const Move& move, const ToolShape& tool, CutResult& result) const
{
    const base::Vec2 c0 = move.from.xy(), v = move.to.xy() - c0;
    const double vv = v.dot(v), z0 = move.from.z, dz = move.to.z - move.from.z, zLow = std::min(z0, z0 + dz);
    struct Part {
        double radius, bottom;  // bottom: above the tip
    };
    std::vector<Part> parts;
    if (tool.stickOutMm() > tool.fluteLengthMm())
        parts.push_back({tool.shankRadiusMm(), tool.fluteLengthMm()});
    if (tool.holderRadiusMm() > 0)
        parts.push_back({tool.holderRadiusMm(), tool.stickOutMm()});
    for (const Part& part : parts) {
        // An arc piece's cutter sweeps the arc, this the chord: narrowed by the arc's bulge, the
        // chord's band lies within the arc's, so a shank as wide as the cutter rides in its slot.
        const double reach = part.radius - arcBulge(move), lowest = zLow + part.bottom;
        if (lowest >= m_box.max.z)  // above the highest the stock ever was (the usual case)
            continue;
        const ColumnRect near = columnsWithin(c0, c0 + v, reach);
        if (near.empty())
            continue;
        const int i0 = near.i0, i1 = near.i1, j0 = near.j0, j1 = near.j1;
        for (int tj = j0 / kTile; tj <= j1 / kTile; ++tj)
            for (int ti = i0 / kTile; ti <= i1 / kTile; ++ti) {
                if (tileTop(ti, tj) <= lowest + result.holderInterferenceMm)
                    continue;
                for (int j = std::max(j0, tj * kTile); j <= std::min(j1, (tj + 1) * kTile - 1); ++j)
                    for (int i = std::max(i0, ti * kTile); i <= std::min(i1, (ti + 1) * kTile - 1); ++i) {
                        const double oldTop = m_top[index(i, j)];
                        if (oldTop <= lowest + result.holderInterferenceMm)
                            continue;
                        const base::Vec2 w = base::Vec2{columnX(i), columnY(j)} - c0;
                        const double tStar = vv < 1e-18 ? 0 : w.dot(v) / vv;
                        const double e2 = std::max(0.0, w.dot(w) - tStar * tStar * vv);
                        if (e2 > reach * reach)
                            continue;
                        double ta = 0, tb = 1;
                        if (vv >= 1e-18) {
                            const double half = std::sqrt((reach * reach - e2) / vv);
                            ta = std::max(0.0, tStar - half), tb = std::min(1.0, tStar + half);
                            if (ta > tb)
                                continue;
                        }
                        const double depth = oldTop - (std::min(z0 + ta * dz, z0 + tb * dz) + part.bottom);
                        if (depth > result.holderInterferenceMm)
                            result.holderInterferenceMm = depth, result.holderAt = {columnX(i), columnY(j), oldTop};
                    }
            }
    }
}

// A tilted tool in a z-map: poses at most half a cell apart, each lowering the columns to the
// cutter's lowest point over their centres (what a z-map can hold of a tilted cut; undercuts
// need the dexel stock).
void HeightField::cutTilted(const Move& move, std::size_t moveIndex, const ToolShape& tool, CutResult& result)
{
    const double step = 0.5 * std::min(m_dx, m_dy);
    const double turn = move.fromAxis().angleTo(move.toAxis()) * tool.totalLengthMm();
    const int poses = std::max(1, int(std::ceil(std::max(move.lengthMm(), turn) / step)));
    const double reach = tool.boundingRadiusMm(), below = m_box.min.z - 1;
    const Vec3 up{0, 0, 1};
    for (int p = 0; p <= poses; ++p) {
        const double t = double(p) / poses;
        const Vec3 tip = move.from + (move.to - move.from) * t;
        const Vec3 axis = move.axisAt(t);
        const Vec3 end = tip + axis * tool.totalLengthMm();
        const ColumnRect near = columnsWithin(tip.xy(), end.xy(), reach);
        for (int j = near.j0; j <= near.j1; ++j)
            for (int i = near.i0; i <= near.i1; ++i) {
                const Vec3 origin{columnX(i), columnY(j), below};
                const double oldTop = m_top[index(i, j)];
                for (ToolPart part : {ToolPart::Shank, ToolPart::Holder}) {
                    const LineSpan s = tool.intersect(part, tip, axis, origin, up);
                    if (!s.empty() && oldTop - (below + s.s0) > result.holderInterferenceMm)
                        result.holderInterferenceMm = oldTop - (below + s.s0),
                        result.holderAt = {origin.x, origin.y, oldTop};
                }
                const LineSpan s = tool.intersect(ToolPart::Cutter, tip, axis, origin, up);
                if (s.empty())
                    continue;
                const double before = result.removedMm3;
                lower(i, j, below + s.s0, moveIndex, result);
                const Vec3 off = origin - tip;
                const double radial = (off - axis * off.dot(axis)).length();
                if (result.removedMm3 > before && radial <= 0.75 * std::max(m_dx, m_dy) &&
                    -(move.to - move.from).dot(axis) > (move.to - move.from).length() * std::sqrt(0.5))
                    result.removedOnAxis = true;
            }
    }
}

}  // namespace camwb::sim
