// fitLinesAndArcs: lines and arcs restored from sampled shapes, the tolerance kept both ways,
// segments ending on polyline vertices, closed loops split at corners.
#include "RegionTestUtil.h"
#include "geom/ArcFit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>

using namespace camwb::geom;
namespace t = camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

std::vector<Vec2> arcPoints(Vec2 c, double r, double a0, double a1, int n)
{
    std::vector<Vec2> pts;
    for (int i = 0; i <= n; ++i) {
        const double a = a0 + (a1 - a0) * i / n;
        pts.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
    }
    return pts;
}

// Every polyline point near the profile and every profile point near the polyline.
void expectWithin(const std::vector<Vec2>& pts, bool closed, const Profile& fit, double tol)
{
    double worstPoint = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        worstPoint = std::max(worstPoint, distanceToProfile(pts[i], fit));
        const Vec2 mid = (pts[i] + pts[(i + 1) % pts.size()]) * 0.5;
        if (closed || i + 1 < pts.size())
            worstPoint = std::max(worstPoint, distanceToProfile(mid, fit));
    }
    EXPECT_LE(worstPoint, tol * 1.0001);
    double worstFit = 0;
    for (const Vec2& q : t::samples(fit, 16))
        worstFit = std::max(worstFit, t::distanceToPolyline(q, pts, closed));
    EXPECT_LE(worstFit, tol * 1.0001);
}

void expectOnVertices(const std::vector<Vec2>& pts, const Profile& fit)
{
    for (const Segment& s : fit.segments) {
        EXPECT_NE(std::find(pts.begin(), pts.end(), s.start), pts.end());
        EXPECT_NE(std::find(pts.begin(), pts.end(), s.end), pts.end());
    }
}

}  // namespace

TEST(ArcFit, CollinearPointsGiveOneLine)
{
    std::vector<Vec2> pts;
    for (int i = 0; i <= 100; ++i)
        pts.push_back({i * 0.5, 2.0 + i * 0.25});
    const Profile fit = fitLinesAndArcs(pts, false, 0.01);
    ASSERT_EQ(fit.segments.size(), 1u);
    EXPECT_FALSE(fit.segments[0].isArc());
    EXPECT_EQ(fit.segments[0].start, pts.front());
    EXPECT_EQ(fit.segments[0].end, pts.back());
    EXPECT_FALSE(fit.closed);
}

TEST(ArcFit, SampledArcGivesOneArcInBothDirections)
{
    const Vec2 c{3, -2};
    std::vector<Vec2> pts = arcPoints(c, 10, 0.2, 0.2 + kPi / 2, 60);
    for (bool reverse : {false, true}) {
        if (reverse)
            std::reverse(pts.begin(), pts.end());
        const Profile fit = fitLinesAndArcs(pts, false, 0.001);
        ASSERT_EQ(fit.segments.size(), 1u);
        const Segment& arc = fit.segments[0];
        ASSERT_TRUE(arc.isArc());
        EXPECT_EQ(arc.ccw, !reverse);
        EXPECT_NEAR(arc.radius(), 10, 1e-9);
        EXPECT_NEAR(distance(arc.center, c), 0, 1e-9);
        EXPECT_NEAR(std::abs(arc.sweep()), kPi / 2, 1e-9);
        expectWithin(pts, false, fit, 0.001);
    }
}

TEST(ArcFit, FullCircleBecomesSeveralArcs)
{
    std::vector<Vec2> pts = arcPoints({1, 1}, 5, 0, 2 * kPi, 200);
    pts.pop_back();  // closed: the first point is not repeated
    const Profile fit = fitLinesAndArcs(pts, true, 0.001);
    ASSERT_GE(fit.segments.size(), 2u);
    EXPECT_EQ(t::countArcs(fit), fit.segments.size());
    for (const Segment& s : fit.segments) {
        EXPECT_NE(s.start, s.end);
        EXPECT_NEAR(s.radius(), 5, 1e-9);
    }
    EXPECT_TRUE(fit.isContinuous(0));
    EXPECT_NEAR(fit.signedArea(), kPi * 25, 1e-6);
    expectWithin(pts, true, fit, 0.001);
    expectOnVertices(pts, fit);
}

TEST(ArcFit, RoundedRectangleGivesFourLinesAndFourArcs)
{
    const Profile shape = t::roundedRectangle(-5, 2, 40, 25, 6);
    // Start the samples in the middle of a corner arc: the seam must still not split it.
    std::vector<Vec2> pts = discretize(shape, 0.0005);
    std::rotate(pts.begin(), pts.begin() + 5, pts.end());
    const Profile fit = fitLinesAndArcs(pts, true, 0.002);
    EXPECT_EQ(t::countLines(fit), 4u);
    EXPECT_EQ(t::countArcs(fit), 4u);
    for (const Segment& s : fit.segments)
        if (s.isArc()) {
            EXPECT_NEAR(s.radius(), 6, 0.01);
        }
    EXPECT_TRUE(fit.isContinuous(0));
    expectWithin(pts, true, fit, 0.002);
    expectOnVertices(pts, fit);
}

TEST(ArcFit, SharpCornersStaySharp)
{
    const std::vector<Vec2> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    const Profile fit = fitLinesAndArcs(square, true, 0.01);
    ASSERT_EQ(fit.segments.size(), 4u);
    EXPECT_EQ(t::countArcs(fit), 0u);
    EXPECT_NEAR(fit.signedArea(), 100, 1e-12);
}

TEST(ArcFit, LargeRadiusBecomesLines)
{
    const std::vector<Vec2> pts = arcPoints({0, 0}, 100, 0, 0.3, 100);
    const Profile fit = fitLinesAndArcs(pts, false, 0.001, 50);
    EXPECT_EQ(t::countArcs(fit), 0u);
    expectWithin(pts, false, fit, 0.001);
}

TEST(ArcFit, DegenerateInputs)
{
    EXPECT_TRUE(fitLinesAndArcs({}, false, 0.01).empty());
    EXPECT_TRUE(fitLinesAndArcs({{1, 1}}, true, 0.01).empty());
    EXPECT_TRUE(fitLinesAndArcs({{1, 1}, {1, 1}, {1, 1}}, false, 0.01).empty());
    const Profile twoPoints = fitLinesAndArcs({{0, 0}, {0, 0}, {3, 4}}, false, 0.01);
    ASSERT_EQ(twoPoints.segments.size(), 1u);
    EXPECT_NEAR(twoPoints.length(), 5, 1e-12);
    // Zero or negative tolerance still terminates and reproduces the polyline.
    const Profile exact = fitLinesAndArcs({{0, 0}, {1, 0.1}, {2, 0}, {3, 0.2}}, false, 0);
    EXPECT_EQ(exact.segments.size(), 3u);
}

// Noisy waves with random tolerances: the tolerance holds both ways.
TEST(ArcFit, RandomWavesStayWithinTolerance)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int round = 0; round < 20; ++round) {
        const double tol = 0.001 + 0.05 * unit(rng);
        const double amplitude = 1 + 10 * unit(rng);
        const double wavelength = 5 + 40 * unit(rng);
        std::vector<Vec2> pts;
        for (int i = 0; i < 400; ++i) {
            const double x = i * 0.25;
            pts.push_back({x, amplitude * std::sin(2 * kPi * x / wavelength) + 0.2 * tol * (unit(rng) - 0.5)});
        }
        const bool closed = round % 2 == 1;
        if (closed)
            pts.push_back({50, -30});
        const Profile fit = fitLinesAndArcs(pts, closed, tol);
        SCOPED_TRACE(round);
        expectWithin(pts, closed, fit, tol);
        expectOnVertices(pts, fit);
        EXPECT_TRUE(fit.isContinuous(0));
    }
}

// 100k points (a slow spiral with straight pieces): finishes quickly (O(n log n) search) and
// still keeps the tolerance.
TEST(ArcFit, LongPolylineStaysWithinTolerance)
{
    std::vector<Vec2> pts;
    for (int i = 0; i < 100000; ++i) {
        const double a = i * 0.002;
        const double r = 50 + 0.01 * i;
        pts.push_back(i % 20000 < 4000 ? Vec2{r, a} : Vec2{r * std::cos(a), r * std::sin(a)});
    }
    const Profile fit = fitLinesAndArcs(pts, false, 0.005);
    EXPECT_LT(fit.segments.size(), 5000u);
    EXPECT_TRUE(fit.isContinuous(0));
    std::vector<Vec2> sub;
    for (std::size_t i = 30000; i < 31000; ++i)
        sub.push_back(pts[i]);
    for (const Vec2& p : sub)
        EXPECT_LE(distanceToProfile(p, fit), 0.005 * 1.0001);
}
