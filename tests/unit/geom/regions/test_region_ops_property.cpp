// Property tests over generated regions: booleans agree with point classification and with a fine
// Clipper reference area; clipPolylines keeps exactly the inside parts, in order and direction;
// segmentInside agrees with dense sampling wherever sampling is unambiguous, and RegionIndex gives
// the answers of anyContains and segmentInside.
#include "RegionTestUtil.h"
#include "geom/RegionIndex.h"
#include "geom/RegionOps.h"

#include <gtest/gtest.h>
#include <polyclipping/clipper.hpp>

#include <random>
#include <thread>

using namespace camwb::geom;
namespace t = camwb::geom::test;

namespace {

Region shifted(Region region, Vec2 by)
{
    auto move = [by](Profile& p) {
        for (Segment& s : p.segments) {
            s.start = s.start + by;
            s.end = s.end + by;
            s.center = s.center + by;
        }
    };
    move(region.outer);
    for (Profile& hole : region.holes)
        move(hole);
    return region;
}

ClipperLib::Paths finePaths(const Region& region)
{
    ClipperLib::Paths paths;
    std::vector<Profile> loops{region.outer};
    loops.insert(loops.end(), region.holes.begin(), region.holes.end());
    for (const Profile& loop : loops) {
        ClipperLib::Path& path = paths.emplace_back();
        for (const Vec2& p : discretize(loop, 1e-4))
            path.push_back({std::llround(p.x * 1e6), std::llround(p.y * 1e6)});
    }
    return paths;
}

double referenceArea(const Region& a, const Region& b, ClipperLib::ClipType type)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(finePaths(a), ClipperLib::ptSubject, true);
    clipper.AddPaths(finePaths(b), ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double area = 0;
    for (const ClipperLib::Path& path : out)
        area += ClipperLib::Area(path) / 1e12;
    return area;
}

double perimeter(const Region& region)
{
    double total = region.outer.length();
    for (const Profile& hole : region.holes)
        total += hole.length();
    return total;
}

std::vector<Vec2> randomWalk(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vec2> walk{{100 * unit(rng), 100 * unit(rng)}};
    const int n = 2 + static_cast<int>(unit(rng) * 8);
    for (int i = 0; i < n; ++i)
        walk.push_back({100 * unit(rng), 100 * unit(rng)});
    return walk;
}

// Position of q along the polyline (arc length of its nearest point).
double positionAlong(const std::vector<Vec2>& polyline, Vec2 q)
{
    double best = 1e300, at = 0, walked = 0;
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
        const Vec2 d = polyline[i + 1] - polyline[i];
        const double len = d.length();
        const double u = std::clamp((q - polyline[i]).dot(d) / (len * len), 0.0, 1.0);
        const double dist = distance(q, polyline[i] + d * u);
        if (dist < best - 1e-9) {
            best = dist;
            at = walked + u * len;
        }
        walked += len;
    }
    return at;
}

}  // namespace

TEST(RegionBooleansProperty, ClassifyPointsAndMatchReferenceAreas)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0, 1);
    const double tol = 0.005;
    for (int round = 0; round < 25; ++round) {
        SCOPED_TRACE(round);
        const Region a = t::randomRegion(rng).normalized();
        const Region b = shifted(t::randomRegion(rng), {40 * unit(rng) - 20, 40 * unit(rng) - 20}).normalized();
        const std::vector<Region> united = unite({a}, {b}, tol);
        const std::vector<Region> difference = subtract({a}, {b}, tol);
        const std::vector<Region> common = intersect({a}, {b}, tol);
        const double slack = (perimeter(a) + perimeter(b)) * tol;
        EXPECT_NEAR(totalArea(united), referenceArea(a, b, ClipperLib::ctUnion), slack);
        EXPECT_NEAR(totalArea(difference), referenceArea(a, b, ClipperLib::ctDifference), slack);
        EXPECT_NEAR(totalArea(common), referenceArea(a, b, ClipperLib::ctIntersection), slack);
        for (int i = 0; i < 400; ++i) {
            const Vec2 p{-30 + 160 * unit(rng), -30 + 160 * unit(rng)};
            if (a.distanceToBoundary(p) < 2 * tol || b.distanceToBoundary(p) < 2 * tol)
                continue;
            const bool inA = a.contains(p), inB = b.contains(p);
            ASSERT_EQ(anyContains(united, p), inA || inB) << p.x << " " << p.y;
            ASSERT_EQ(anyContains(difference, p), inA && !inB) << p.x << " " << p.y;
            ASSERT_EQ(anyContains(common, p), inA && inB) << p.x << " " << p.y;
        }
    }
}

TEST(ClipPolylinesProperty, KeepsExactlyTheInsideInOrder)
{
    std::mt19937 rng(11);
    for (int round = 0; round < 30; ++round) {
        SCOPED_TRACE(round);
        const std::vector<Region> regions{t::randomRegion(rng).normalized()};
        const std::vector<std::vector<Vec2>> walks{randomWalk(rng), randomWalk(rng), randomWalk(rng)};
        const auto pieces = clipPolylines(walks, regions, 0.01);
        // Every piece lies inside; pieces follow the walks in order and direction.
        std::size_t walk = 0;
        double lastPosition = -1;
        double clippedLength = 0;
        for (const std::vector<Vec2>& piece : pieces) {
            ASSERT_GE(piece.size(), 2u);
            for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
                clippedLength += distance(piece[i], piece[i + 1]);
                for (int k = 0; k <= 10; ++k) {
                    const Vec2 q = piece[i] + (piece[i + 1] - piece[i]) * (k / 10.0);
                    ASSERT_TRUE(anyContains(regions, q) || regions[0].distanceToBoundary(q) < 1e-7);
                }
            }
            // Find the walk this piece belongs to (the current one or a later one).
            while (walk < walks.size() && t::distanceToPolyline(piece.front(), walks[walk], false) > 1e-9) {
                ++walk;
                lastPosition = -1;
            }
            ASSERT_LT(walk, walks.size());
            const double from = positionAlong(walks[walk], piece.front());
            const double to = positionAlong(walks[walk], piece.back());
            EXPECT_GE(from, lastPosition - 1e-9);
            EXPECT_GT(to, from);
            lastPosition = to;
        }
        // The inside length by dense sampling matches the pieces' length.
        double sampledLength = 0;
        const double step = 0.02;
        for (const std::vector<Vec2>& w : walks)
            for (std::size_t i = 0; i + 1 < w.size(); ++i) {
                const double len = distance(w[i], w[i + 1]);
                const int n = static_cast<int>(len / step) + 1;
                for (int k = 0; k < n; ++k)
                    if (anyContains(regions, w[i] + (w[i + 1] - w[i]) * ((k + 0.5) / n)))
                        sampledLength += len / n;
            }
        EXPECT_NEAR(clippedLength, sampledLength, 0.2);
    }
}

TEST(SegmentInsideProperty, AgreesWithDenseSampling)
{
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0, 1);
    int decided = 0, insideCount = 0;
    for (int round = 0; round < 10; ++round) {
        const std::vector<Region> regions{t::randomRegion(rng).normalized()};
        for (int i = 0; i < 100; ++i) {
            const Vec2 a{100 * unit(rng), 100 * unit(rng)};
            const Vec2 b = a + Vec2{20 * unit(rng) - 10, 20 * unit(rng) - 10};
            // Samples 0.01 apart: a crossing lies within 0.005 of a sample, so "every sample
            // inside and farther than 0.01 from the boundary" means no crossing.
            bool clearlyOutside = false, clearlyInside = true;
            const int n = static_cast<int>(distance(a, b) / 0.01) + 2;
            for (int k = 0; k <= n; ++k) {
                const Vec2 q = a + (b - a) * (static_cast<double>(k) / n);
                const bool near = regions[0].distanceToBoundary(q) < 0.01;
                const bool in = regions[0].contains(q);
                clearlyOutside = clearlyOutside || (!in && !near);
                clearlyInside = clearlyInside && in && !near;
            }
            if (!clearlyInside && !clearlyOutside)
                continue;
            ++decided;
            insideCount += clearlyInside;
            ASSERT_EQ(segmentInside(a, b, regions), clearlyInside) << a.x << "," << a.y << " " << b.x << "," << b.y;
        }
    }
    EXPECT_GT(decided, 900);
    EXPECT_GT(insideCount, 150);
}

TEST(RegionIndexProperty, AnswersAsTheLoopScans)
{
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0, 1);
    int inside = 0, links = 0;
    for (int round = 0; round < 10; ++round) {
        // Two regions, one with islands, and the points and links round them.
        const std::vector<Region> regions{t::randomRegion(rng).normalized(),
                                          shifted(t::randomRegion(rng).normalized(), {110, 0})};
        const RegionIndex index(regions);
        for (int i = 0; i < 300; ++i) {
            const Vec2 a{210 * unit(rng), 100 * unit(rng)};
            // Ends on loop vertices too: touching counts as inside, in both.
            const Vec2 b =
                i % 10 == 0 ? regions[0].outer.segments[0].start : a + Vec2{30 * unit(rng) - 15, 30 * unit(rng) - 15};
            ASSERT_EQ(index.contains(a), anyContains(regions, a)) << a.x << "," << a.y;
            const bool expected = segmentInside(a, b, regions);
            ASSERT_EQ(index.segmentInside(a, b), expected) << a.x << "," << a.y << " " << b.x << "," << b.y;
            inside += index.contains(a);
            links += expected;
        }
    }
    EXPECT_GT(inside, 500);
    EXPECT_GT(links, 200);
}

// Threads share one index (the waterline's levels ask it on all cores): every thread gets the
// answers one thread got alone.
TEST(RegionIndexProperty, ThreadsShareOneIndex)
{
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::vector<Region> regions{t::randomRegion(rng).normalized(),
                                      shifted(t::randomRegion(rng).normalized(), {110, 0})};
    const RegionIndex index(regions);
    std::vector<Vec2> from, to;
    std::vector<char> inside, linked;
    for (int i = 0; i < 4000; ++i) {
        from.push_back({210 * unit(rng), 100 * unit(rng)});
        to.push_back(from.back() + Vec2{30 * unit(rng) - 15, 30 * unit(rng) - 15});
        inside.push_back(index.contains(from.back()));
        linked.push_back(index.segmentInside(from.back(), to.back()));
    }
    std::vector<int> wrong(4, 0);
    std::vector<std::thread> threads;
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (int round = 0; round < 5; ++round)
                for (std::size_t i = 0; i < from.size(); ++i)
                    wrong[k] += index.contains(from[i]) != bool(inside[i]) ||
                                index.segmentInside(from[i], to[i]) != bool(linked[i]);
        });
    for (std::thread& thread : threads)
        thread.join();
    EXPECT_EQ(wrong, std::vector<int>(4, 0));
    EXPECT_GT(std::count(inside.begin(), inside.end(), 1), 500);
}

// Forty nested rings: a point in the middle lies beyond forty loops, each crossed once, more than
// the index keeps on the stack.
TEST(RegionIndexProperty, ManyNestedLoopsAtOnePoint)
{
    std::vector<Profile> loops;
    for (int i = 0; i < 40; ++i)
        loops.push_back(t::circle({0, 0}, 100 - 2 * i));
    const std::vector<Region> regions = regionsFromLoops(loops, 0.01);
    ASSERT_EQ(regions.size(), 20u);
    const RegionIndex index(regions);
    for (double x = 0; x < 101; x += 0.5) {
        const Vec2 p{x, 0.25};
        ASSERT_EQ(index.contains(p), anyContains(regions, p)) << x;
    }
    EXPECT_FALSE(index.contains({0, 0.25}));  // within the innermost circle: a hole
    EXPECT_TRUE(index.contains({23, 0.25}));  // between the innermost outer loop (r 24) and its hole
}

TEST(RegionsFromLoopsProperty, NestedRingsAlternate)
{
    // Concentric circles and rounded squares alternately: even depth outer, odd depth hole.
    std::vector<Profile> loops;
    for (int i = 0; i < 6; ++i) {
        const double r = 60 - 9 * i;
        loops.push_back(i % 2 ? t::circle({0, 0}, r) : t::roundedRectangle(-r, -r, 2 * r, 2 * r, r / 3).reversed());
    }
    std::shuffle(loops.begin(), loops.end(), std::mt19937(3));
    const std::vector<Region> regions = regionsFromLoops(loops, 0.01);
    ASSERT_EQ(regions.size(), 3u);
    for (const Region& region : regions) {
        EXPECT_EQ(region.holes.size(), 1u);
        EXPECT_GT(region.outer.signedArea(), 0);
        EXPECT_LT(region.holes[0].signedArea(), 0);
    }
    for (int i = 0; i < 6; ++i) {
        // Between ring i and ring i+1 (on the +x axis, past the rounded corners).
        const Vec2 p{60 - 9 * i - 4.5, 0};
        EXPECT_EQ(anyContains(regions, p), i % 2 == 0) << i;
    }
}
