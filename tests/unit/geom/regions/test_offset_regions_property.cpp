// Property test of offsetRegions over generated shapes (rounded rectangles and star polygons with
// bulged arc edges, islands of circles and rounded rectangles): a shrink never comes closer than
// |delta| to the exact input loops, stays inside the input, and loses little area against a fine
// Clipper offset of a finely discretised input (less than perimeter * 2 * tolerance).
#include "RegionTestUtil.h"
#include "geom/RegionOps.h"

#include <gtest/gtest.h>
#include <polyclipping/clipper.hpp>

#include <numbers>
#include <random>

using namespace camwb::geom;
namespace t = camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

// The arc from a through m to b (m strictly between them along the arc).
Segment arcThrough(Vec2 a, Vec2 m, Vec2 b)
{
    const Vec2 ab = m - a, ac = b - a;
    const double d = 2 * ab.cross(ac);
    const Vec2 c = a + Vec2{(ac.y * ab.dot(ab) - ab.y * ac.dot(ac)) / d, (ab.x * ac.dot(ac) - ac.x * ab.dot(ab)) / d};
    return Segment::arc(a, b, c, d > 0);
}

// Star-shaped polygon around (50, 50) whose edges are lines or arcs bulging in or out.
Profile bulgedStar(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    const int n = 5 + static_cast<int>(unit(rng) * 5);
    std::vector<Vec2> pts;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * (i + 0.3 * unit(rng)) / n;
        const double r = 28 + 12 * unit(rng);
        pts.push_back({50 + r * std::cos(a), 50 + r * std::sin(a)});
    }
    Profile p;
    for (int i = 0; i < n; ++i) {
        const Vec2 a = pts[i], b = pts[(i + 1) % n];
        const double bulge = (unit(rng) - 0.5) * 0.3 * distance(a, b);
        if (unit(rng) < 0.3 || std::abs(bulge) < 0.5) {
            p.segments.push_back(Segment::line(a, b));
            continue;
        }
        const Vec2 m = (a + b) * 0.5 + (b - a).normalized().rightNormal() * bulge;
        p.segments.push_back(arcThrough(a, m, b));
    }
    return p;
}

Profile randomIsland(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec2 c{30 + 40 * unit(rng), 30 + 40 * unit(rng)};
    if (unit(rng) < 0.5)
        return t::circle(c, 2 + 4 * unit(rng)).reversed();
    const double w = 4 + 8 * unit(rng), h = 4 + 8 * unit(rng);
    return t::roundedRectangle(c.x - w / 2, c.y - h / 2, w, h, std::min(w, h) * 0.45 * unit(rng)).reversed();
}

bool loopClear(const Profile& loop, const Region& region, double clearance)
{
    for (const Vec2& p : t::samples(loop, 32))
        if (!region.contains(p) || region.distanceToBoundary(p) < clearance)
            return false;
    return true;
}

Region randomRegion(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    Region region;
    if (unit(rng) < 0.4) {
        const double w = 40 + 40 * unit(rng), h = 40 + 40 * unit(rng);
        region.outer = t::roundedRectangle(50 - w / 2, 50 - h / 2, w, h, std::min(w, h) * 0.4 * unit(rng));
    } else {
        region.outer = bulgedStar(rng);
    }
    const int islands = static_cast<int>(unit(rng) * 4);
    for (int i = 0; i < 20 && static_cast<int>(region.holes.size()) < islands; ++i) {
        const Profile island = randomIsland(rng);
        if (loopClear(island, region, 1.0))
            region.holes.push_back(island);
    }
    return region;
}

// Area of a Clipper offset of the input discretised to 0.1 um chords (the exact offset's area
// to within ~perimeter * 1e-4) and the perimeter of that offset.
std::pair<double, double> referenceOffset(const Region& region, double delta)
{
    ClipperLib::ClipperOffset offsetter;
    offsetter.ArcTolerance = 100;  // 0.1 um
    std::vector<Profile> loops{region.outer};
    loops.insert(loops.end(), region.holes.begin(), region.holes.end());
    for (const Profile& loop : loops) {
        ClipperLib::Path path;
        for (const Vec2& p : discretize(loop, 1e-4))
            path.push_back({std::llround(p.x * 1e6), std::llround(p.y * 1e6)});
        offsetter.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    }
    ClipperLib::Paths out;
    offsetter.Execute(out, delta * 1e6);
    double area = 0, perimeter = 0;
    for (const ClipperLib::Path& path : out) {
        area += ClipperLib::Area(path) / 1e12;
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto& a = path[i];
            const auto& b = path[(i + 1) % path.size()];
            perimeter += std::hypot(static_cast<double>(a.X - b.X), static_cast<double>(a.Y - b.Y)) / 1e6;
        }
    }
    return {area, perimeter};
}

}  // namespace

TEST(OffsetRegionsProperty, ShrinkKeepsDistanceAndArea)
{
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> unit(0, 1);
    const double tolerances[] = {0.001, 0.005, 0.01, 0.03};
    int nonEmpty = 0;
    for (int round = 0; round < 60; ++round) {
        const Region input = randomRegion(rng).normalized();
        const double delta = 0.5 + 8 * unit(rng);
        const double tol = tolerances[round % 4];
        SCOPED_TRACE("round " + std::to_string(round) + " delta " + std::to_string(delta) + " tol " +
                     std::to_string(tol));
        const std::vector<Region> result = offsetRegions({input}, -delta, tol);
        double worst = 1e300;
        for (const Region& region : result) {
            EXPECT_GT(region.outer.signedArea(), 0);
            EXPECT_TRUE(region.outer.isContinuous(1e-9));
            std::vector<Profile> loops{region.outer};
            for (const Profile& hole : region.holes) {
                EXPECT_LT(hole.signedArea(), 0);
                EXPECT_TRUE(hole.isContinuous(1e-9));
                loops.push_back(hole);
            }
            for (const Profile& loop : loops)
                for (const Vec2& p : t::samples(loop, 20)) {
                    worst = std::min(worst, input.distanceToBoundary(p));
                    ASSERT_TRUE(input.contains(p));
                }
        }
        if (!result.empty()) {
            ++nonEmpty;
            EXPECT_GE(worst, delta - 1e-6);
        }
        const auto [referenceArea, perimeter] = referenceOffset(input, -delta);
        const double area = totalArea(result);
        EXPECT_LE(area, referenceArea + perimeter * 1e-3 + 1e-9);
        EXPECT_GE(area, referenceArea - perimeter * 2 * tol - 1e-9);
    }
    EXPECT_GT(nonEmpty, 45);
}

// Growing: the result contains the input and stays within delta + tolerance of it.
TEST(OffsetRegionsProperty, GrowStaysNearExactOffset)
{
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 20; ++round) {
        const Region input = randomRegion(rng).normalized();
        const double delta = 0.5 + 5 * unit(rng);
        const double tol = 0.01;
        SCOPED_TRACE(round);
        const std::vector<Region> result = offsetRegions({input}, delta, tol);
        ASSERT_FALSE(result.empty());
        for (const Vec2& p : t::samples(input.outer, 20))
            EXPECT_TRUE(anyContains(result, p));
        for (const Region& region : result)
            for (const Vec2& p : t::samples(region.outer, 20)) {
                EXPECT_FALSE(input.contains(p));
                EXPECT_NEAR(input.distanceToBoundary(p), delta, tol);
            }
        const auto [referenceArea, perimeter] = referenceOffset(input, delta);
        EXPECT_NEAR(totalArea(result), referenceArea, perimeter * tol);
    }
}
