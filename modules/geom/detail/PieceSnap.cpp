#include "geom/detail/PieceSnap.h"

#include "geom/CarrierIntersection.h"
#include "geom/detail/LoopQueries.h"
#include "geom/detail/OffsetCore.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace camwb::geom::detail {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
// Pieces a contour edge may skip whole (Clipper drops repeated points, so a piece shorter than its
// 1 nm grid leaves no vertex of its own).
constexpr std::size_t kMaxSkipped = 4;
constexpr double kMinSegment = 1e-9;  // mm: shorter runs are left out
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kMaxArcSweep = 1.5 * std::numbers::pi;  // longer runs are split, as ArcFit does

}  // namespace

// Walks one contour back onto the pieces: which piece each edge runs along, the exact corner
// where the piece changes, then the runs between corners as lines and arcs.
class ContourWalk {
public:
    ContourWalk(const PieceSnap& snap, const ClipperLib::Path& contour) :
        m_snap(snap),
        m_raw(snap.m_raw),
        m_contour(contour),
        m_n(contour.size())
    {
    }

    std::optional<Profile> run()
    {
        if (m_n < 3)
            return std::nullopt;
        m_origin.resize(m_n);
        m_at.resize(m_n);
        for (std::size_t v = 0; v < m_n; ++v) {
            m_origin[v] = m_snap.origin(m_contour[v]);
            m_at[v] = m_origin[v] ? m_origin[v]->exact : fromClipper(m_contour[v]);
        }
        m_edge.assign(m_n, kNone);
        m_walkTo.assign(m_n, kNone);
        for (std::size_t e = 0; e < m_n; ++e)
            if (!placeEdge(e))
                return std::nullopt;
        m_corner.assign(m_n, std::nullopt);
        std::size_t first = kNone;
        for (std::size_t v = 0; v < m_n; ++v) {
            const std::size_t in = arriving(v);
            if (in == m_edge[v])
                continue;
            m_corner[v] = cornerPoint(v, in, m_edge[v]);
            if (!m_corner[v])
                return std::nullopt;
            if (first == kNone)
                first = v;
        }
        if (first == kNone ? !wholeLoop() : !walkFrom(first))
            return std::nullopt;
        if (m_out.segments.empty())
            return std::nullopt;
        m_out.segments.back().end = m_out.segments.front().start;
        return plausible() ? std::optional<Profile>(std::move(m_out)) : std::nullopt;
    }

private:
    const RawPiece& piece(std::size_t k) const { return m_raw.pieces[k]; }

    static Vec2 tangentAt(const RawPiece& p, Vec2 q)
    {
        const Segment& s = p.segment;
        if (!s.isArc())
            return (s.end - s.start) * (1 / fastDistance(s.start, s.end));
        const Vec2 radial = (q - s.center) * (1 / fastDistance(q, s.center));
        return radial.leftNormal();
    }

    // The piece an edge arrives on at v.
    std::size_t arriving(std::size_t v) const
    {
        const std::size_t e = (v + m_n - 1) % m_n;
        return m_walkTo[e] != kNone ? m_walkTo[e] : m_edge[e];
    }

    std::size_t stepsForward(std::size_t from, std::size_t to) const
    {
        std::size_t k = from;
        for (std::size_t steps = 1; steps <= kMaxSkipped + 1; ++steps) {
            k = m_raw.next(k);
            if (k == to)
                return steps;
            if (k == from)
                break;
        }
        return kNone;
    }

    bool placeEdge(std::size_t e)
    {
        const std::size_t w = (e + 1) % m_n;
        const PieceSnap::Origin* ov = m_origin[e];
        const PieceSnap::Origin* ow = m_origin[w];
        const std::size_t a = ov ? ov->piece : kNone;
        const std::size_t b = ow ? (ow->isStart ? m_raw.prev(ow->piece) : ow->piece) : kNone;
        if (a != kNone && b != kNone && a != b) {
            if (stepsForward(a, b) != kNone) {
                m_edge[e] = a;
                m_walkTo[e] = b;
            } else if (m_snap.onPiece(m_at[e], b)) {
                m_edge[e] = b;  // the loops cross at the vertex itself
            } else if (m_snap.onPiece(m_at[w], a)) {
                m_edge[e] = a;
            } else {
                return false;
            }
            return true;
        }
        if (a != kNone || b != kNone) {
            m_edge[e] = a != kNone ? a : b;
            return true;
        }
        const std::optional<std::size_t> through = m_snap.pieceThrough(m_at[e], m_at[w]);
        if (!through)
            return false;
        m_edge[e] = *through;
        return true;
    }

    std::optional<Vec2> cornerPoint(std::size_t v, std::size_t in, std::size_t out) const
    {
        const Vec2 near = m_at[v];
        const double tol = m_snap.m_snapTolerance;
        if (m_raw.next(in) == out && fastDistance(piece(out).segment.start, near) <= tol)
            return piece(out).segment.start;
        const std::optional<Vec2> x = intersectCarriers(piece(in).segment, piece(out).segment, near);
        if (!x)
            return std::nullopt;
        // Where the pieces cross at a small angle, chords within the chord tolerance of them cross
        // further along: allow for that.
        const double sine = std::abs(tangentAt(piece(in), *x).cross(tangentAt(piece(out), *x)));
        const double allowed = tol + 2 * m_snap.m_chordTolerance / std::max(sine, 0.02);
        return fastDistance(*x, near) <= allowed ? x : std::nullopt;
    }

    bool walkFrom(std::size_t first)
    {
        std::size_t current = m_edge[first];
        Vec2 from = *m_corner[first];
        for (std::size_t i = 0; i < m_n; ++i) {
            const std::size_t e = (first + i) % m_n;
            if (m_walkTo[e] != kNone) {
                for (std::size_t k = current; k != m_walkTo[e]; k = m_raw.next(k)) {
                    if (!emit(k, from, piece(k).segment.end))
                        return false;
                    from = piece(k).segment.end;
                }
                current = m_walkTo[e];
            }
            const std::size_t w = (e + 1) % m_n;
            if (m_corner[w]) {
                if (!emit(current, from, *m_corner[w]))
                    return false;
                from = *m_corner[w];
                current = m_edge[w];
            }
        }
        return true;
    }

    // A contour that follows one loop of a single piece, a whole circle, all the way round.
    bool wholeLoop()
    {
        const std::size_t k = m_edge[0];
        const RawPiece& p = piece(k);
        const std::size_t loop = m_raw.loopOf(k);
        if (!p.segment.isArc() || m_raw.loopBegin[loop + 1] - m_raw.loopBegin[loop] != 1 ||
            std::abs(p.sweep) < kTwoPi - 1e-9)
            return false;
        const Vec2 middle = piecePoint(p, 0.5);
        push(Segment::arc(p.segment.start, middle, p.segment.center, p.segment.ccw));
        push(Segment::arc(middle, p.segment.start, p.segment.center, p.segment.ccw));
        return true;
    }

    // The run along piece k from a to b: false when it would run backwards or off the piece.
    bool emit(std::size_t k, Vec2 a, Vec2 b)
    {
        const RawPiece& p = piece(k);
        const double tol = m_snap.m_snapTolerance;
        if (!p.segment.isArc()) {
            const Vec2 d = p.segment.end - p.segment.start;
            const double length = fastLength(d);
            const double ta = (a - p.segment.start).dot(d) / length, tb = (b - p.segment.start).dot(d) / length;
            if (ta < -tol || tb > length + tol || tb < ta - tol)
                return false;
            if (fastDistance(a, b) >= kMinSegment)
                push(Segment::line(a, b));
            return true;
        }
        const double total = std::abs(p.sweep);
        const double slack = std::min(tol / p.radius, 0.25);
        auto along = [&](Vec2 q) {
            const double angle = angleAlongArc(p.segment, q);  // [0, 2 pi)
            return angle > total + slack && angle > 0.5 * (total + kTwoPi) ? angle - kTwoPi : angle;
        };
        const double sa = along(a);
        double sb = along(b);
        if (total >= kTwoPi - 1e-9) {
            // A whole circle has no start of its own: a run may pass the point it was drawn from.
            if (sb < sa - slack)
                sb += kTwoPi;
        } else if (sa < -slack || sb > total + slack || sb < sa - slack) {
            return false;
        }
        const double sweep = sb - sa;
        if (sweep * p.radius < kMinSegment)
            return true;
        if (sweep > kMaxArcSweep) {
            const Vec2 from = a - p.segment.center;
            const double angle = std::atan2(from.y, from.x) + (p.segment.ccw ? 0.5 : -0.5) * sweep;
            const Vec2 middle = p.segment.center + Vec2{std::cos(angle), std::sin(angle)} * p.radius;
            push(Segment::arc(a, middle, p.segment.center, p.segment.ccw));
            push(Segment::arc(middle, b, p.segment.center, p.segment.ccw));
            return true;
        }
        push(Segment::arc(a, b, p.segment.center, p.segment.ccw));
        return true;
    }

    void push(Segment s)
    {
        if (!m_out.segments.empty())
            s.start = m_out.segments.back().end;  // left-out runs are shorter than kMinSegment
        m_out.segments.push_back(s);
    }

    // The exact loop encloses about the contour's area (the contour's edges are chords within the
    // chord tolerance, its crossings within the snap tolerance): catches a run taken the wrong way.
    bool plausible() const
    {
        double twice = 0, perimeter = 0;
        for (std::size_t v = 0; v < m_n; ++v) {
            const Vec2 a = fromClipper(m_contour[v]), b = fromClipper(m_contour[(v + 1) % m_n]);
            twice += a.cross(b);
            perimeter += fastDistance(a, b);
        }
        const double area = m_out.signedArea();
        const double slack = perimeter * (m_snap.m_chordTolerance + m_snap.m_snapTolerance) + 1e-9;
        return (area > 0) == (twice > 0) && std::abs(area - 0.5 * twice) <= slack;
    }

    const PieceSnap& m_snap;
    const RawLoops& m_raw;
    const ClipperLib::Path& m_contour;
    const std::size_t m_n;
    std::vector<const PieceSnap::Origin*> m_origin;
    std::vector<Vec2> m_at;                     // exact where known, else Clipper's point
    std::vector<std::size_t> m_edge;            // piece each edge leaves its first vertex on
    std::vector<std::size_t> m_walkTo;          // piece it arrives on when it skips whole pieces
    std::vector<std::optional<Vec2>> m_corner;  // where the piece changes, at a vertex
    Profile m_out;
};

PieceSnap::PieceSnap(const RawLoops& raw, double chordTolerance) :
    m_raw(raw),
    m_snapTolerance(std::max(8 * chordTolerance, 1e-6)),
    m_chordTolerance(chordTolerance)
{
    m_index.reserve(raw.pieces.size() * 4);
    for (std::size_t loop = 0; loop + 1 < raw.loopBegin.size(); ++loop) {
        ClipperLib::Path& path = m_paths.emplace_back();
        const std::size_t end = raw.loopBegin[loop + 1];
        for (std::size_t k = raw.loopBegin[loop]; k < end; ++k) {
            const RawPiece& p = raw.pieces[k];
            const Segment& s = p.segment;
            const int chords = s.isArc() ? chordCount(p.radius, std::abs(p.sweep), chordTolerance) : 1;
            const double a0 = s.isArc() ? std::atan2(s.start.y - s.center.y, s.start.x - s.center.x) : 0;
            for (int i = 0; i < chords; ++i) {
                const double angle = a0 + p.sweep * i / chords;
                const Vec2 q = i == 0 ? s.start : s.center + Vec2{std::cos(angle), std::sin(angle)} * p.radius;
                if (!(std::abs(q.x) < kMaxCoordinate) || !(std::abs(q.y) < kMaxCoordinate)) {
                    m_inRange = false;
                    return;
                }
                const ClipperLib::IntPoint ip = toClipper(q);
                // Repeated grid points (the last one also against the loop's first) are left out.
                if (!path.empty() && (ip == path.back() || (k + 1 == end && ip == path.front())))
                    continue;
                path.push_back(ip);
                m_origins.push_back({k, i == 0, q});
                const auto [it, added] = m_index.try_emplace(Key{ip.X, ip.Y}, static_cast<int>(m_origins.size() - 1));
                if (!added)
                    it->second = -1;
            }
        }
    }
}

const PieceSnap::Origin* PieceSnap::origin(const ClipperLib::IntPoint& p) const
{
    const auto it = m_index.find(Key{p.X, p.Y});
    return it == m_index.end() || it->second < 0 ? nullptr : &m_origins[static_cast<std::size_t>(it->second)];
}

bool PieceSnap::onPiece(Vec2 p, std::size_t piece) const
{
    return distanceToSegment(p, m_raw.pieces[piece].segment) <= m_snapTolerance;
}

void PieceSnap::buildBands() const
{
    if (m_raw.pieces.empty())
        return;
    std::vector<Box> boxes;
    boxes.reserve(m_raw.pieces.size());
    for (const RawPiece& p : m_raw.pieces)
        boxes.push_back(boxOf(p.segment));
    m_minY = boxes.front().minY;
    double maxY = boxes.front().maxY;
    for (const Box& b : boxes) {
        m_minY = std::min(m_minY, b.minY);
        maxY = std::max(maxY, b.maxY);
    }
    const std::size_t count = std::clamp<std::size_t>(boxes.size() / 2, 1, 4096);
    m_bandHeight = std::max((maxY - m_minY) / static_cast<double>(count), 1e-9);
    m_bands.resize(count);
    for (std::size_t k = 0; k < boxes.size(); ++k)
        for (std::size_t b = band(boxes[k].minY - m_snapTolerance); b <= band(boxes[k].maxY + m_snapTolerance); ++b)
            m_bands[b].push_back(k);
}

std::size_t PieceSnap::band(double y) const
{
    const double b = std::floor((y - m_minY) / m_bandHeight);
    return static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(m_bands.size() - 1)));
}

std::optional<std::size_t> PieceSnap::pieceThrough(Vec2 a, Vec2 b) const
{
    if (m_bands.empty())
        buildBands();
    std::optional<std::size_t> best;
    double bestSum = std::numeric_limits<double>::infinity();
    if (m_bands.empty())
        return best;
    for (const std::size_t k : m_bands[band(a.y)]) {
        const Segment& s = m_raw.pieces[k].segment;
        const double da = distanceToSegment(a, s);
        if (da > m_snapTolerance)
            continue;
        const double db = distanceToSegment(b, s);
        if (db <= m_snapTolerance && da + db < bestSum) {
            best = k;
            bestSum = da + db;
        }
    }
    return best;
}

std::optional<Profile> PieceSnap::snap(const ClipperLib::Path& contour) const
{
    return ContourWalk(*this, contour).run();
}

}  // namespace camwb::geom::detail
