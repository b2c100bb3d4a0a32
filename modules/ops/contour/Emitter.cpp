#include "ops/contour/Emitter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::ops::contour {

namespace {
constexpr double kZTol = 1e-9;
}  // namespace

bool Tabs::contains(double s) const
{
    if (pathLength > 0)
        s = std::fmod(std::fmod(s, pathLength) + pathLength, pathLength);
    for (const auto& [a, b] : spans)
        for (double shift : {-pathLength, 0.0, pathLength})
            if (s + shift > a && s + shift < b)
                return true;
    return false;
}

void Emitter::add(toolpath::Record record) { m_toolpath.add(std::move(record), {m_operationIndex, m_index++}); }

void Emitter::rapid(Vec3 to)
{
    add(toolpath::Rapid{to});
    m_position = to;
}

void Emitter::linear(Vec3 to, Feed feed)
{
    if (distance(to, m_position) < 1e-12)
        return;
    add(feedMove(to, feed));
    m_position = to;
}

void Emitter::piece(const Segment& s, double z1, Feed feed)
{
    if (!s.isArc()) {
        linear({s.end.x, s.end.y, z1}, feed);
        return;
    }
    // Half a turn at most per record: a full circle would have its end on its start, and posts
    // writing the radius form cannot tell the long way round from the short.
    if (std::abs(s.sweep()) > std::numbers::pi + 1e-9) {
        const double z0 = m_position.z;
        const Vec2 mid = s.pointAt(0.5);
        arc(Segment::arc(s.start, mid, s.center, s.ccw), 0.5 * (z0 + z1), feed);
        arc(Segment::arc(mid, s.end, s.center, s.ccw), z1, feed);
        return;
    }
    arc(s, z1, feed);
}

void Emitter::arc(const Segment& s, double z1, Feed feed)
{
    toolpath::Arc a;
    a.to = {s.end.x, s.end.y, z1};
    a.center = {s.center.x, s.center.y, m_position.z};  // in the start's plane
    a.normal = {0, 0, 1};
    a.clockwise = !s.ccw;
    a.feedMmPerMin = feed.mmPerMin;
    a.feedKind = feed.kind;
    add(a);
    m_position = a.to;
}

void cutAlong(Emitter& out, const Path& path, double from, double to, double zFrom, double zTo, const Tabs* tabs,
              const Feeds& feeds)
{
    const double L = path.length();
    const bool backwards = to < from;
    // Work forwards on the reversed path when running backwards.
    const Path walked = backwards ? Path{geom::Profile{path.segments, path.closed}.reversed().segments, path.closed,
                                         !path.materialOnRight}
                                  : path;
    const double a0 = backwards ? L - from : from;
    const double a1 = backwards ? L - to : to;
    auto onPath = [&](double s) { return backwards ? L - s : s; };  // walked -> path arclength
    auto zLin = [&](double s) { return a1 > a0 ? zFrom + (zTo - zFrom) * (s - a0) / (a1 - a0) : zTo; };
    const bool tabbed = tabs && !tabs->spans.empty() && std::min(zFrom, zTo) < tabs->topZ - kZTol;

    std::vector<double> cuts{a0, a1};
    const int wraps = L > 0 ? static_cast<int>(std::floor(a1 / L)) : 0;
    for (int k = 0; k <= wraps; ++k) {
        double at = k * L;
        for (const Segment& s : walked.segments) {
            cuts.push_back(at);
            at += s.length();
        }
        if (tabbed)
            for (const auto& [sa, sb] : tabs->spans)
                for (double e : {sa, sb})
                    for (double shift : {-L, 0.0, L}) {
                        const double onWalked = backwards ? L - (e + shift) : e + shift;
                        cuts.push_back(onWalked + k * L);
                    }
    }
    if (tabbed && std::abs(zTo - zFrom) > kZTol)
        cuts.push_back(a0 + (a1 - a0) * (tabs->topZ - zFrom) / (zTo - zFrom));
    std::sort(cuts.begin(), cuts.end());

    auto zAt = [&](double s, bool inTab) { return inTab ? std::max(zLin(s), tabs->topZ) : zLin(s); };
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = std::max(cuts[i], a0), b = std::min(cuts[i + 1], a1);
        if (b - a < 1e-9)
            continue;
        const bool inTab = tabbed && tabs->contains(onPath(0.5 * (a + b)));
        const double za = zAt(a, inTab), zb = zAt(b, inTab);
        if (std::abs(out.position().z - za) > kZTol)
            out.vertical(za, za > out.position().z ? feeds.cut : feeds.plunge);
        // The span lies on one lap: fold it back into [0, L].
        const double lap = L > 0 ? std::floor((0.5 * (a + b)) / L) * L : 0;
        // Segment ends are among the cuts, so this is one piece (more only through rounding).
        const std::vector<Segment> pieces = piecesBetween(walked, a - lap, b - lap);
        const bool sloped = std::abs(zb - za) > kZTol;
        double done = a;
        for (const Segment& s : pieces) {
            done += s.length();
            out.piece(s, &s == &pieces.back() ? zb : zAt(done, inTab), sloped ? feeds.ramp : feeds.cut);
        }
    }
    if (std::abs(out.position().z - zTo) > kZTol)
        out.vertical(zTo, zTo > out.position().z ? feeds.cut : feeds.plunge);
}

}  // namespace camwb::ops::contour
