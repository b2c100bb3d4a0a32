// Property of cutter compensation on generated contours: every point of the tool-centre path
// between the entry and the exit is exactly the radius away from the programmed contour (never
// closer: no gouge), whichever side, rules and radius, wherever the contour allows the tool. The
// contours are star-shaped loops of lines and arcs with inside and outside corners; a case the
// filter reports as a gouge is counted, not checked, and most cases must allow the tool.
#include "CompensationSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace camwb::nc::test {
namespace {

struct Contour {
    std::vector<Piece> pieces;
    std::vector<Record> records;  // as an interpreter sends them, from pieces[0].start round
};

// A star-shaped loop about the origin: `n` corners at random radii, each edge a line or an arc
// bulging out or in (never so much that it meets another edge), from the middle of the first
// edge round to it.
Contour makeContour(std::mt19937& random, int n)
{
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vec2> corners;
    for (int i = 0; i < n; ++i) {
        const double angle = (i + 0.3 * unit(random)) * 2 * std::numbers::pi / n;
        const double radius = 40 + 30 * unit(random);
        corners.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    // The loop starts and ends in the middle of its first edge, a line: a closed contour has no
    // corner where it starts (the control has nothing to trim there either).
    const Vec2 middle = (corners[0] + corners[1]) * 0.5;
    corners.insert(corners.begin() + 1, middle);
    std::rotate(corners.begin(), corners.begin() + 1, corners.end());
    n = static_cast<int>(corners.size());
    Contour c;
    for (int i = 0; i < n; ++i) {
        Piece p;
        p.start = corners[static_cast<std::size_t>(i)];
        p.end = corners[static_cast<std::size_t>((i + 1) % n)];
        const bool firstEdge = i == 0 || i == n - 1;
        if (!firstEdge && unit(random) < 0.4) {
            // An arc through the chord's ends with its centre on the bisector, at least as large
            // as the chord: a gentle bulge one way or the other.
            const Vec2 mid = (p.start + p.end) * 0.5;
            const Vec2 chord = p.end - p.start;
            const double half = chord.length() / 2;
            const double offset = half * (1.2 + 2 * unit(random)) * (unit(random) < 0.5 ? 1 : -1);
            p.arc = true;
            p.center = mid + chord.normalized().leftNormal() * offset;
            // Centre left of the chord: a counter-clockwise arc takes the short way.
            p.clockwise = offset < 0;
        }
        c.pieces.push_back(p);
        if (p.arc)
            c.records.push_back(
                Arc{{p.end.x, p.end.y, -1}, {p.center.x, p.center.y, -1}, {0, 0, 1}, p.clockwise, 0, 300});
        else
            c.records.push_back(Linear{{p.end.x, p.end.y, -1}, 300});
    }
    return c;
}

// Points along a move from `from`: a line's ends and middle, an arc every few degrees.
std::vector<Vec2> samples(const Vec3& from, const Record& record)
{
    std::vector<Vec2> out;
    if (const auto* l = std::get_if<Linear>(&record)) {
        for (double t : {0.0, 0.25, 0.5, 0.75, 1.0})
            out.push_back(from.xy() + (l->to.xy() - from.xy()) * t);
    } else if (const auto* a = std::get_if<Arc>(&record)) {
        const Vec2 c = a->center.xy();
        const double r = distance(from.xy(), c);
        const double a0 = angleOf(from.xy() - c);
        double sweep = angleOf(a->to.xy() - c) - a0;
        if (a->clockwise)
            sweep = -sweep;
        while (sweep <= 0)
            sweep += 2 * std::numbers::pi;
        const int steps = 32;
        for (int k = 0; k <= steps; ++k) {
            const double angle = a0 + (a->clockwise ? -1 : 1) * sweep * k / steps;
            out.push_back(c + Vec2{std::cos(angle), std::sin(angle)} * r);
        }
    }
    return out;
}

void checkRules(const CompensationRules& rules, const char* name)
{
    std::mt19937 random(20261130);
    std::uniform_real_distribution<double> unit(0, 1);
    int checked = 0, refused = 0;
    for (int round = 0; round < 300; ++round) {
        const Contour contour = makeContour(random, 5 + static_cast<int>(unit(random) * 6));
        const double radius = 0.5 + 4 * unit(random);
        const bool left = unit(random) < 0.5;
        Compensated c(rules);
        c.comp.setRadius(radius, "tool 1");
        // NORM approaches square to the contour from outside the star; LinuxCNC's entry ends
        // square to itself, so it approaches along the first edge, as its manual advises.
        const Vec2 first = contour.pieces.front().start;
        const Vec2 along = (contour.pieces.front().end - first).normalized();
        const Vec2 away = rules.entrySquareToContour ? first + first.normalized() * 30 : first - along * 30;
        c.block(1, Rapid{{away.x, away.y, 5}});
        c.block(2, Rapid{{away.x, away.y, -1}});
        c.block(3, CutterComp{left ? CutterCompSide::Left : CutterCompSide::Right});
        c.block(4, Linear{{first.x, first.y, -1}, 300});
        int line = 5;
        for (const Record& r : contour.records)
            c.block(line++, r);
        c.block(line, CutterComp{CutterCompSide::Off});
        c.block(line, Linear{{away.x, away.y, -1}, 300});
        c.finish();
        if (c.result.hasErrors()) {
            ++refused;
            continue;
        }
        ASSERT_TRUE(c.result.diagnostics.empty()) << name << " round " << round << ": " << c.diagnostics();
        // Between the entry (the move of block 4) and the exit (the last move) every point of the
        // path is exactly `radius` from the contour.
        const Toolpath& path = c.path();
        Vec3 at{};
        for (std::size_t i = 0; i < path.size(); ++i) {
            const Record& r = path.record(i);
            const int source = path.source(i).line;
            const bool contourMove = source > 4 && source < line;
            if (contourMove)
                for (const Vec2& p : samples(at, r)) {
                    const double d = distanceTo(contour.pieces, p);
                    ASSERT_NEAR(d, radius, 1e-6) << name << " round " << round << " record " << i << " line " << source
                                                 << " at (" << p.x << ", " << p.y << ")";
                }
            std::visit(
                [&at](const auto& move) {
                    if constexpr (requires { move.to; })
                        at = move.to;
                },
                r);
        }
        ++checked;
    }
    EXPECT_GT(checked, 200) << name << ": " << refused << " of 300 refused";
}

TEST(CompensationProperty, EveryPointIsTheRadiusFromTheContourWithNormRules)
{
    checkRules(CompensationRules::sinumerik(), "NORM");
}

TEST(CompensationProperty, EveryPointIsTheRadiusFromTheContourWithLinuxCncRules)
{
    CompensationRules rules = CompensationRules::linuxCnc();
    rules.tangentTolerance = 1e-9;  // LinuxCNC's 0.05 rad leaves near-tangent joints a hair off
    checkRules(rules, "LinuxCNC");
}

}  // namespace
}  // namespace camwb::nc::test
