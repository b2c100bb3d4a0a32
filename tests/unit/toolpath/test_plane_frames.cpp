// Working planes from a normal and from spatial angles, and the angles back: the same plane
// whichever way it was given, and the frames' points where they are on the workpiece.
#include "toolpath/PlaneFrames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace camwb::toolpath;

namespace {

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace

TEST(PlaneFrames, SpatialAnglesTurnAboutTheFixedAxesXThenYThenZ)
{
    // A 90 about X alone: the tool axis (frame z) turns from +Z to -Y, the frame's y to +Z.
    const WorkingPlane a = planeFromSpatialAngles(90, 0, 0);
    expectNear(a.xAxis, {1, 0, 0});
    expectNear(a.zAxis, {0, -1, 0});
    expectNear(a.yAxis(), {0, 0, 1});
    // B 30 alone: z tilts towards +X.
    const WorkingPlane b = planeFromSpatialAngles(0, 30, 0);
    expectNear(b.zAxis, {0.5, 0, std::sqrt(3) / 2});
    // A 90 then C 90 about the fixed Z: the tool axis -Y turns on to +X.
    const WorkingPlane ac = planeFromSpatialAngles(90, 0, 90);
    expectNear(ac.zAxis, {1, 0, 0});
    expectNear(ac.xAxis, {0, 1, 0});
    // A point of the frame, in the workpiece and back.
    const WorkingPlane shifted = planeFromSpatialAngles(0, 30, 0, {10, 0, 5});
    expectNear(shifted.toWorkpiece({0, 0, 2}), {11, 0, 5 + std::sqrt(3)});
    expectNear(shifted.toLocal(shifted.toWorkpiece({3, -4, 7})), {3, -4, 7});
    EXPECT_FALSE(planeFromSpatialAngles(0, 0, 0).tilted());
}

TEST(PlaneFrames, AnglesBackFromTheirPlane)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(-179, 179), tilt(-89, 89);
    for (int i = 0; i < 2000; ++i) {
        const double a = angle(random), b = tilt(random), c = angle(random);
        const auto back = spatialAngles(planeFromSpatialAngles(a, b, c));
        EXPECT_NEAR(back[0], a, 1e-9);
        EXPECT_NEAR(back[1], b, 1e-9);
        EXPECT_NEAR(back[2], c, 1e-9);
    }
    // B = 90: A and C turn about one line; A is 0 and C carries it, the same plane.
    const WorkingPlane gimbal = planeFromSpatialAngles(30, 90, 10);
    const auto angles = spatialAngles(gimbal);
    EXPECT_EQ(angles[0], 0);
    EXPECT_NEAR(angles[1], 90, 1e-9);
    const WorkingPlane again = planeFromSpatialAngles(angles[0], angles[1], angles[2]);
    expectNear(again.xAxis, gimbal.xAxis, 1e-9);
    expectNear(again.zAxis, gimbal.zAxis, 1e-9);
}

TEST(PlaneFrames, AlongANormalKeepsTheWorkpieceXWherePossible)
{
    const WorkingPlane p = planeAlong({0, -2, 2});  // a face leaning towards -Y at 45 degrees
    expectNear(p.zAxis, {0, -std::sqrt(0.5), std::sqrt(0.5)});
    expectNear(p.xAxis, {1, 0, 0});
    const auto angles = spatialAngles(p);
    EXPECT_NEAR(angles[0], 45, 1e-12);  // A 45 turns Z towards -Y
    EXPECT_NEAR(angles[1], 0, 1e-12);
    EXPECT_NEAR(angles[2], 0, 1e-12);
    const WorkingPlane alongX = planeAlong({1, 0, 0});
    expectNear(alongX.xAxis, {0, 1, 0});
    EXPECT_NEAR(alongX.xAxis.dot(alongX.zAxis), 0, 1e-15);
    EXPECT_FALSE(planeAlong({0, 0, 5}).tilted());
}
