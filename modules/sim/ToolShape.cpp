#include "sim/ToolShape.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace camwb::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Typical holders (collet nut diameter and length, then the body to the gauge line), from the
// catalogue figures of the common makers rounded to whole millimetres. A holder's real shape
// belongs in the tool library; this table only makes a holder-too-short check possible at all.
struct HolderRow {
    const char* name;
    std::vector<HolderStep> steps;
};
const std::vector<HolderRow>& holderTable()
{
    static const std::vector<HolderRow> rows = {
        {"er11", {{19, 20}, {25, 30}}},           {"er16", {{28, 25}, {32, 35}}},
        {"er20", {{34, 25}, {40, 40}}},           {"er25", {{42, 30}, {45, 40}}},
        {"er32", {{50, 35}, {50, 35}}},           {"er40", {{63, 40}, {63, 40}}},
        {"sk40 er16", {{28, 25}, {32, 45}}},      {"sk40 er32", {{50, 35}, {50, 35}}},
        {"sk40 er40", {{63, 40}, {63, 40}}},      {"hsk63 er16", {{28, 25}, {32, 75}}},
        {"hsk63 er32", {{50, 35}, {50, 65}}},     {"bt40 er32", {{50, 35}, {50, 35}}},
        {"sk40 weldon 12", {{42, 60}, {50, 20}}}, {"hsk63 shrink 12", {{24, 50}, {32, 50}}},
    };
    return rows;
}

// Roots of a s^2 + b s + c <= 0 as the interval(s) between/outside them.
struct Quadratic {
    int count = 0;  // 0: nowhere or everywhere (see all), 1: [lo, hi], 2: (-inf, lo] and [hi, inf)
    bool all = false;
    double lo = 0, hi = 0;
};
Quadratic solveAtMostZero(double a, double b, double c)
{
    Quadratic q;
    if (std::abs(a) < 1e-14) {
        if (std::abs(b) < 1e-14) {
            q.all = c <= 0;
            return q;
        }
        q.count = 1;
        q.lo = b > 0 ? -kInf : -c / b;
        q.hi = b > 0 ? -c / b : kInf;
        return q;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) {
        q.all = a < 0;
        return q;
    }
    const double root = std::sqrt(disc);
    // The stable pair of roots (no cancellation when b dominates).
    const double t = -0.5 * (b + std::copysign(root, b));
    double r1 = t / a, r2 = t != 0 ? c / t : r1;
    if (r1 > r2)
        std::swap(r1, r2);
    q.count = a > 0 ? 1 : 2;
    q.lo = r1;
    q.hi = r2;
    return q;
}

// The s where h0 + s * dh lies in [lo, hi].
LineSpan heightRange(double h0, double dh, double lo, double hi)
{
    if (std::abs(dh) < 1e-14)
        return h0 >= lo && h0 <= hi ? LineSpan{-kInf, kInf} : LineSpan{};
    double a = (lo - h0) / dh, b = (hi - h0) / dh;
    if (a > b)
        std::swap(a, b);
    return {a, b};
}

LineSpan meet(LineSpan a, LineSpan b) { return {std::max(a.s0, b.s0), std::min(a.s1, b.s1)}; }

LineSpan hull(LineSpan a, LineSpan b)
{
    if (a.empty())
        return b;
    if (b.empty())
        return a;
    return {std::min(a.s0, b.s0), std::max(a.s1, b.s1)};
}

// The part of `q` (the solution of a quadratic <= 0) inside `range`.
LineSpan clip(const Quadratic& q, LineSpan range)
{
    if (q.all)
        return range;
    if (q.count == 1)
        return meet({q.lo, q.hi}, range);
    if (q.count == 2)
        return hull(meet({-kInf, q.lo}, range), meet({q.hi, kInf}, range));
    return {};
}

}  // namespace

double HolderShape::lengthMm() const
{
    double sum = 0;
    for (const HolderStep& s : steps)
        sum += s.lengthMm;
    return sum;
}

HolderShape holderShape(const std::string& name)
{
    const std::string key = lower(name);
    const auto& rows = holderTable();
    auto found = std::find_if(rows.begin(), rows.end(), [&](const HolderRow& r) { return key == r.name; });
    if (found == rows.end()) {  // "SK50 ER25 long" still has an ER25 nut
        found = std::find_if(rows.begin(), rows.end(), [&](const HolderRow& r) {
            const std::string n = r.name;
            return n.rfind("er", 0) == 0 && key.find(n) != std::string::npos;
        });
    }
    if (found != rows.end())
        return {name, found->steps, true};
    return {name, {{50, 35}, {50, 35}}, false};  // the default: an ER32 nut, 70 mm to the gauge line
}

ToolShape::ToolShape(const toolpath::Tool& tool) : m_tool(tool), m_holder(holderShape(tool.holder))
{
    m_radius = std::max(0.0, tool.diameterMm / 2);
    const std::string kind = lower(tool.kind);
    const bool pointed = tool.pointAngleDeg > 0 && tool.pointAngleDeg < 180;
    if (kind == "ball")
        m_corner = m_radius;
    else if ((kind == "drill" || kind == "chamfer") && pointed)
        m_coneSlope = std::tan(tool.pointAngleDeg / 2 * kPi / 180);
    else if (kind == "bull" || (kind != "flat" && !pointed))
        m_corner = std::clamp(tool.cornerRadiusMm, 0.0, m_radius);
    // Without a flute length the whole stick-out cuts (nothing to call shank); without a length the
    // stick-out is three diameters, a common default for holders' gauge tables.
    m_flute = tool.fluteLengthMm > 0 ? tool.fluteLengthMm : tool.lengthMm > 0 ? tool.lengthMm : 3 * tool.diameterMm;
    m_stickOut = tool.lengthMm > 0 ? std::max(tool.lengthMm, m_flute) : std::max(m_flute, 3 * tool.diameterMm);
    m_shankRadius = m_radius;

    if (m_coneSlope > 0) {
        const double pointHeight = std::min(m_radius / m_coneSlope, m_flute);
        m_cutter.push_back({Piece::Cone, m_coneSlope, 0, pointHeight});
        if (pointHeight < m_flute)
            m_cutter.push_back({Piece::Cylinder, m_radius, pointHeight, m_flute});
    } else if (m_corner > 0 && m_corner >= m_radius - 1e-12) {
        m_cutter.push_back({Piece::Sphere, m_radius, m_radius, m_flute});
        if (m_radius < m_flute)
            m_cutter.push_back({Piece::Cylinder, m_radius, m_radius, m_flute});
    } else if (m_corner > 0) {
        m_cutter.push_back({Piece::Corner, m_corner, 0, std::min(m_corner, m_flute), m_radius - m_corner});
        m_cutter.push_back({Piece::Cylinder, m_radius - m_corner, 0, m_flute});
        if (m_corner < m_flute)
            m_cutter.push_back({Piece::Cylinder, m_radius, m_corner, m_flute});
    } else {
        m_cutter.push_back({Piece::Cylinder, m_radius, 0, m_flute});
    }
    if (m_stickOut > m_flute)
        m_shank.push_back({Piece::Cylinder, m_shankRadius, m_flute, m_stickOut});
    double h = m_stickOut;
    for (const HolderStep& s : m_holder.steps) {
        m_holderPieces.push_back({Piece::Cylinder, s.diameterMm / 2, h, h + s.lengthMm});
        h += s.lengthMm;
    }
}

double ToolShape::holderRadiusMm() const
{
    double r = 0;
    for (const HolderStep& s : m_holder.steps)
        r = std::max(r, s.diameterMm / 2);
    return r;
}

double ToolShape::totalLengthMm() const { return m_stickOut + m_holder.lengthMm(); }

double ToolShape::boundingRadiusMm() const { return std::max({m_radius, m_shankRadius, holderRadiusMm()}); }

double ToolShape::lowerSurface(double d) const
{
    if (d > m_radius + 1e-12)
        return kInf;
    if (m_coneSlope > 0)
        return d / m_coneSlope;
    const double flatRadius = m_radius - m_corner;
    if (d <= flatRadius)
        return 0;
    const double off = d - flatRadius;
    return m_corner - std::sqrt(std::max(0.0, m_corner * m_corner - off * off));
}

double ToolShape::profileRadius(double h) const
{
    if (h < 0)
        return 0;
    if (h <= m_flute) {
        if (m_coneSlope > 0)
            return std::min(m_radius, h * m_coneSlope);
        if (h >= m_corner)
            return m_radius;
        const double up = m_corner - h;
        return m_radius - m_corner + std::sqrt(std::max(0.0, m_corner * m_corner - up * up));
    }
    if (h <= m_stickOut)
        return m_shankRadius;
    for (const Piece& p : m_holderPieces)
        if (h <= p.h1)
            return p.radius;
    return 0;
}

LineSpan ToolShape::intersect(ToolPart part, const Vec3& tip, const Vec3& axis, const Vec3& origin,
                              const Vec3& dir) const
{
    // The line in the tool's frame: height h0 + s * dh along the axis, offset perp0 + s * perpD.
    const Vec3 w = origin - tip;
    const double h0 = w.dot(axis), dh = dir.dot(axis);
    const Vec3 perp0 = w - axis * h0, perpD = dir - axis * dh;
    const std::vector<Piece>& pieces = part == ToolPart::Cutter  ? m_cutter
                                       : part == ToolPart::Shank ? m_shank
                                                                 : m_holderPieces;
    LineSpan span;
    for (const Piece& p : pieces)
        span = hull(span, pieceSpan(p, h0, dh, perp0, perpD));
    return span;
}

LineSpan ToolShape::pieceSpan(const Piece& p, double h0, double dh, const Vec3& perp0, const Vec3& perpD) const
{
    const double a = perpD.dot(perpD), b = 2 * perp0.dot(perpD), c = perp0.dot(perp0);
    switch (p.kind) {
    case Piece::Cylinder:
        return clip(solveAtMostZero(a, b, c - p.radius * p.radius), heightRange(h0, dh, p.h0, p.h1));
    case Piece::Sphere: {
        const double hc = h0 - p.h0;  // height over the centre
        return clip(solveAtMostZero(a + dh * dh, b + 2 * hc * dh, c + hc * hc - p.radius * p.radius),
                    heightRange(h0, dh, -kInf, p.h1));
    }
    case Piece::Cone: {  // rho <= k h over h >= 0: a convex cone, so one span survives the clip
        const double k2 = p.radius * p.radius;
        return clip(solveAtMostZero(a - k2 * dh * dh, b - 2 * k2 * h0 * dh, c - k2 * h0 * h0),
                    heightRange(h0, dh, 0, p.h1));
    }
    case Piece::Corner:
        return cornerSpan(p, h0, dh, perp0, perpD);
    }
    return {};
}

// The bull-nose corner: rho <= inner + radius, h between the torus' lower surface and the top of
// the tube. A torus meets a line in a quartic; instead F(s) = lower(rho(s)) - h(s) is convex
// (lower is convex and non-decreasing in rho, rho(s) convex), so its minimum is found by golden
// section and the two ends of {F <= 0} by bisection, to well under a micrometre.
LineSpan ToolShape::cornerSpan(const Piece& p, double h0, double dh, const Vec3& perp0, const Vec3& perpD) const
{
    const double outer = p.inner + p.radius;
    const double a = perpD.dot(perpD), b = 2 * perp0.dot(perpD), c = perp0.dot(perp0);
    const LineSpan domain = clip(solveAtMostZero(a, b, c - outer * outer), heightRange(h0, dh, -kInf, p.h1));
    if (domain.empty())
        return {};
    auto lowerAt = [&](double rho) {
        const double off = std::max(0.0, rho - p.inner);
        return p.radius - std::sqrt(std::max(0.0, p.radius * p.radius - off * off));
    };
    if (!std::isfinite(domain.s0) || !std::isfinite(domain.s1))  // along the axis: rho is constant
        return meet(domain, heightRange(h0, dh, lowerAt(std::sqrt(c)), p.h1));
    auto f = [&](double s) { return lowerAt(std::sqrt(std::max(0.0, (a * s + b) * s + c))) - (h0 + s * dh); };
    constexpr double g = 0.6180339887498949;
    double lo = domain.s0, hi = domain.s1;
    for (int i = 0; i < 60 && hi - lo > 1e-9; ++i) {
        const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
        if (f(m1) < f(m2))
            hi = m2;
        else
            lo = m1;
    }
    const double best = (lo + hi) / 2;
    if (f(best) > 0)
        return {};
    auto edge = [&](double inside, double outside) {
        if (f(outside) <= 0)
            return outside;
        for (int i = 0; i < 50 && std::abs(outside - inside) > 1e-9; ++i) {
            const double m = (inside + outside) / 2;
            (f(m) <= 0 ? inside : outside) = m;
        }
        return inside;
    };
    return {edge(best, domain.s0), edge(best, domain.s1)};
}

}  // namespace camwb::sim
