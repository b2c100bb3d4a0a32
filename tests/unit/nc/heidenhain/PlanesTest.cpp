// Circles of the Klartext interpreter outside the XY plane: the axes of CC (or of a CR / CT block)
// name the plane, DR+ turns by the right-hand rule about +Z, +Y or +X, polar angles count from
// X, Z or Y, CP makes a helix along the plane's normal; what is not allowed there (C moving off
// its plane, CP with an in-plane axis, RL/RR) is an error on its line, and RND/CHF are not traced.
#include "TestSupport.h"
#include "nc/ToolTable.h"
#include "toolpath/ArcGeometry.h"

#include <cmath>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

// The point half way along `arc`, which starts at `start`.
Vec3 halfWay(const Vec3& start, const Arc& arc)
{
    const auto points = linearizeArc(start, arc, 1e3, arcSweepDeg(start, arc) / 2 + 1e-9);
    EXPECT_EQ(points.size(), 2u);
    return points.front();
}

TEST(HeidenhainPlanes, QuarterCircleInZxTurnsByTheRightHandRuleAboutY)
{
    // About +Y, +X turns towards -Z: a quarter DR+ from X+10 ends at Z-10, DR- at Z+10.
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Z+0\n"
                                 "4 C X+0 Z-10 DR+ F100\n"
                                 "5 C X+10 Z+0 DR-\n"
                                 "6 C X+0 Z+10 DR-\n"
                                 "7 CP IPA+90 DR+\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 4u);
    for (const Arc& a : arcs) {
        expectNear(a.normal, {0, 1, 0});
        expectNear(a.center, {0, 0, 0});
    }
    EXPECT_FALSE(arcs[0].clockwise);
    expectNear(arcs[0].to, {0, 0, -10});
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, arcs[0]), 90, 1e-9);
    const double h = 10 / std::sqrt(2.0);
    expectNear(halfWay({10, 0, 0}, arcs[0]), {h, 0, -h}, 1e-9);
    EXPECT_TRUE(arcs[1].clockwise);
    EXPECT_NEAR(arcSweepDeg({0, 0, -10}, arcs[1]), 90, 1e-9);
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, arcs[2]), 90, 1e-9);
    expectNear(halfWay({10, 0, 0}, arcs[2]), {h, 0, h}, 1e-9);
    // CP computes its end from the angle: the right-hand rule decides where it is.
    expectNear(arcs[3].to, {10, 0, 0}, 1e-12);
    EXPECT_FALSE(arcs[3].clockwise);
}

TEST(HeidenhainPlanes, QuarterCircleInYzTurnsByTheRightHandRuleAboutX)
{
    // About +X, +Y turns towards +Z.
    const Traced r = run(program("2 L X+0 Y+10 Z+0 FMAX\n"
                                 "3 CC Y+0 Z+0\n"
                                 "4 CP IPA+90 DR+ F100\n"
                                 "5 C Y+10 Z+0 DR-\n"
                                 "6 C Y+0 Z+10 DR+\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 3u);
    expectNear(arcs[0].normal, {1, 0, 0});
    expectNear(arcs[0].to, {0, 0, 10}, 1e-12);
    EXPECT_TRUE(arcs[1].clockwise);
    EXPECT_NEAR(arcSweepDeg({0, 0, 10}, arcs[1]), 90, 1e-9);
    const double h = 10 / std::sqrt(2.0);
    expectNear(halfWay({0, 10, 0}, arcs[2]), {0, h, h}, 1e-9);
}

TEST(HeidenhainPlanes, XyStaysAsItWas)
{
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Y+0\n4 CP IPA+90 DR+ F100\n"));
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].to, {0, 10, 0}, 1e-12);
    expectNear(arcs[0].normal, {0, 0, 1});
}

TEST(HeidenhainPlanes, RadiusArcsInZxPickTheirCentreBySignAndDirection)
{
    // From X+10 to Z-10 with radius 10: the short arc DR+ about the origin, the long one about
    // X+10 Z-10. No CC: the two axes of the CR block name the plane.
    struct Case {
        const char* words;
        Vec3 centre;
        double sweep;
    } cases[] = {
        {"R+10 DR+", {0, 0, 0}, 90},
        {"R-10 DR+", {10, 0, -10}, 270},
        {"R+10 DR-", {10, 0, -10}, 90},
        {"R-10 DR-", {0, 0, 0}, 270},
    };
    for (const Case& c : cases) {
        const Traced r = run(program(std::string("2 L X+10 Y+0 Z+0 FMAX\n3 CR X+0 Z-10 ") + c.words + " F100\n"));
        EXPECT_TRUE(r.result.diagnostics.empty()) << c.words << ": " << r.diagnostics()[0];
        const auto arcs = r.all<Arc>();
        ASSERT_EQ(arcs.size(), 1u) << c.words;
        expectNear(arcs[0].normal, {0, 1, 0});
        expectNear(arcs[0].center, c.centre, 1e-9);
        EXPECT_NEAR(arcSweepDeg({10, 0, 0}, arcs[0]), c.sweep, 1e-9) << c.words;
    }
}

TEST(HeidenhainPlanes, TangentialArcInZxFollowsTheLineBefore)
{
    // Along +X, then CT to X+20 Z-10: a quarter about X+10 Z-10 that leaves along +X.
    const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n3 L X+10 F100\n4 CT X+20 Z-10\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].center, {10, 0, -10}, 1e-9);
    expectNear(arcs[0].normal, {0, 1, 0});
    EXPECT_FALSE(arcs[0].clockwise);
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, arcs[0]), 90, 1e-9);
}

TEST(HeidenhainPlanes, MultiTurnHelicesEndExactly)
{
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Y+0\n"
                                 "4 CP IPA+1080 IZ-3 DR+ F100\n"
                                 "5 CC X+0 Z+0\n"
                                 "6 CP IPA-720 IY+2 DR-\n"
                                 "7 L X+0 Y+10 Z+0 FMAX\n"
                                 "8 CC Y+0 Z+0\n"
                                 "9 CP IPA+450 IX-1.5 DR+\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 3u);
    EXPECT_EQ(arcs[0].to, (Vec3{10, 0, -3}));  // exactly: whole laps end where they began
    EXPECT_EQ(arcs[0].turns, 2);
    EXPECT_NEAR(arcSweepDeg({10, 0, 0}, arcs[0]), 1080, 1e-9);
    EXPECT_EQ(arcs[1].to, (Vec3{10, 2, -3}));
    EXPECT_EQ(arcs[1].turns, 1);
    EXPECT_TRUE(arcs[1].clockwise);
    expectNear(arcs[1].normal, {0, 1, 0});
    // YZ: 450 degrees from Y+10 about +X end at Z+10 (the height along the normal is X).
    expectNear(arcs[2].to, {-1.5, 0, 10}, 1e-12);
    EXPECT_EQ(arcs[2].turns, 1);
    EXPECT_NEAR(arcSweepDeg({0, 10, 0}, arcs[2]), 450, 1e-9);
}

TEST(HeidenhainPlanes, PolarAnglesCountFromThePlanesFirstAxis)
{
    const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Z+0\n"
                                 "4 LP PR+5 PA+0 F100\n"
                                 "5 LP PR+5 PA+90\n"
                                 "6 CC Y+0 Z+0\n"
                                 "7 LP PR+5 PA+0\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto lines = r.all<Linear>();
    ASSERT_EQ(lines.size(), 3u);
    expectNear(lines[0].to, {0, 0, 5}, 1e-12);
    expectNear(lines[1].to, {5, 0, 0}, 1e-12);
    expectNear(lines[2].to, {5, 5, 0}, 1e-12);
}

TEST(HeidenhainPlanes, OneAxisCcKeepsThePlaneAndTakesTheOtherFromThePosition)
{
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n"
                                 "3 CC X+0 Z+0\n"
                                 "4 CC X+5\n"
                                 "5 C X+0 Z+0 DR+ F100\n"));
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].center, {5, 0, 0});
    expectNear(arcs[0].normal, {0, 1, 0});
}

TEST(HeidenhainPlanes, RadiusCheckAndUnknownStartInZx)
{
    const Traced r = run(program("2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Z+0\n4 C X+0 Z-11 DR+ F100\n"));
    EXPECT_TRUE(r.has(Severity::Error, 5, "arc start radius 10.0000 and end radius 11.0000")) << r.diagnostics()[0];
    // From the origin given by the caller, but no Z programmed: the radius is not checked.
    const Traced u = run(program("2 L X+10 Y+0 FMAX\n3 CC X+0 Z+0\n4 C X+0 Z-11 DR+ F100\n"));
    EXPECT_TRUE(u.has(Severity::Warning, 5, "no Z and X programmed before it")) << u.diagnostics()[0];
}

TEST(HeidenhainPlanes, WhatTheOtherPlanesDoNotAllowIsAnErrorOnItsLine)
{
    struct Case {
        const char* body;
        int line;
        const char* message;
    } cases[] = {
        {"2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Z+0\n4 C X+0 Y+5 Z-10 DR+ F100\n", 5,
         "a circle in the ZX plane cannot move along Y"},
        {"2 L X+0 Y+10 Z+0 FMAX\n3 CC Y+0 Z+0\n4 CR Y+0 Z+10 IX+1 R+10 DR+ F100\n", 5,
         "a circle in the YZ plane cannot move along X"},
        {"2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Z+0\n4 CP IPA+90 IZ-1 DR+ F100\n", 5, "CP in the ZX plane takes"},
        {"2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Y+0 Z+0\n", 4, "CC with X, Y and Z"},
        {"2 L X+10 Y+0 Z+0 FMAX\n3 CC X+0 Y+0\n4 CC Z+5\n", 5, "CC Z alone"},
        {"2 L X+0 Y+10 Z+0 FMAX\n3 CT X+0 Z-10 F100\n", 4, "to be tangent to in the ZX plane"},
    };
    for (const Case& c : cases) {
        const Traced r = run(program(c.body));
        EXPECT_TRUE(r.has(Severity::Error, c.line, c.message))
            << c.body << (r.result.diagnostics.empty() ? "" : r.diagnostics()[0]);
    }
}

TEST(HeidenhainPlanes, CompensationWithACircleOutsideXyIsAnError)
{
    // With and without a known radius: the control compensates in the XY working plane only.
    for (const char* toolDef : {"1 TOOL DEF 1 L+0 R+3\n", "1 ; no tool data\n"}) {
        const std::string text = std::string("0 BEGIN PGM T MM\n") + toolDef +
                                 "2 TOOL CALL 1 Z S3000\n"
                                 "3 L X+10 Y+0 Z+0 R0 FMAX\n"
                                 "4 L X+20 RL F100\n"
                                 "5 CC X+10 Z+0\n"
                                 "6 C X+0 Z+0 DR+\n"
                                 "7 L X-10 R0\n"
                                 "8 END PGM T MM\n";
        const Traced r = run(text);
        EXPECT_TRUE(r.has(Severity::Error, 7, "an arc in another plane is not allowed")) << text << r.trace();
        ASSERT_EQ(r.all<Arc>().size(), 1u);
        expectNear(r.all<Arc>()[0].to, {0, 0, 0});  // traced as programmed
    }
}

TEST(HeidenhainPlanes, CornersNextToACircleOutsideXyAreNotTraced)
{
    const Traced r = run(program("2 L X+0 Y+0 Z+0 FMAX\n3 L X+10 F100\n4 RND R2\n5 CC X+10 Z-10\n"
                                 "6 C X+20 Z-10 DR+\n"));
    EXPECT_TRUE(r.has(Severity::Warning, 5, "RND next to a circle outside the XY working plane")) << r.trace();
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 1u);
    expectNear(arcs[0].normal, {0, 1, 0});
    expectNear(r.all<Linear>().back().to, {10, 0, 0});  // the line keeps its corner
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
