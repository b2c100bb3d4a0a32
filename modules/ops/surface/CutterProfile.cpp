#include "ops/surface/CutterProfile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace camwb::ops::surface {

double CutterProfile::Piece::at(double d) const
{
    if (kind == Line)
        return z0 + slope * (d - d0);
    const double off = d - cd;
    return cz - std::sqrt(std::max(0.0, r * r - off * off));
}

CutterProfile::CutterProfile(const sim::ToolShape& shape, double stockMm)
{
    const double R = shape.radiusMm(), s = std::max(0.0, stockMm);
    m_radius = R + s;
    m_lowest = -s;
    if (shape.coneSlope() > 0) {
        // The point z = d / k; grown: an arc round the tip, the cone line moved out along its
        // normal, an arc round the rim.
        const double k = shape.coneSlope(), n = std::sqrt(1 + k * k);
        if (s == 0) {
            add({Piece::Line, 0, R, 0, 1 / k});
            return;
        }
        add({Piece::Arc, 0, s / n, 0, 0, 0, 0, s});
        add({Piece::Line, s / n, R + s / n, (s / n) / k - s * n / k, 1 / k});
        add({Piece::Arc, R + s / n, R + s, 0, 0, R, R / k, s});
        return;
    }
    // Flat, ball and bull-nose: a flat of radius R - c and the corner arc of radius c, both grown.
    const double c = shape.cornerRadiusMm(), flat = R - c;
    if (flat > 0 || c + s == 0)
        add({Piece::Line, 0, c + s == 0 ? R : flat, -s, 0});
    if (c + s > 0)
        add({Piece::Arc, std::max(0.0, flat), m_radius, 0, 0, std::max(0.0, flat), c, c + s});
}

double CutterProfile::height(double d) const
{
    if (d > m_radius)
        return std::numeric_limits<double>::infinity();
    for (int i = 0; i < m_count; ++i)
        if (d <= m_pieces[i].d1 || i + 1 == m_count)
            return m_pieces[i].at(std::max(d, m_pieces[i].d0));
    return std::numeric_limits<double>::infinity();
}

double CutterProfile::planeContact(double slope) const
{
    // slope * d - height(d) is concave; each piece's best is an end or where the arc's slope is the
    // plane's, and the best of those is the piece-wise maximum.
    double bestD = 0, best = -std::numeric_limits<double>::infinity();
    auto consider = [&](double d) {
        const double v = slope * d - height(d);
        if (v > best)
            best = v, bestD = d;
    };
    for (int i = 0; i < m_count; ++i) {
        const Piece& p = m_pieces[i];
        consider(p.d0);
        consider(p.d1);
        if (p.kind == Piece::Arc)
            consider(std::clamp(p.cd + p.r * slope / std::sqrt(1 + slope * slope), p.d0, p.d1));
    }
    return bestD;
}

}  // namespace camwb::ops::surface
