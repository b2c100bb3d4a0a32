// The height field's sweep of a flat tool along a level arc. A point lies within r of the arc
// from a to b when its angle about the centre lies between theirs and its distance from the
// centre within r of the arc's radius (the annular sector), or when it lies within r of a or b:
// past the arc's ends the nearest point of the arc is an end. So a row of the sweep is at most
// two spans of the annulus cut by the sector's two rays, and the end discs' chords; a quarter
// arc's fifteen pieces, cut as chords, set up each row fifteen times for a column or two each.
#include "sim/HeightField.h"

#include "sim/detail/HeightFieldRows.h"

#include <algorithm>
#include <cmath>

namespace camwb::sim {

namespace {

// Narrows the x range [lo, hi] (relative to the centre) of row wy to the half-plane left of the
// ray along d (cross(d, w) >= 0), or right of it. The bound is computed the same way for either
// side, so two sectors sharing a ray split a row's columns between them without a gap.
void clipToSide(base::Vec2 d, double wy, bool left, double& lo, double& hi)
{
    if (d.y == 0) {
        const double s = d.x * wy;
        if (left ? s < 0 : s > 0)
            lo = 1, hi = 0;
        return;
    }
    const double bound = d.x * wy / d.y;
    if ((d.y > 0) == left)
        hi = std::min(hi, bound);
    else
        lo = std::max(lo, bound);
}

struct Span {
    double x0, x1;
};

// The box of the arc from a to b about `centre` (less than half a turn, the shorter way): its
// ends and the points where it crosses an axis direction.
struct ArcBox {
    ArcBox(base::Vec2 a, base::Vec2 b, base::Vec2 centre, double radius)
    {
        const base::Vec2 da = a - centre, db = b - centre;
        ccw = da.cross(db) >= 0;
        from = ccw ? da : db, to = ccw ? db : da;
        lo = {std::min(a.x, b.x), std::min(a.y, b.y)}, hi = {std::max(a.x, b.x), std::max(a.y, b.y)};
        for (const base::Vec2 e : {base::Vec2{1, 0}, base::Vec2{0, 1}, base::Vec2{-1, 0}, base::Vec2{0, -1}})
            if (from.cross(e) >= 0 && e.cross(to) >= 0) {
                const base::Vec2 p = centre + e * radius;
                lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
            }
    }
    bool ccw;
    base::Vec2 from, to;  // the sector runs counter-clockwise from the ray along `from` to `to`
    base::Vec2 lo, hi;
};

}  // namespace

double HeightField::arcBulge(const Move& move)
{
    if (move.arcRadius <= 0)
        return 0;
    const double half = 0.5 * base::distance(move.from.xy(), move.to.xy());
    return move.arcRadius - std::sqrt(std::max(0.0, move.arcRadius * move.arcRadius - half * half));
}

bool HeightField::holderClear(base::Vec2 lo, base::Vec2 hi, double z, const ToolShape& tool) const
{
    auto clear = [&](double radius, double bottom) {
        return z + bottom >= m_box.max.z || tilesBelow(columnsWithin(lo, hi, radius), z + bottom);
    };
    return (tool.stickOutMm() <= tool.fluteLengthMm() || clear(tool.shankRadiusMm(), tool.fluteLengthMm())) &&
           (tool.holderRadiusMm() <= 0 || clear(tool.holderRadiusMm(), tool.stickOutMm()));
}

void HeightField::sweepLevelArc(base::Vec2 a, base::Vec2 b, base::Vec2 centre, double arcRadius, double z, double r,
                                bool startDone, std::size_t moveIndex, CutResult& result)
{
    const ArcBox box(a, b, centre, arcRadius);
    const base::Vec2 from = box.from, to = box.to;
    const ColumnRect near = columnsWithin(box.lo, box.hi, r);
    if (near.empty())
        return;
    const int j0 = near.j0, j1 = near.j1;
    const double outer = arcRadius + r, inner = arcRadius - r;
    const detail::ColumnIndex column(m_box.min.x, m_dx);
    // x clamped to a column beyond the grid before it becomes an index (a huge arc's sector
    // reaches far beyond the stock).
    const double xMin = m_box.min.x - m_dx, xMax = m_box.max.x + m_dx;
    auto sweep = [&](int j, double x0, double x1) {
        const int i0 = std::max(0, column.atOrRight(std::max(x0, xMin)));
        const int i1 = std::min(m_nx - 1, column.atOrLeft(std::min(x1, xMax)));
        lowerSpan(j, i0, i1, z, moveIndex, result);
    };
    // The end disc's chords, kept for the next move (it starts there).
    const DiscChords& end = computeEndChords(b, r, j0, j1);
    for (int j = j0; j <= j1; ++j) {
        const double y = columnY(j), wy = y - centre.y;
        // The row's spans (the sector's two at most, the discs'), merged where they overlap so
        // that each column is looked at once: the discs lie mostly inside the sector.
        Span spans[4];
        int count = 0;
        auto add = [&](double x0, double x1) {
            if (x0 <= x1)
                spans[count++] = {x0, x1};
        };
        if (std::abs(wy) <= outer) {
            const double half = std::sqrt(outer * outer - wy * wy);
            double x0 = -half, x1 = half;
            clipToSide(from, wy, true, x0, x1);
            clipToSide(to, wy, false, x0, x1);
            if (inner > 0 && std::abs(wy) < inner) {  // the row crosses the hole inside the annulus
                const double hole = std::sqrt(inner * inner - wy * wy);
                add(centre.x + x0, centre.x + std::min(x1, -hole));
                add(centre.x + std::max(x0, hole), centre.x + x1);
            } else {
                add(centre.x + x0, centre.x + x1);
            }
        }
        const double endHalf = end.half[std::size_t(j - j0)];
        if (endHalf >= 0)
            add(b.x - endHalf, b.x + endHalf);
        if (!startDone) {
            const double startHalf = startChord(a, r, j);
            if (startHalf >= 0)
                add(a.x - startHalf, a.x + startHalf);
        }
        std::sort(spans, spans + count, [](const Span& p, const Span& q) { return p.x0 < q.x0; });
        for (int k = 0; k < count;) {
            Span merged = spans[k++];
            for (; k < count && spans[k].x0 <= merged.x1; ++k)
                merged.x1 = std::max(merged.x1, spans[k].x1);
            sweep(j, merged.x0, merged.x1);
        }
    }
    keepEndChords();
}

// A helix's pieces each lower the whole disc under the tool's end a little deeper than the one
// before: cut in turn, every column under the tool is written again by each piece. A cut only
// lowers columns to the lowest the tool reaches over them, so the order of the cuts does not
// change the stock, nor the volume and the deepest gouge they add up to. Cut from the last piece
// back, the first (deepest) writes the disc and the others find most of it below them already and
// pass it by. The shank and holder would meet the stock as each piece leaves it: where they could
// reach it anywhere about the circle, the pieces are cut in turn.
CutResult HeightField::cutHelixRun(const Move* first, std::size_t count, std::size_t moveIndex, const ToolShape& tool)
{
    const base::Vec2 centre = first->arcCentre, out{first->arcRadius, first->arcRadius};
    double zLow = first->from.z;
    for (std::size_t k = 0; k < count; ++k)
        zLow = std::min(zLow, first[k].to.z);
    if (!holderClear(centre - out, centre + out, zLow, tool))
        return Stock::cutArcRun(first, count, moveIndex, tool);
    CutResult result;
    m_cutNow = {};
    const double r = tool.radiusMm();
    for (std::size_t k = count; k-- > 0;) {
        // A flat tool's disc where a piece is lowest is where its neighbour starts (going down)
        // or ends (going up), and the neighbour, going on the same way, is as low there.
        const bool down = first[k].to.z < first[k].from.z;
        const bool discCovered =
            tool.flatBottomed() && (down ? k + 1 < count && first[k + 1].to.z <= first[k + 1].from.z
                                         : k > 0 && first[k - 1].to.z >= first[k - 1].from.z);
        if (!clearOfStock(first[k], r + arcBulge(first[k])))
            cutVertical(first[k], moveIndex, tool, result, discCovered);
    }
    refreshTiles(m_cutNow);
    m_changed.add(m_cutNow);
    m_lastEnd = first[count - 1].to, m_lastRadius = r, m_lastFlatVertical = tool.flatBottomed();
    return result;
}

CutResult HeightField::cutArcRun(const Move* first, std::size_t count, std::size_t moveIndex, const ToolShape& tool)
{
    const double r = tool.radiusMm();
    if (count < 2 || r <= 0 || !first->positionKnown)
        return Stock::cutArcRun(first, count, moveIndex, tool);
    for (std::size_t k = 1; k < count; ++k)
        if (!continuesLevelArc(first[k - 1], first[k]))  // a helix (or any run not all level)
            return cutHelixRun(first, count, moveIndex, tool);
    if (!tool.flatBottomed())
        return Stock::cutArcRun(first, count, moveIndex, tool);
    const base::Vec2 centre = first->arcCentre;
    const double arcRadius = first->arcRadius, z = first->from.z;
    CutResult result;
    for (std::size_t k = 0; k < count;) {
        // Pieces while the turn from this one's start stays within a third of a turn: a convex
        // sector whose rays are far from opposite, so which way it turns is never in doubt (a
        // quarter arc, the commonest, is one sector).
        const base::Vec2 a = first[k].from.xy() - centre;
        const bool ccw = a.cross(first[k].to.xy() - centre) >= 0;
        const double third = -0.5 * arcRadius * arcRadius;  // a.dot(b) at 120 degrees
        std::size_t e = k + 1;
        for (; e < count; ++e) {
            const base::Vec2 b = first[e].to.xy() - centre;
            if (a.dot(b) < third || (a.cross(b) >= 0) != ccw)
                break;
        }
        const Move& last = first[e - 1];
        // The shank and holder meet what each piece leaves: where they could reach the stock at
        // all, the pieces are cut one by one.
        const ArcBox box(first[k].from.xy(), last.to.xy(), centre, arcRadius);
        if (e - k == 1 || !holderClear(box.lo, box.hi, z, tool)) {
            for (; k < e; ++k)
                result.add(cut(first[k], moveIndex, tool));
            continue;
        }
        m_cutNow = {};
        const bool startDone = m_lastFlatVertical && m_lastRadius == r && m_lastEnd == first[k].from;
        if (z < m_box.max.z && !tilesBelow(columnsWithin(box.lo, box.hi, r), z + detail::kEps))
            sweepLevelArc(first[k].from.xy(), last.to.xy(), centre, arcRadius, z, r, startDone, moveIndex, result);
        refreshTiles(m_cutNow);
        m_changed.add(m_cutNow);
        m_lastEnd = last.to, m_lastRadius = r, m_lastFlatVertical = true;
        k = e;
    }
    return result;
}

}  // namespace camwb::sim
