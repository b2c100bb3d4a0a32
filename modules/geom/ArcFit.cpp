#include "geom/ArcFit.h"

#include "geom/detail/LoopQueries.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace camwb::geom {

namespace {

using detail::fastDistance;
using detail::fastLength;

// Arcs longer than this are split: a full circle gives two arcs instead of one arc and a short
// closing chord, and no fitted arc comes near start == end.
constexpr double kMaxArcSweep = 1.5 * std::numbers::pi;

// A fitted piece covering polyline vertices [from, to] (indices into the fitter's point array).
struct Piece {
    Segment segment;
    std::size_t from = 0;
    std::size_t to = 0;
};

double distanceToChord(Vec2 p, Vec2 a, Vec2 d, double len2)
{
    if (len2 <= 0)
        return fastDistance(p, a);
    const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
    return fastDistance(p, a + d * t);
}

// Greedy cover of v[0..last] by lines and arcs. Runs are found by growing the run length
// exponentially and then bisecting, so a polyline of n points costs O(n log n) fit checks.
class Fitter {
public:
    Fitter(std::vector<Vec2> points, double tolerance, double maxArcRadius) :
        m_v(std::move(points)),
        m_tol(tolerance),
        m_maxRadius(maxArcRadius)
    {
    }

    const std::vector<Vec2>& points() const { return m_v; }

    bool lineFits(std::size_t i, std::size_t j) const
    {
        const Vec2 a = m_v[i];
        const Vec2 d = m_v[j] - a;
        const double len2 = d.dot(d);
        for (std::size_t k = i + 1; k < j; ++k)
            if (distanceToChord(m_v[k], a, d, len2) > m_tol)
                return false;
        return true;
    }

    // The arc through v[i], v[(i+j)/2] and v[j] when every vertex and edge in between is within
    // tolerance of it and the points advance monotonically along it.
    std::optional<Segment> arcFit(std::size_t i, std::size_t j) const
    {
        if (j < i + 2)
            return std::nullopt;
        const Vec2 a = m_v[i];
        const Vec2 ab = m_v[(i + j) / 2] - a;
        const Vec2 ac = m_v[j] - a;
        const double d = 2 * ab.cross(ac);
        const double ab2 = ab.dot(ab), ac2 = ac.dot(ac);
        if (std::abs(d) <= 1e-300)
            return std::nullopt;
        const Vec2 c = a + Vec2{(ac.y * ab2 - ab.y * ac2) / d, (ab.x * ac2 - ac.x * ab2) / d};
        const double r = fastDistance(a, c);
        if (!(r < m_maxRadius) || !std::isfinite(r))
            return std::nullopt;
        const bool ccw = d > 0;
        const double dir = ccw ? 1.0 : -1.0;
        const double backtrack = -m_tol / r;
        double swept = 0;
        Vec2 prev = a - c;
        for (std::size_t k = i + 1; k <= j; ++k) {
            const Vec2 u = m_v[k] - c;
            if (std::abs(fastLength(u) - r) > m_tol)
                return std::nullopt;
            // The whole edge within the band r +- tol (its ends are checked as vertices; its
            // point nearest the centre here): then the arc and the edge stay within tol of
            // each other, which an edge-midpoint check alone does not guarantee.
            if (distanceToChord(Vec2{}, prev, u - prev, (u - prev).dot(u - prev)) < r - m_tol)
                return std::nullopt;
            const double step = dir * std::atan2(prev.cross(u), prev.dot(u));
            if (step < backtrack)
                return std::nullopt;
            swept += step;
            if (swept > kMaxArcSweep)
                return std::nullopt;
            prev = u;
        }
        if (swept <= 0)
            return std::nullopt;
        return Segment::arc(a, m_v[j], c, ccw);
    }

    // Largest j in [i+1, last] with lineFits(i, j) (assuming fits are monotone in j).
    std::size_t longestLine(std::size_t i, std::size_t last) const
    {
        return longestRun(i, last, i + 1, [this](std::size_t a, std::size_t b) { return lineFits(a, b); });
    }

    std::size_t longestArc(std::size_t i, std::size_t last) const
    {
        if (i + 2 > last || !arcFit(i, i + 2))
            return i;
        return longestRun(i, last, i + 2, [this](std::size_t a, std::size_t b) { return arcFit(a, b).has_value(); });
    }

    std::vector<Piece> cover(std::size_t last) const
    {
        std::vector<Piece> pieces;
        std::size_t i = 0;
        while (i < last) {
            const std::size_t lineEnd = longestLine(i, last);
            const std::size_t arcEnd = longestArc(i, last);
            if (arcEnd > lineEnd) {
                pieces.push_back({*arcFit(i, arcEnd), i, arcEnd});
                i = arcEnd;
            } else {
                pieces.push_back({Segment::line(m_v[i], m_v[lineEnd]), i, lineEnd});
                i = lineEnd;
            }
        }
        return pieces;
    }

    // One piece covering [i, j] when a line (preferred) or an arc fits it.
    std::optional<Segment> fitRun(std::size_t i, std::size_t j) const
    {
        if (lineFits(i, j))
            return Segment::line(m_v[i], m_v[j]);
        return arcFit(i, j);
    }

private:
    template <class Fits> std::size_t longestRun(std::size_t i, std::size_t last, std::size_t good, Fits fits) const
    {
        std::size_t length = 2 * (good - i);
        while (good < last) {
            const std::size_t j = std::min(i + length, last);
            if (!fits(i, j)) {
                std::size_t bad = j;
                while (bad - good > 1) {
                    const std::size_t mid = good + (bad - good) / 2;
                    (fits(i, mid) ? good : bad) = mid;
                }
                return good;
            }
            good = j;
            length *= 2;
        }
        return good;
    }

    std::vector<Vec2> m_v;
    double m_tol;
    double m_maxRadius;
};

std::vector<Vec2> withoutRepeats(const std::vector<Vec2>& points, bool closed)
{
    std::vector<Vec2> out;
    out.reserve(points.size());
    for (const Vec2& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            continue;
        if (out.empty() || fastDistance(out.back(), p) > 1e-12)
            out.push_back(p);
    }
    while (closed && out.size() > 1 && fastDistance(out.front(), out.back()) <= 1e-12)
        out.pop_back();
    return out;
}

// The vertex where the direction turns most: a real corner if the loop has one, so the seam
// between the first and the last fitted piece falls where a segment boundary belongs anyway.
std::size_t sharpestCorner(const std::vector<Vec2>& v)
{
    const std::size_t n = v.size();
    std::size_t best = 0;
    double bestTurn = -1;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 in = v[k] - v[(k + n - 1) % n];
        const Vec2 out = v[(k + 1) % n] - v[k];
        const double turn = std::atan2(std::abs(in.cross(out)), in.dot(out));
        if (turn > bestTurn + 1e-12) {
            bestTurn = turn;
            best = k;
        }
    }
    return best;
}

Profile toProfile(const std::vector<Piece>& pieces, bool closed)
{
    Profile profile;
    profile.closed = closed;
    profile.segments.reserve(pieces.size());
    for (const Piece& piece : pieces)
        profile.segments.push_back(piece.segment);
    return profile;
}

}  // namespace

Profile fitLinesAndArcs(const std::vector<Vec2>& points, bool closed, double tolerance, double maxArcRadius)
{
    const double tol = tolerance >= 1e-9 ? tolerance : 1e-9;  // NaN too
    std::vector<Vec2> v = withoutRepeats(points, closed);
    if (v.size() < 2)
        return Profile{{}, closed};
    if (!closed) {
        const std::size_t last = v.size() - 1;
        return toProfile(Fitter(std::move(v), tol, maxArcRadius).cover(last), false);
    }

    // Closed: start at the sharpest corner and lay the loop out twice (plus the closing point) so
    // that runs across the seam can be checked with plain indices.
    const std::size_t n = v.size();
    std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(sharpestCorner(v)), v.end());
    std::vector<Vec2> twice;
    twice.reserve(2 * n + 1);
    for (int round = 0; round < 2; ++round)
        twice.insert(twice.end(), v.begin(), v.end());
    twice.push_back(v.front());
    const Fitter fitter(std::move(twice), tol, maxArcRadius);
    std::vector<Piece> pieces = fitter.cover(n);

    // Where the start vertex lies inside a smooth run (a loop without corners), the first and
    // last pieces belong together: merge them while one line or arc still fits both.
    while (pieces.size() >= 3) {
        const std::size_t from = pieces.back().from;
        const std::size_t to = n + pieces.front().to;
        const std::optional<Segment> merged = fitter.fitRun(from, to);
        if (!merged)
            break;
        pieces.back() = {*merged, from, to};
        pieces.erase(pieces.begin());
    }
    return toProfile(pieces, true);
}

}  // namespace camwb::geom
