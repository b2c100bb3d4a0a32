#include "ops/surface/BallReach.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops::surface {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A support line of the reach: the largest u.q over it and the point q where it is reached.
struct Support {
    double h = -std::numeric_limits<double>::infinity();
    base::Vec2 at;
    base::Vec2 u;  // its direction (kept: the corners ask it again, and sin and cos cost)
};

// Along the edge a-b the support in direction u is the largest u.p_xy + sqrt(r^2 - (p_z - zc)^2):
// a concave function of the edge parameter, so its best point is an end or where its derivative
// vanishes, da = b db / sqrt(r^2 - b^2) with b the height off the centre. A point out of reach
// counts as if just within it (the root taken as 0): larger, so on the safe side. Growing the
// reach by `grow` all round adds it to every support (the sum with a disc).
void edgeSupport(base::Vec2 u, const base::Vec3& a, const base::Vec3& b, double zc, double r, double grow,
                 Support& best)
{
    const double da = u.x * (b.x - a.x) + u.y * (b.y - a.y), b0 = a.z - zc, db = b.z - a.z;
    const auto at = [&](double t) {
        const double h = b0 + db * t, w = std::sqrt(std::max(r * r - h * h, 0.0)) + grow;
        const base::Vec2 q{a.x + (b.x - a.x) * t + u.x * w, a.y + (b.y - a.y) * t + u.y * w};
        const double value = u.x * q.x + u.y * q.y;
        if (value > best.h)
            best.h = value, best.at = q;
    };
    at(0);
    at(1);
    if (std::abs(db) > 1e-15) {
        const double k = da / db, t = (k * r / std::sqrt(1 + k * k) - b0) / db;
        if (t > 0 && t < 1)
            at(t);
    }
}

struct Reach {
    const std::vector<base::Vec3>& piece;
    double zc, r, grow, chord;

    Support support(double angle) const
    {
        const base::Vec2 u{std::cos(angle), std::sin(angle)};
        Support best;
        best.u = u;
        for (std::size_t i = 0; i < piece.size(); ++i)
            edgeSupport(u, piece[i], piece[(i + 1) % piece.size()], zc, r, grow, best);
        return best;
    }

    // The corner where the support lines at angles a0 < a1 (less than pi apart) meet; refined
    // until it stands within the chord of the segment between their touching points, between
    // which the reach's boundary runs (convex), so that the corners stay within the chord of it.
    void corners(double a0, const Support& s0, double a1, const Support& s1, int depth,
                 std::vector<base::Vec2>& out) const
    {
        const base::Vec2 u0 = s0.u, u1 = s1.u;
        const double det = u0.x * u1.y - u0.y * u1.x;
        const base::Vec2 c{(s0.h * u1.y - s1.h * u0.y) / det, (s1.h * u0.x - s0.h * u1.x) / det};
        const base::Vec2 d{s1.at.x - s0.at.x, s1.at.y - s0.at.y};
        const double len = std::hypot(d.x, d.y);
        const double off = len > 1e-12 ? std::abs(d.x * (c.y - s0.at.y) - d.y * (c.x - s0.at.x)) / len
                                       : std::hypot(c.x - s0.at.x, c.y - s0.at.y);
        if (off <= chord || depth == 0) {
            out.push_back(c);
            return;
        }
        const double am = (a0 + a1) / 2;
        const Support sm = support(am);
        corners(a0, s0, am, sm, depth - 1, out);
        corners(am, sm, a1, s1, depth - 1, out);
    }
};

}  // namespace

std::vector<base::Vec2> ballReach(const std::vector<base::Vec3>& piece, double zc, double radius, double grow,
                                  double chord)
{
    std::vector<base::Vec2> out;
    if (piece.size() < 3 || !(radius > 0))
        return out;
    double lo = piece[0].z, hi = piece[0].z;
    for (const base::Vec3& p : piece)
        lo = std::min(lo, p.z), hi = std::max(hi, p.z);
    if (lo > zc + radius || hi < zc - radius)
        return out;
    // Eight support lines to start with, each gap refined where the boundary between them bends
    // away from the corner (a round end needs about pi sqrt(r / chord) lines, a straight side one).
    const Reach reach{piece, zc, radius, std::max(grow, 0.0), std::max(chord, 1e-6)};
    constexpr int kStart = 8;
    std::vector<Support> s(kStart + 1);
    for (int k = 0; k < kStart; ++k)
        s[k] = reach.support(2 * kPi * k / kStart);
    s[kStart] = s[0];
    s[kStart].u = {std::cos(2 * kPi), std::sin(2 * kPi)};  // as the angle gives it, to the last bit
    for (int k = 0; k < kStart; ++k)
        reach.corners(2 * kPi * k / kStart, s[k], 2 * kPi * (k + 1) / kStart, s[k + 1], 12, out);
    return out;
}

}  // namespace camwb::ops::surface
