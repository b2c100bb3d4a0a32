// Property tests over generated shapes (rounded rectangles, polygons, concave arcs, open chains)
// and a matrix of options: no cutting move comes closer to the finished contour than the tool
// radius plus the radial stock, on the free side; rapids stay above the safe height; the passes
// run at exactly the stated levels; the part's arcs stay arcs.
#include "ContourTestUtil.h"

#include <set>

using namespace camwb;
using namespace camwb::ops::test;

namespace {

struct Options {
    std::string name;
    ops::ContourParams params;
};

std::vector<Options> optionMatrix(ops::ContourSide side)
{
    std::vector<Options> out;
    for (bool climb : {true, false}) {
        auto p = params(side, climb);
        p.stepDownMm = 1.2;
        out.push_back({climb ? "plain-climb" : "plain-conventional", p});
    }
    auto p = params(side);
    p.radialStockMm = 0.3;
    p.axialStockMm = 0.2;
    p.stepDownMm = 1;
    p.leadIn = p.leadOut = ops::LeadKind::Arc;
    p.leadRadiusMm = 3;
    p.entry = ops::EntryKind::Ramp;
    p.rampAngleDeg = 4;
    p.tabCount = 3;
    p.tabWidthMm = 2;
    p.tabHeightMm = 1;
    out.push_back({"arc-leads-ramp-tabs-stock", p});
    p = params(side, false);
    p.leadIn = ops::LeadKind::Line;
    p.leadOut = ops::LeadKind::PerpendicularLine;
    p.leadRadiusMm = 2;
    p.entry = ops::EntryKind::Helix;
    p.helixDiameterMm = 3;
    p.helixPitchMm = 0.7;
    p.stepDownMm = 1.5;
    p.radialPasses = 3;
    p.radialStepoverMm = 1.5;
    out.push_back({"line-leads-helix-passes", p});
    return out;
}

struct Shape {
    std::string name;
    Profile profile;
    ops::ContourSide side;
};

std::vector<Shape> corpus()
{
    std::vector<Shape> out;
    for (const auto& [name, profile] : closedShapes()) {
        out.push_back({name + "/outside", profile, ops::ContourSide::Outside});
        out.push_back({name + "/inside", profile, ops::ContourSide::Inside});
    }
    for (const auto& [name, profile] : openChains()) {
        out.push_back({name + "/left", profile, ops::ContourSide::Left});
        out.push_back({name + "/right", profile, ops::ContourSide::Right});
    }
    return out;
}

// Which side of the chain p is on (> 0 left), by the nearest segment.
double chainSide(const Profile& chain, Vec2 p)
{
    double best = 1e300, side = 0;
    for (const Segment& s : chain.segments) {
        const double d = geom::distanceToSegment(p, s);
        if (d < best) {
            best = d;
            side = s.isArc() ? (s.ccw ? 1 : -1) * (s.radius() - distance(p, s.center))
                             : (s.end - s.start).cross(p - s.start);
        }
    }
    return side;
}

}  // namespace

TEST(ContourProperty, NoGougeRapidsAboveSafeLevelsExactArcsKept)
{
    const auto tc = tool(6);
    const double r = 3;
    int computed = 0, refused = 0;
    for (const Shape& shape : corpus())
        for (const Options& o : optionMatrix(shape.side)) {
            SCOPED_TRACE(shape.name + " " + o.name);
            const ops::ContourParams& p = o.params;
            auto result = ops::computeContour({shape.profile}, p, tc, 0);
            if (!result.ok()) {
                // Only a tool, lead or helix too large for a feature may refuse (a tangent line lead
                // inside the round boss, ...): refused, never gouged.
                ++refused;
                EXPECT_TRUE(result.error().message.find("too large") != std::string::npos ||
                            result.error().message.find("does not fit") != std::string::npos ||
                            result.error().message.find("make the lead smaller") != std::string::npos)
                    << result.error().message;
                continue;
            }
            ++computed;
            const std::vector<Move> moves = walk(result.value().toolpath);
            const std::vector<Vec2> poly = geom::discretize(shape.profile, 1e-4);
            const double minClear = r + p.radialStockMm - 1e-6;
            const double bottom = p.heights.finalZ + p.axialStockMm;
            const std::vector<double> levels = ops::stepDownLevels(p.heights.startZ, bottom, p.stepDownMm);
            std::set<double> loopLevels;
            bool first = true;
            for (const Move& m : moves) {
                if (m.rapid) {
                    // Rapids end above the safe height; only straight up they may start lower
                    // (retracts). The first one arrives from anywhere.
                    EXPECT_GE(m.to.z, p.heights.safeZ - 1e-12) << "rapid " << m.record;
                    const bool straightUp = distance(m.from.xy(), m.to.xy()) < 1e-12 && m.to.z > m.from.z;
                    if (!first && !straightUp)
                        EXPECT_GE(m.from.z, p.heights.safeZ - 1e-12) << "rapid " << m.record;
                    first = false;
                    continue;
                }
                for (const Vec3& pt : m.points) {
                    EXPECT_GE(pt.z, bottom - 1e-12);
                    const double c = shape.profile.closed ? clearance(shape.profile, poly, pt.xy(),
                                                                      shape.side == ops::ContourSide::Outside)
                                                          : geom::distanceToProfile(pt.xy(), shape.profile);
                    ASSERT_GE(c, minClear)
                        << "gouge by record " << m.record << " at " << pt.x << ", " << pt.y << ", " << pt.z;
                    if (!shape.profile.closed && m.lengthXY > 0)  // the tool stays on its side of the chain
                        ASSERT_EQ(chainSide(shape.profile, pt.xy()) > 0, shape.side == ops::ContourSide::Left)
                            << "record " << m.record;
                }
                if (m.lengthXY > 1e-9 && std::abs(m.from.z - m.to.z) < 1e-12 && m.to.z < p.heights.startZ)
                    loopLevels.insert(m.to.z);
            }
            // Horizontal cutting at exactly the levels (and the tab top where tabs are).
            std::set<double> expected(levels.begin(), levels.end());
            if (p.tabCount > 0)
                expected.insert(p.heights.finalZ + p.tabHeightMm);
            EXPECT_EQ(loopLevels, expected);
            // Each level cuts at least the part's arcs as arcs.
            const int partArcs = static_cast<int>(geom::test::countArcs(shape.profile));
            EXPECT_GE(result.value().counts.arcs, partArcs * static_cast<int>(levels.size()) * p.radialPasses);
        }
    EXPECT_GT(computed, 100);
    EXPECT_LT(refused, 12);
}
