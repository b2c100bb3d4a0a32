// The hole order: nearest neighbour then 2-opt on an open path from a start point.
#include "HoleTestSupport.h"
#include "ops/DrillOp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>

using namespace camwb;
using ops::test::uniform;

namespace {

double pathLength(const std::vector<base::Vec2>& points, base::Vec2 start, const std::vector<int>& order)
{
    double length = 0;
    base::Vec2 at = start;
    for (int i : order) {
        length += base::distance(at, points[i]);
        at = points[i];
    }
    return length;
}

// Nearest neighbour alone, written again here so that the test does not trust the code under test.
std::vector<int> nearestNeighbour(const std::vector<base::Vec2>& points, base::Vec2 start)
{
    std::vector<int> order;
    std::vector<bool> used(points.size());
    base::Vec2 at = start;
    for (std::size_t k = 0; k < points.size(); ++k) {
        int best = -1;
        for (std::size_t i = 0; i < points.size(); ++i)
            if (!used[i] && (best < 0 || base::distance(at, points[i]) < base::distance(at, points[best])))
                best = static_cast<int>(i);
        used[best] = true;
        order.push_back(best);
        at = points[best];
    }
    return order;
}

bool isPermutation(std::vector<int> order, std::size_t n)
{
    std::sort(order.begin(), order.end());
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    return order == identity;
}

}  // namespace

TEST(ShortRapidOrder, NeverLongerThanNearestNeighbourAndNoReversalHelps)
{
    std::mt19937 random(31);
    int shorter = 0;  // trials where 2-opt improved on nearest neighbour
    for (int trial = 0; trial < 400; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const int n = 1 + static_cast<int>(random() % 60);
        std::vector<base::Vec2> points;
        for (int i = 0; i < n; ++i)
            points.push_back({uniform(random, -100, 100), uniform(random, -100, 100)});
        const base::Vec2 start{uniform(random, -120, 120), uniform(random, -120, 120)};
        const std::vector<int> order = ops::shortRapidOrder(points, start);
        ASSERT_TRUE(isPermutation(order, points.size()));
        const double length = pathLength(points, start, order);
        const double nearestNeighbourLength = pathLength(points, start, nearestNeighbour(points, start));
        EXPECT_LE(length, nearestNeighbourLength + 1e-9);
        shorter += length < nearestNeighbourLength - 1e-6;
        // 2-opt's fixed point: reversing any stretch makes the path no shorter.
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                std::vector<int> reversed = order;
                std::reverse(reversed.begin() + i, reversed.begin() + j + 1);
                EXPECT_GE(pathLength(points, start, reversed), length - 1e-6);
            }
    }
    EXPECT_GT(shorter, 200);  // 2-opt is not idle: it shortens most random sets
}

TEST(ShortRapidOrder, FindsTheSerpentineOnAGrid)
{
    // 7 x 5 holes 10 mm apart, given in shuffled order, start off each corner in turn: the
    // shortest path steps 10 mm each time (a serpentine), whatever the input order.
    std::vector<base::Vec2> grid;
    for (int row = 0; row < 5; ++row)
        for (int column = 0; column < 7; ++column)
            grid.push_back({10.0 * column, 10.0 * row});
    std::mt19937 random(3);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<base::Vec2> points = grid;
        std::shuffle(points.begin(), points.end(), random);
        const base::Vec2 corner{trial % 2 ? 60.0 : 0.0, trial % 4 < 2 ? 0.0 : 40.0};
        const base::Vec2 start = corner + base::Vec2{trial % 2 ? 6.0 : -6.0, trial % 4 < 2 ? -8.0 : 8.0};
        const std::vector<int> order = ops::shortRapidOrder(points, start);
        ASSERT_TRUE(isPermutation(order, points.size()));
        EXPECT_EQ(points[order.front()], corner);
        for (std::size_t k = 1; k < order.size(); ++k)
            EXPECT_DOUBLE_EQ(base::distance(points[order[k - 1]], points[order[k]]), 10) << "trial " << trial;
    }
}

TEST(ShortRapidOrder, EmptyAndSingle)
{
    EXPECT_TRUE(ops::shortRapidOrder({}, {0, 0}).empty());
    EXPECT_EQ(ops::shortRapidOrder({{5, 5}}, {0, 0}), std::vector<int>{0});
}
