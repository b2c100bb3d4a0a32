// Shared by the contour tests: tools, parameters, generated shapes and a walk over the CL records
// that samples every cutting move exactly (arcs and helices by angle) for the property checks.
#pragma once

#include "../../geom/GeomTestUtil.h"
#include "ops/ContourOp.h"
#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace camwb::ops::test {

using base::Vec2;
using base::Vec3;
using geom::Profile;
using geom::Segment;

inline ToolController tool(double diameter = 10)
{
    ToolController tc;
    tc.tool.number = 2;
    tc.tool.name = "Flat";
    tc.tool.diameterMm = diameter;
    tc.spindleRpm = 10000;
    tc.cuttingFeedMmPerMin = 1200;
    tc.plungeFeedMmPerMin = 300;
    tc.rampFeedMmPerMin = 600;
    return tc;
}

inline ContourParams params(ContourSide side = ContourSide::Outside, bool climb = true)
{
    ContourParams p;
    p.name = "Outer contour";
    p.side = side;
    p.climb = climb;
    p.heights = {15, 2, 0, -3};
    return p;
}

// A cutting move sampled from its start: points with Z, and what it was.
struct Move {
    std::size_t record = 0;
    bool rapid = false, arc = false, helix = false;
    Vec3 from, to;
    double feed = 0;
    std::vector<Vec3> points;  // from .. to inclusive
    double lengthXY = 0;
};

// Sweep (signed, ccw positive) of an arc record from `from`; a whole turn when it ends where it starts.
inline double arcSweep(const Vec3& from, const toolpath::Arc& a)
{
    const Vec2 u = from.xy() - a.center.xy(), v = a.to.xy() - a.center.xy();
    double angle = std::atan2(u.cross(v), u.dot(v));
    if (!a.clockwise && angle <= 1e-12)
        angle += 2 * std::numbers::pi;
    if (a.clockwise && angle >= -1e-12)
        angle -= 2 * std::numbers::pi;
    return angle + (a.clockwise ? -1 : 1) * 2 * std::numbers::pi * a.turns;
}

// Every motion record of a toolpath with its samples (about every 0.1 mm, at least 16).
inline std::vector<Move> walk(const toolpath::Toolpath& tp)
{
    std::vector<Move> moves;
    Vec3 pos;
    bool known = false;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const toolpath::Record& r = tp.record(i);
        Move m;
        m.record = i;
        m.from = pos;
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            m.rapid = true;
            m.to = rapid->to;
            m.points = {pos, m.to};
        } else if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
            m.to = l->to;
            m.feed = l->feedMmPerMin;
            m.lengthXY = distance(pos.xy(), m.to.xy());
            const int n = std::max(16, static_cast<int>(distance(pos, m.to) / 0.1));
            for (int k = 0; k <= n; ++k)
                m.points.push_back(pos + (m.to - pos) * (static_cast<double>(k) / n));
        } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
            m.arc = true;
            m.to = a->to;
            m.feed = a->feedMmPerMin;
            m.helix = std::abs(a->to.z - pos.z) > 1e-12;
            const double sweep = arcSweep(pos, *a);
            const Vec2 c = a->center.xy();
            const double radius = distance(pos.xy(), c);
            m.lengthXY = std::abs(sweep) * radius;
            const double a0 = std::atan2(pos.y - c.y, pos.x - c.x);
            const int n = std::max(16, static_cast<int>(m.lengthXY / 0.1));
            for (int k = 0; k <= n; ++k) {
                const double t = static_cast<double>(k) / n;
                const double ang = a0 + sweep * t;
                m.points.push_back(
                    {c.x + radius * std::cos(ang), c.y + radius * std::sin(ang), pos.z + (a->to.z - pos.z) * t});
            }
            EXPECT_NEAR(distance(a->to.xy(), c), radius, 1e-9) << "arc record " << i;
        } else {
            continue;
        }
        if (!known && !m.rapid)
            ADD_FAILURE() << "record " << i << " moves before any rapid positioned the tool";
        known = true;
        pos = m.to;
        moves.push_back(std::move(m));
    }
    return moves;
}

// Distance from the contour, negative on the material side (closed: inside outside cuts etc.).
// `poly`: the contour discretised (geom::discretize, 1e-4), for the inside test.
inline double clearance(const Profile& contour, const std::vector<Vec2>& poly, Vec2 p, bool materialInside)
{
    const double d = geom::distanceToProfile(p, contour);
    if (!contour.closed)
        return d;
    bool inside = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            inside = !inside;
    return inside == materialInside ? -d : d;
}

// Rounded rectangles, regular and random polygons, shapes with concave arcs.
inline std::vector<std::pair<std::string, Profile>> closedShapes()
{
    std::vector<std::pair<std::string, Profile>> out;
    out.push_back({"plate", geom::test::roundedRectangle(0, 0, 90, 60, 8)});
    out.push_back({"plate-cw", geom::test::roundedRectangle(-20, 5, 70, 40, 12).reversed()});
    out.push_back({"rectangle", geom::test::rectangle(0, 0, 40, 20)});
    out.push_back({"boss", geom::test::circle({20, 10}, 15)});
    out.push_back({"L", geom::test::polygon({{0, 0}, {60, 0}, {60, 25}, {25, 25}, {25, 50}, {0, 50}})});
    std::mt19937 rng(99);
    for (int i = 0; i < 4; ++i) {
        std::uniform_real_distribution<double> radius(25, 45), jitter(-0.2, 0.2);
        const int n = 5 + i;
        std::vector<Vec2> pts;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * std::numbers::pi * (k + jitter(rng)) / n;
            pts.push_back({radius(rng) * std::cos(a), radius(rng) * std::sin(a)});
        }
        out.push_back({"polygon" + std::to_string(i), geom::test::polygon(pts)});
    }
    // A slot with a concave half-circle bottom (radius 14) and rounded outer corners.
    Profile u;
    u.segments = {
        Segment::line({5, 0}, {75, 0}),    Segment::arc({75, 0}, {80, 5}, {75, 5}, true),
        Segment::line({80, 5}, {80, 60}),  Segment::line({80, 60}, {54, 60}),
        Segment::line({54, 60}, {54, 30}), Segment::arc({54, 30}, {26, 30}, {40, 30}, false),
        Segment::line({26, 30}, {26, 60}), Segment::line({26, 60}, {0, 60}),
        Segment::line({0, 60}, {0, 5}),    Segment::arc({0, 5}, {5, 0}, {5, 5}, true),
    };
    out.push_back({"U", u});
    // A plate with a concave arc in one side, meeting the lines at an angle.
    Profile bite;
    bite.segments = {
        Segment::line({0, 0}, {80, 0}),    Segment::line({80, 0}, {80, 50}),
        Segment::line({80, 50}, {55, 50}), Segment::arc({55, 50}, {25, 50}, {40, 70}, true),
        Segment::line({25, 50}, {0, 50}),  Segment::line({0, 50}, {0, 0}),
    };
    out.push_back({"bite", bite});
    return out;
}

// Open chains: a straight edge, an L, a chain with an arc and a random gentle polyline.
inline std::vector<std::pair<std::string, Profile>> openChains()
{
    auto chain = [](std::vector<Segment> segs) { return Profile{std::move(segs), false}; };
    std::vector<std::pair<std::string, Profile>> out;
    out.push_back({"edge", chain({Segment::line({0, 0}, {80, 0})})});
    out.push_back({"L", chain({Segment::line({0, 0}, {60, 0}), Segment::line({60, 0}, {60, 40})})});
    out.push_back({"arc", chain({Segment::line({-40, 30}, {0, 30}), Segment::arc({0, 30}, {30, 0}, {0, 0}, false),
                                 Segment::line({30, 0}, {30, -40})})});
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> step(20, 30), slope(-0.5, 0.5);
    std::vector<Segment> segs;
    Vec2 at{0, 0};
    for (int i = 0; i < 5; ++i) {
        const double dx = step(rng);
        const Vec2 next{at.x + dx, at.y + dx * slope(rng)};
        segs.push_back(Segment::line(at, next));
        at = next;
    }
    out.push_back({"zigzag", chain(segs)});
    return out;
}

}  // namespace camwb::ops::test
