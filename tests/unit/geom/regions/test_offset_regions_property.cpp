// Property test of offsetRegions over generated shapes (rounded rectangles and star polygons with
// bulged arc edges, islands of circles and rounded rectangles): a shrink never comes closer than
// |delta| to the exact input loops, stays inside the input, and loses little area against a fine
// Clipper offset of a finely discretised input (less than perimeter * 2 * tolerance). The exact
// line/arc offset: its loops lie at exactly the offset distance from the input, ring after ring,
// with the same loops (outer and holes) as the fine Clipper offset.
#include "RegionTestUtil.h"
#include "geom/RegionOps.h"

#include <gtest/gtest.h>
#include <polyclipping/clipper.hpp>

#include <random>

using namespace camwb::geom;
namespace t = camwb::geom::test;

namespace {

struct Reference {
    double area = 0, perimeter = 0;
    int outerLoops = 0, holes = 0;
};

// A Clipper offset of the input discretised to 0.1 um chords: its area (the exact offset's area
// to within ~perimeter * 1e-4), perimeter and loops.
Reference reference(const Region& region, double delta)
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
    Reference ref;
    for (const ClipperLib::Path& path : out) {
        const double area = ClipperLib::Area(path) / 1e12;
        ref.area += area;
        ++(area > 0 ? ref.outerLoops : ref.holes);
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto& a = path[i];
            const auto& b = path[(i + 1) % path.size()];
            ref.perimeter += std::hypot(static_cast<double>(a.X - b.X), static_cast<double>(a.Y - b.Y)) / 1e6;
        }
    }
    return ref;
}

std::pair<double, double> referenceOffset(const Region& region, double delta)
{
    const Reference ref = reference(region, delta);
    return {ref.area, ref.perimeter};
}

// The largest difference between `distance` and the distance of a point of the result's loops
// from the input's loops.
double worstDistanceError(const Region& input, const std::vector<Region>& result, double distance)
{
    double worst = 0;
    for (const Region& region : result) {
        std::vector<Profile> loops{region.outer};
        loops.insert(loops.end(), region.holes.begin(), region.holes.end());
        for (const Profile& loop : loops)
            for (const Vec2& p : t::samples(loop, 16))
                worst = std::max(worst, std::abs(input.distanceToBoundary(p) - distance));
    }
    return worst;
}

// Checks one offset of `input` against the fine Clipper offset by the same distance; true when
// every point of it lies at the distance to within 1e-6 mm (exact lines and arcs).
bool checkExactOffset(const Region& input, const std::vector<Region>& result, double delta, double tol)
{
    const double distance = delta < 0 ? -delta + offsetSafetyMargin(tol) : delta;
    const Reference ref = reference(input, delta < 0 ? -distance : distance);
    int outerLoops = 0, holes = 0;
    for (const Region& region : result) {
        ++outerLoops;
        holes += static_cast<int>(region.holes.size());
        EXPECT_TRUE(region.outer.isContinuous(1e-9));
    }
    EXPECT_EQ(outerLoops, ref.outerLoops);
    EXPECT_EQ(holes, ref.holes);
    EXPECT_NEAR(totalArea(result), ref.area, ref.perimeter * 1e-3 + 1e-9);
    const double worst = worstDistanceError(input, result, distance);
    EXPECT_LE(worst, tol);
    return worst <= 1e-6;
}

}  // namespace

TEST(OffsetRegionsProperty, ShrinkKeepsDistanceAndArea)
{
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> unit(0, 1);
    const double tolerances[] = {0.001, 0.005, 0.01, 0.03};
    int nonEmpty = 0;
    for (int round = 0; round < 60; ++round) {
        const Region input = t::randomRegion(rng).normalized();
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
        const Region input = t::randomRegion(rng).normalized();
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

// Shrinks and grows by any distance: the loops lie exactly at the distance (no discretisation or
// arc fitting left in them) and are the loops Clipper finds.
TEST(OffsetRegionsProperty, ExactLinesAndArcsAtTheDistance)
{
    std::mt19937 rng(314);
    std::uniform_real_distribution<double> unit(0, 1);
    const double tolerances[] = {0.001, 0.01, 0.03};
    int exact = 0;
    const int rounds = 60;
    for (int round = 0; round < rounds; ++round) {
        const Region input = t::randomRegion(rng).normalized();
        const double delta = (round % 3 == 2 ? 1 : -1) * (0.3 + 6 * unit(rng));
        const double tol = tolerances[round % 3];
        SCOPED_TRACE("round " + std::to_string(round) + " delta " + std::to_string(delta));
        exact += checkExactOffset(input, offsetRegions({input}, delta, tol), delta, tol);
    }
    EXPECT_GE(exact, rounds - 1);  // a contour may be fitted where a crossing is not found again
}

// Ring after ring as the pocket's offset pattern takes them (each ring the offset of the one
// before, split regions followed separately): every ring exact against its own input.
TEST(OffsetRegionsProperty, ChainedRingsStayExact)
{
    std::mt19937 rng(2718);
    const double tol = 0.01, step = 0.9;
    int rings = 0, exact = 0;
    for (int round = 0; round < 8; ++round) {
        std::vector<Region> pending = offsetRegions({t::randomRegion(rng).normalized()}, -3, tol);
        while (!pending.empty() && rings < 400) {
            const Region input = pending.back();
            pending.pop_back();
            SCOPED_TRACE("round " + std::to_string(round) + " ring " + std::to_string(rings));
            const std::vector<Region> next = offsetRegions({input}, -step, tol);
            ++rings;
            exact += checkExactOffset(input, next, -step, tol);
            pending.insert(pending.end(), next.begin(), next.end());
        }
    }
    EXPECT_GT(rings, 100);
    EXPECT_GE(exact, rings - rings / 50);
}
