// The contour's options one by one: tabs (spans, widths, heights), cutter compensation records
// and the programmed path, radial passes, helix and ramp geometry, leads, open-chain directions,
// staying down between levels.
#include "ContourTestUtil.h"

using namespace camwb;
using namespace camwb::ops::test;
using geom::distanceToProfile;
using geom::test::roundedRectangle;

namespace {

const Profile kPlate = roundedRectangle(0, 0, 90, 60, 8);

ops::OpResult compute(const std::vector<Profile>& loops, const ops::ContourParams& p, double toolDiameter = 10)
{
    auto r = ops::computeContour(loops, p, tool(toolDiameter), 0);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return r.ok() ? r.value() : ops::OpResult{};
}

// Horizontal cutting moves at z, in order.
std::vector<Move> at(const std::vector<Move>& moves, double z)
{
    std::vector<Move> out;
    for (const Move& m : moves)
        if (!m.rapid && m.lengthXY > 1e-9 && std::abs(m.from.z - z) < 1e-12 && std::abs(m.to.z - z) < 1e-12)
            out.push_back(m);
    return out;
}

}  // namespace

TEST(ContourTabs, RaiseToTheTabTopExactlyOverEvenlySpacedSpans)
{
    for (const auto& [name, shape] : closedShapes()) {
        for (int count : {1, 3}) {
            SCOPED_TRACE(name + " tabs " + std::to_string(count));
            auto p = params(ops::ContourSide::Outside);
            p.stepDownMm = 1;
            p.tabCount = count;
            p.tabWidthMm = 3;
            p.tabHeightMm = 1.5;  // levels -1, -2 and -3: the last two are below the top at -1.5
            const std::vector<Move> moves = walk(compute({shape}, p, 6).toolpath);
            const double width = 3 + 6;
            for (double level : {-2.0, -3.0}) {
                // Walk the level from its first move at depth: runs at the top are the tabs.
                double s = 0, loopLength = 0;
                std::vector<std::pair<double, double>> runs;  // arclength from, to at the top
                bool onLevel = false;
                for (const Move& m : moves) {
                    const bool flat = std::abs(m.from.z - m.to.z) < 1e-12;
                    if (!onLevel && flat && m.to.z == level && m.lengthXY > 0)
                        onLevel = true;
                    if (!onLevel)
                        continue;
                    if (m.rapid || (flat && m.to.z != level && m.to.z != -1.5))
                        break;
                    if (!flat) {
                        // Up and down at the tab edges are straight vertical moves; anything else
                        // (the plunge to the next level) ends this one.
                        if (!((m.from.z == level && m.to.z == -1.5) || (m.from.z == -1.5 && m.to.z == level)))
                            break;
                        EXPECT_LT(m.lengthXY, 1e-12) << "record " << m.record;
                        continue;
                    }
                    if (m.to.z == -1.5) {
                        if (!runs.empty() && std::abs(runs.back().second - s) < 1e-9)
                            runs.back().second = s + m.lengthXY;
                        else
                            runs.push_back({s, s + m.lengthXY});
                    }
                    s += m.lengthXY;
                }
                loopLength = s;
                ASSERT_EQ(runs.size(), static_cast<std::size_t>(count)) << "level " << level;
                for (std::size_t k = 0; k < runs.size(); ++k) {
                    EXPECT_NEAR(runs[k].second - runs[k].first, width, 1e-9);
                    EXPECT_NEAR(0.5 * (runs[k].first + runs[k].second), (k + 0.5) * loopLength / count, 1e-9);
                }
            }
            // The level above the tab top has no tabs.
            for (const Move& m : at(moves, -1.0))
                EXPECT_EQ(m.to.z, -1.0);
        }
    }
}

TEST(ContourCompensation, RecordsAndProgrammedContour)
{
    struct Case {
        ops::ContourSide side;
        bool climb;
        toolpath::CutterCompSide expected;
    };
    for (const Case& c : {Case{ops::ContourSide::Outside, true, toolpath::CutterCompSide::Left},
                          Case{ops::ContourSide::Outside, false, toolpath::CutterCompSide::Right},
                          Case{ops::ContourSide::Inside, true, toolpath::CutterCompSide::Left},
                          Case{ops::ContourSide::Inside, false, toolpath::CutterCompSide::Right}})
        for (double stock : {0.0, 0.5}) {
            SCOPED_TRACE(std::to_string(static_cast<int>(c.side)) + (c.climb ? " climb" : " conv") + " stock " +
                         std::to_string(stock));
            auto p = params(c.side, c.climb);
            p.compensation = ops::CompensationOutput::Control;
            p.radialStockMm = stock;
            p.stepDownMm = 1.5;
            p.leadIn = p.leadOut = ops::LeadKind::Arc;
            p.leadRadiusMm = 7;
            const toolpath::Toolpath tp = compute({kPlate}, p).toolpath;
            int on = 0, off = 0, cornerArcs = 0;
            bool active = false;
            Vec3 pos;
            for (std::size_t i = 0; i < tp.size(); ++i) {
                const toolpath::Record& r = tp.record(i);
                if (const auto* cc = std::get_if<toolpath::CutterComp>(&r)) {
                    // The control switches on a straight move: the next record is a Linear.
                    ASSERT_LT(i + 1, tp.size());
                    EXPECT_TRUE(std::holds_alternative<toolpath::Linear>(tp.record(i + 1))) << "record " << i;
                    if (cc->side == toolpath::CutterCompSide::Off) {
                        EXPECT_TRUE(active);
                        ++off;
                        active = false;
                    } else {
                        EXPECT_EQ(cc->side, c.expected);
                        EXPECT_FALSE(active);
                        ++on;
                        active = true;
                    }
                    continue;
                }
                if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
                    EXPECT_FALSE(active) << "rapid under compensation, record " << i;
                    pos = rapid->to;
                } else if (const auto* l = std::get_if<toolpath::Linear>(&r)) {
                    pos = l->to;
                } else if (const auto* a = std::get_if<toolpath::Arc>(&r)) {
                    // The programmed contour: the corner arcs are the part's moved by the stock.
                    for (Vec2 corner : {Vec2{8, 8}, Vec2{82, 8}, Vec2{82, 52}, Vec2{8, 52}})
                        if (distance(a->center.xy(), corner) < 1e-9) {
                            ++cornerArcs;
                            const double expected = 8 + (c.side == ops::ContourSide::Outside ? stock : -stock);
                            EXPECT_NEAR(distance(a->to.xy(), a->center.xy()), expected, 1e-9);
                        }
                    pos = a->to;
                }
            }
            EXPECT_EQ(cornerArcs, 8);
            EXPECT_EQ(on, 2);  // two levels
            EXPECT_EQ(off, 2);
            // Every programmed point of the loop moves lies exactly `stock` off the contour.
            const std::vector<Move> moves = walk(tp);
            int onContour = 0;
            for (const Move& m : at(moves, -3))
                for (const Vec3& pt : m.points) {
                    const double d = distanceToProfile(pt.xy(), kPlate);
                    EXPECT_GE(d, stock - 1e-9);
                    onContour += std::abs(d - stock) < 1e-9;
                }
            EXPECT_GT(onContour, 2000);
        }
}

TEST(ContourRadialPasses, OutermostFirstEndingOnTheOffset)
{
    auto p = params();
    p.radialPasses = 3;
    p.radialStepoverMm = 2;
    p.radialStockMm = 0.25;
    const std::vector<Move> moves = walk(compute({kPlate}, p).toolpath);
    std::vector<double> passDistances;
    for (const Move& m : at(moves, -3)) {
        const double d = distanceToProfile(m.to.xy(), kPlate);
        if (passDistances.empty() || std::abs(passDistances.back() - d) > 1e-6)
            passDistances.push_back(d);
    }
    ASSERT_EQ(passDistances.size(), 3u);
    EXPECT_NEAR(passDistances[0], 9.25, 1e-9);
    EXPECT_NEAR(passDistances[1], 7.25, 1e-9);
    EXPECT_NEAR(passDistances[2], 5.25, 1e-9);
}

TEST(ContourEntry, HelixPitchAndRadiusExact)
{
    auto p = params(ops::ContourSide::Inside);
    p.entry = ops::EntryKind::Helix;
    p.helixDiameterMm = 8;
    p.helixPitchMm = 0.8;
    p.stepDownMm = 1.5;
    const ops::OpResult r = compute({kPlate}, p);
    int helices = 0;
    double totalDrop = 0;
    for (const Move& m : walk(r.toolpath)) {
        if (!m.helix)
            continue;
        ++helices;
        const auto& a = std::get<toolpath::Arc>(r.toolpath.record(m.record));
        EXPECT_NEAR(distance(m.from.xy(), a.center.xy()), 4, 1e-9);
        EXPECT_EQ(a.center.z, m.from.z);  // the centre in the start's plane
        const double sweep = std::abs(arcSweep(m.from, a));
        EXPECT_LE(sweep, std::numbers::pi + 1e-9);
        EXPECT_NEAR((m.from.z - m.to.z) / sweep * 2 * std::numbers::pi, 0.8, 1e-9);
        EXPECT_EQ(m.feed, 600);
        totalDrop += m.from.z - m.to.z;
    }
    EXPECT_EQ(r.counts.helices, helices);
    EXPECT_NEAR(totalDrop, 3, 1e-9);  // 0 -> -1.5 -> -3
}

TEST(ContourEntry, RampNeverSteeperThanTheAngle)
{
    for (const auto& [name, shape] : closedShapes()) {
        SCOPED_TRACE(name);
        auto p = params();
        p.entry = ops::EntryKind::Ramp;
        p.rampAngleDeg = 3;
        p.stepDownMm = 1;
        int ramps = 0;
        for (const Move& m : walk(compute({shape}, p, 6).toolpath)) {
            if (m.rapid || m.lengthXY < 1e-9 || std::abs(m.from.z - m.to.z) < 1e-12)
                continue;
            ++ramps;
            EXPECT_LE((m.from.z - m.to.z) / m.lengthXY, std::tan(3 * std::numbers::pi / 180) + 1e-9);
            EXPECT_GT(m.from.z, m.to.z);
            EXPECT_EQ(m.feed, 600);
        }
        EXPECT_GE(ramps, 3);
        // No plunge below the top of the material: the only plunge-feed move goes down to z 0.
        for (const Move& m : walk(compute({shape}, p, 6).toolpath))
            if (m.feed == 300)
                EXPECT_GE(m.to.z, 0);
    }
}

TEST(ContourLeads, ArcAndLineGeometry)
{
    auto p = params();
    p.leadRadiusMm = 4;
    for (ops::LeadKind kind : {ops::LeadKind::Arc, ops::LeadKind::Line, ops::LeadKind::PerpendicularLine}) {
        p.leadIn = p.leadOut = kind;
        const toolpath::Toolpath tp = compute({kPlate}, p).toolpath;
        // SectionBegin, rapid, rapid, plunge at the lead start, then the lead-in.
        const Vec2 leadStart = std::get<toolpath::Linear>(tp.record(3)).to.xy();
        const toolpath::Record& in = tp.record(4);
        // The path starts at the middle of the top or bottom side, 5 mm off it.
        const Vec2 pathStart = std::holds_alternative<toolpath::Arc>(in) ? std::get<toolpath::Arc>(in).to.xy()
                                                                         : std::get<toolpath::Linear>(in).to.xy();
        EXPECT_NEAR(pathStart.x, 45, 1e-9);
        EXPECT_NEAR(distanceToProfile(pathStart, kPlate), 5, 1e-9);
        const double outward = std::abs(leadStart.y - 30) - std::abs(pathStart.y - 30);  // away from the plate
        if (kind == ops::LeadKind::Arc) {
            const auto& a = std::get<toolpath::Arc>(in);
            EXPECT_NEAR(distance(a.center.xy(), pathStart), 4, 1e-9);
            EXPECT_NEAR(std::abs(leadStart.x - pathStart.x), 4, 1e-9);  // a quarter arc
            EXPECT_NEAR(outward, 4, 1e-9);
        } else if (kind == ops::LeadKind::Line) {
            EXPECT_NEAR(std::abs(leadStart.x - pathStart.x), 4, 1e-9);  // tangent
            EXPECT_NEAR(outward, 0, 1e-9);
        } else {
            EXPECT_NEAR(leadStart.x, pathStart.x, 1e-9);  // perpendicular
            EXPECT_NEAR(outward, 4, 1e-9);
        }
    }
}

TEST(ContourChains, DirectionAndSideOfOpenChains)
{
    const Profile chain{{Segment::line({0, 0}, {60, 0}), Segment::line({60, 0}, {60, 40})}, false};
    struct Case {
        ops::ContourSide side;
        bool climb;
        Vec2 first;  // where the cut starts
        double y0;   // the first side's offset
    };
    for (const Case& c :
         {Case{ops::ContourSide::Left, true, {0, 5}, 5}, Case{ops::ContourSide::Left, false, {55, 40}, 5},
          Case{ops::ContourSide::Right, true, {65, 40}, -5}, Case{ops::ContourSide::Right, false, {0, -5}, -5},
          Case{ops::ContourSide::On, true, {0, 0}, 0}}) {
        SCOPED_TRACE(std::to_string(static_cast<int>(c.side)) + (c.climb ? " climb" : " conventional"));
        auto p = params(c.side, c.climb);
        p.stepDownMm = 1.5;
        const ops::OpResult r = compute({chain}, p);
        const std::vector<Move> moves = walk(r.toolpath);
        const auto& plunge = std::get<toolpath::Linear>(r.toolpath.record(3));
        EXPECT_NEAR(distance(plunge.to.xy(), c.first), 0, 1e-9);
        for (const Move& m : at(moves, -3))
            for (const Vec3& pt : m.points)
                EXPECT_NEAR(distanceToProfile(pt.xy(), chain), std::abs(c.y0), 1e-9);
        // An open chain retracts between levels: two plunges from the safe height.
        int descents = 0;
        for (const Move& m : moves)
            descents += !m.rapid && m.from.z == 2 && m.to.z < 2;
        EXPECT_EQ(descents, 2);
    }
}

TEST(ContourLevels, ClosedLoopStaysDownBetweenLevelsAxialStockLeft)
{
    auto p = params();
    p.stepDownMm = 1;
    p.axialStockMm = 0.5;
    const ops::OpResult r = compute({kPlate}, p);
    const std::vector<Move> moves = walk(r.toolpath);
    int rapids = 0;
    double lowest = 0;
    for (const Move& m : moves) {
        rapids += m.rapid;
        lowest = std::min(lowest, m.to.z);
    }
    EXPECT_EQ(rapids, 3);  // clearance, safe, and back to clearance at the end
    EXPECT_DOUBLE_EQ(lowest, -2.5);
    for (double z : {-2.5 / 3, -5.0 / 3, -2.5})
        EXPECT_FALSE(at(moves, z).empty()) << z;
}
