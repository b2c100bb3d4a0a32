// Open-chain offsets: lines stay lines, arcs stay arcs, convex corners get arcs, concave ones are
// trimmed, the ends are offset sideways; a property check over generated chains.
#include "geom/ChainOffset.h"
#include "../GeomTestUtil.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

using namespace camwb::geom;
using namespace camwb::geom::test;
constexpr double kPi = std::numbers::pi;

namespace {

Profile openPolyline(const std::vector<Vec2>& pts)
{
    Profile p;
    p.closed = false;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        p.segments.push_back(Segment::line(pts[i], pts[i + 1]));
    return p;
}

// An x-monotone chain with gentle turns, some of its steps bulged into arcs, so that no part of
// it comes back near another (the offset stays exactly `d` from the chain).
Profile randomChain(std::mt19937& rng)
{
    std::uniform_real_distribution<double> step(12, 25), slope(-0.6, 0.6), bulge(-0.25, 0.25), coin(0, 1);
    std::uniform_int_distribution<int> count(2, 7);
    Profile p;
    p.closed = false;
    Vec2 at{0, 0};
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
        const double dx = step(rng);
        const Vec2 next{at.x + dx, at.y + dx * slope(rng)};
        if (coin(rng) < 0.4) {
            // Centre on the bisector; the sagitta is a fraction of the chord.
            const Vec2 mid = (at + next) * 0.5;
            const double chord = distance(at, next);
            const double sag = bulge(rng) * chord;
            if (std::abs(sag) < 0.5) {
                p.segments.push_back(Segment::line(at, next));
            } else {
                const double r = (chord * chord / 4 + sag * sag) / (2 * std::abs(sag));
                const Vec2 normal = (next - at).normalized().leftNormal();
                // sag > 0: the arc bulges to the left (clockwise travel), centre to the right.
                const Vec2 centre = mid - normal * ((r - std::abs(sag)) * (sag > 0 ? 1 : -1));
                p.segments.push_back(Segment::arc(at, next, centre, sag < 0));
            }
        } else {
            p.segments.push_back(Segment::line(at, next));
        }
        at = next;
    }
    return p;
}

}  // namespace

TEST(ChainOffset, LShapeLeftAndRight)
{
    const Profile chain = openPolyline({{0, 0}, {40, 0}, {40, 30}});  // turns left at (40, 0)
    auto left = offsetChain(chain, ChainSide::Left, 2);
    ASSERT_TRUE(left.ok()) << left.error().message;
    // Left of a left turn is the concave side: trimmed, two lines, no arc.
    ASSERT_EQ(left.value().segments.size(), 2u);
    EXPECT_FALSE(left.value().closed);
    EXPECT_EQ(countArcs(left.value()), 0u);
    EXPECT_NEAR(distance(left.value().segments[0].start, {0, 2}), 0, 1e-12);
    EXPECT_NEAR(distance(left.value().segments[0].end, {38, 2}), 0, 1e-12);
    EXPECT_NEAR(distance(left.value().segments[1].end, {38, 30}), 0, 1e-12);

    auto right = offsetChain(chain, ChainSide::Right, 2);
    ASSERT_TRUE(right.ok()) << right.error().message;
    const Profile& r = right.value();
    ASSERT_EQ(r.segments.size(), 3u);  // line, corner arc, line
    ASSERT_TRUE(r.segments[1].isArc());
    EXPECT_TRUE(r.segments[1].ccw);
    EXPECT_NEAR(distance(r.segments[1].center, {40, 0}), 0, 1e-12);
    EXPECT_NEAR(r.segments[1].radius(), 2, 1e-12);
    EXPECT_NEAR(distance(r.segments[0].start, {0, -2}), 0, 1e-12);
    EXPECT_NEAR(distance(r.segments[2].end, {42, 30}), 0, 1e-12);
    EXPECT_TRUE(r.isContinuous(1e-9));
}

TEST(ChainOffset, ArcsStayArcsWithRadiusChanged)
{
    Profile chain;
    chain.closed = false;
    chain.segments = {Segment::line({-10, 10}, {0, 10}), Segment::arc({0, 10}, {10, 0}, {0, 0}, false),
                      Segment::line({10, 0}, {10, -10})};
    for (auto [side, radius] : {std::pair{ChainSide::Left, 13.0}, std::pair{ChainSide::Right, 7.0}}) {
        auto off = offsetChain(chain, side, 3);
        ASSERT_TRUE(off.ok()) << off.error().message;
        ASSERT_EQ(off.value().segments.size(), 3u);  // tangent joints: nothing inserted
        EXPECT_TRUE(off.value().segments[1].isArc());
        EXPECT_NEAR(off.value().segments[1].radius(), radius, 1e-12);
        EXPECT_FALSE(off.value().segments[1].ccw);
    }
    // 10.5 mm to the centre side of a 10 mm arc: nothing left of it.
    auto tooFar = offsetChain(chain, ChainSide::Right, 10.5);
    ASSERT_FALSE(tooFar.ok());
    EXPECT_NE(tooFar.error().message.find("tool too large for the concave arc of radius 10"), std::string::npos)
        << tooFar.error().message;
}

TEST(ChainOffset, Errors)
{
    const Profile chain = openPolyline({{0, 0}, {40, 0}, {40, 30}});
    EXPECT_FALSE(offsetChain(chain, ChainSide::Left, 0).ok());
    EXPECT_FALSE(offsetChain(chain, ChainSide::Left, -1).ok());
    EXPECT_FALSE(offsetChain(Profile{{}, false}, ChainSide::Left, 1).ok());
    Profile gap = chain;
    gap.segments[1].start = {40, 1};
    auto r = offsetChain(gap, ChainSide::Left, 1);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("discontinuous"), std::string::npos);
    // A short step between two left turns vanishes on the left at 3 mm.
    auto narrow = offsetChain(openPolyline({{0, 0}, {40, 0}, {40, 4}, {0, 4}}), ChainSide::Left, 3);
    ASSERT_FALSE(narrow.ok());
    EXPECT_NE(narrow.error().message.find("tool too large"), std::string::npos) << narrow.error().message;
    auto back = offsetChain(openPolyline({{0, 0}, {40, 0}, {20, 0}}), ChainSide::Left, 1);
    ASSERT_FALSE(back.ok());
    EXPECT_NE(back.error().message.find("turns back"), std::string::npos);
}

TEST(ChainOffset, ClosedChainIsOffsetAsALoop)
{
    auto off = offsetChain(rectangle(0, 0, 40, 20), ChainSide::Right, 2);  // ccw: right = outside
    ASSERT_TRUE(off.ok());
    EXPECT_TRUE(off.value().closed);
    EXPECT_EQ(countArcs(off.value()), 4u);
    EXPECT_NEAR(off.value().signedArea(), 40 * 20 + 2 * 2 * (40 + 20) + kPi * 4, 1e-9);
}

TEST(ChainOffsetProperty, EveryPointAtTheDistanceEndsSideways)
{
    std::mt19937 rng(4242);
    int checked = 0;
    for (int i = 0; i < 40; ++i) {
        const Profile chain = randomChain(rng);
        ASSERT_TRUE(chain.isContinuous(1e-9));
        for (ChainSide side : {ChainSide::Left, ChainSide::Right})
            for (double d : {0.5, 2.0, 4.0}) {
                SCOPED_TRACE("chain " + std::to_string(i) + (side == ChainSide::Left ? " left " : " right ") +
                             std::to_string(d));
                auto off = offsetChain(chain, side, d);
                if (!off.ok()) {
                    // Only a concave arc too tight for the distance may refuse.
                    EXPECT_NE(off.error().message.find("concave arc"), std::string::npos) << off.error().message;
                    continue;
                }
                const Profile& o = off.value();
                EXPECT_TRUE(o.isContinuous(1e-9));
                EXPECT_FALSE(o.closed);
                EXPECT_GE(countArcs(o), countArcs(chain));
                for (const Vec2& p : discretize(o, 0.01))
                    EXPECT_NEAR(distanceToProfile(p, chain), d, 1e-6) << p.x << ", " << p.y;
                // Ends sideways from the chain's ends, on the chosen side.
                const Segment& first = chain.segments.front();
                const Vec2 n =
                    side == ChainSide::Left ? first.startTangent().leftNormal() : first.startTangent().rightNormal();
                EXPECT_NEAR(distance(o.segments.front().start, first.start + n * d), 0, 1e-9);
                ++checked;
            }
    }
    EXPECT_GT(checked, 180);
}
