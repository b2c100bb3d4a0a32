#include "HoleTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <limits>

namespace camwb::ops::test {

double uniform(std::mt19937& random, double low, double high)
{
    // Not std::uniform_real_distribution: its sequence differs between standard libraries.
    return low + (high - low) * (random() / 4294967296.0);
}

std::vector<geom::Hole> randomHoles(std::mt19937& random, int count, double minDiameter, double maxDiameter)
{
    std::vector<geom::Hole> holes;
    while (static_cast<int>(holes.size()) < count) {
        geom::Hole hole;
        hole.faceIndex = static_cast<int>(holes.size()) + 1;
        hole.center = {uniform(random, -150, 150), uniform(random, -150, 150)};
        hole.diameterMm = uniform(random, minDiameter, maxDiameter);
        hole.topZ = uniform(random, -5, 5);
        hole.bottomZ = hole.topZ - uniform(random, 0.2, 25);
        hole.through = random() % 2 == 0;
        bool overlaps = false;
        for (const geom::Hole& other : holes)
            overlaps |= base::distance(other.center, hole.center) < (other.diameterMm + hole.diameterMm) / 2 + 1;
        if (!overlaps)
            holes.push_back(hole);
    }
    return holes;
}

ToolController toolController(double diameterMm)
{
    ToolController tc;
    tc.tool.number = 4;
    tc.tool.name = "test tool";
    tc.tool.diameterMm = diameterMm;
    tc.spindleRpm = 3000;
    tc.cuttingFeedMmPerMin = 600;
    tc.plungeFeedMmPerMin = 150;
    tc.rampFeedMmPerMin = 300;
    return tc;
}

const geom::Hole& holeAround(const std::vector<geom::Hole>& holes, base::Vec2 p)
{
    auto outside = [&](const geom::Hole& hole) { return base::distance(hole.center, p) - hole.diameterMm / 2; };
    const geom::Hole* best = &holes.front();
    for (const geom::Hole& hole : holes)
        if (outside(hole) < outside(*best))
            best = &hole;
    return *best;
}

void expectProgressAndCancel(const std::function<base::Result<OpResult>(const Progress&)>& compute,
                             std::size_t holeCount, const std::string& what)
{
    std::vector<double> reported;
    std::atomic<bool> cancel = false;
    const Progress progress{[&](double f) { reported.push_back(f); }, &cancel};
    ASSERT_TRUE(compute(progress));
    EXPECT_EQ(reported.size(), holeCount + 1);
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_EQ(reported.back(), 1);
    cancel = true;
    auto result = compute(progress);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().message, what + ": cancelled");
}

}  // namespace camwb::ops::test
