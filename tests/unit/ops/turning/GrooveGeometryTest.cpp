// The groove's geometry by line intersections (spec F1, seed REQ-02..05): Kod 1's figures, the
// thesis' closed forms for R2, R5, R6 > 0, and the cases they cannot do (R2 = 0, R5 = 0, R6 = 0).
#include "sim/TurningProfile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace camwb::sim {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180; }

// The thesis' closed forms (seed §2.4/§2.5, Rov. 2, 9, 7, 17, 20-23, 31-33, 40-46, 54-55), kept
// here only to check the general intersections against them.
GrooveGeometry thesisForms(const GrooveParameters& g)
{
    const double t2 = std::tan(rad(g.r2)), t5 = std::tan(rad(g.r5)), t6 = std::tan(rad(g.r6));
    const double d = g.r3 * t5;
    const double c = (g.r3 - t2 * (g.r4 + g.r3 * t5)) / (t2 + 1 / t6);
    const double h1 = g.r3 - c / t6;
    const double dRx = (g.r8 * std::tan(rad(g.r2 - g.r6)) + g.r8 * t6) * std::cos(rad(g.r6));
    const double dUx = (g.r8 * std::tan(rad(g.r2 + g.r5)) - g.r8 * t5) * std::cos(rad(g.r5));
    GrooveGeometry geo;
    geo.d = d;
    geo.c = c;
    geo.h1 = h1;
    geo.h2 = c / t6;
    geo.c1 = turningPoint(g.r0 - h1, g.r1 - d - g.r4 - c);
    geo.r = turningPoint(g.r0 - h1 + dRx, g.r1 - d - g.r4 - c + dRx / t2);
    geo.s = turningPoint(g.r0 - g.r3 + g.r7, g.r1 - d - g.r4 + g.r8 / std::cos(rad(g.r6)) - g.r7 * t6);
    geo.t = turningPoint(g.r0 - g.r3 + g.r7, g.r1 - d - (g.r8 / std::cos(rad(g.r5)) - g.r7 * t5));
    geo.u = turningPoint(g.r0 - dUx, g.r1 - dUx / t2);
    return geo;
}

void expectPoint(Vec2 actual, double z, double x, double tol)
{
    EXPECT_NEAR(actual.x, z, tol);
    EXPECT_NEAR(actual.y, x, tol);
}

// Distance of point q from the line through a with direction (dz, dx).
double lineDistance(Vec2 q, Vec2 a, double dz, double dx)
{
    return std::abs((q.x - a.x) * dx - (q.y - a.y) * dz) / std::hypot(dz, dx);
}

TEST(GrooveGeometry, Req02AuxiliaryDistancesOfKod1)
{
    const GrooveGeometry geo = grooveGeometry({});
    EXPECT_NEAR(geo.d, 20.000491, 1e-6);
    EXPECT_NEAR(geo.c, 10.010495, 1e-6);
    EXPECT_NEAR(geo.h1, 30.003773, 1e-6);
    EXPECT_NEAR(geo.h2, 139.996227, 1e-6);
    expectPoint(geo.c1, 109.989014, 149.996227, 1e-6);
}

TEST(GrooveGeometry, Req03OffsetCornersOfKod1)
{
    const GrooveGeometry geo = grooveGeometry({});
    expectPoint(geo.r, 110.476352, 150.191159, 1e-6);
    expectPoint(geo.s, 120.465033, 10.500000, 1e-6);
    expectPoint(geo.t, 164.554886, 10.500000, 1e-6);
    expectPoint(geo.u, 184.471690, 179.788680, 1e-6);
    EXPECT_NEAR(geo.t.x - geo.s.x, 44.089853, 1e-6);
}

// REQ-05: the offset flanks' slopes dz/dx, as the code computes them from the points (the printed
// Rov. 72 left out Tx), are tan R5 and -tan R6; the lines run through the corners.
TEST(GrooveGeometry, Req05FlankLines)
{
    const GrooveGeometry geo = grooveGeometry({});
    const double m = (geo.t.x - geo.u.x) / (geo.t.y - geo.u.y), n = (geo.r.x - geo.s.x) / (geo.r.y - geo.s.y);
    EXPECT_NEAR(m, std::tan(rad(6.71)), 1e-9);
    EXPECT_NEAR(m, 0.117650, 1e-6);
    EXPECT_NEAR(n, -std::tan(rad(4.09)), 1e-9);
    EXPECT_NEAR(n, -0.071505, 1e-6);
    EXPECT_NEAR(geo.zRight(geo.u.y), geo.u.x, 1e-9);
    EXPECT_NEAR(geo.zLeft(geo.r.y), geo.r.x, 1e-9);
    EXPECT_NEAR(geo.xRight(geo.u.x), geo.u.y, 1e-9);
    EXPECT_NEAR(geo.xLeft(geo.r.x), geo.r.y, 1e-9);
}

// REQ-03 properties and REQ-04 on random grooves of the seed's sweep ranges (R2, R5, R6 > 0):
// offset corners R8 from their flanks, R and U on the cone, the closed forms to 1e-9.
TEST(GrooveGeometry, Req04IntersectionsEqualTheClosedForms)
{
    std::mt19937 rng(17);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
    for (int k = 0; k < 200; ++k) {
        GrooveParameters g;
        g.r0 = 350;
        g.r1 = 500;
        g.r2 = uniform(0.5, 40);
        g.r3 = uniform(20, 120);
        g.r4 = uniform(5, 80);
        g.r5 = uniform(0.5, 30);
        g.r6 = uniform(0.5, 30);
        g.r7 = uniform(0, 2);
        g.r8 = uniform(0, 2);
        SCOPED_TRACE(k);
        const GrooveGeometry geo = grooveGeometry(g), th = thesisForms(g);
        EXPECT_NEAR(geo.d, th.d, 1e-9);
        EXPECT_NEAR(geo.c, th.c, 1e-9);
        EXPECT_NEAR(geo.h1, th.h1, 1e-9);
        EXPECT_NEAR(geo.h2, th.h2, 1e-9);
        for (auto [a, b] : {std::pair{geo.c1, th.c1}, {geo.r, th.r}, {geo.s, th.s}, {geo.t, th.t}, {geo.u, th.u}})
            expectPoint(a, b.x, b.y, 1e-9);
        const double t5 = std::tan(rad(g.r5)), t6 = std::tan(rad(g.r6));
        EXPECT_NEAR(lineDistance(geo.r, geo.bottomLeft, -t6, 1), g.r8, 1e-9);
        EXPECT_NEAR(lineDistance(geo.s, geo.bottomLeft, -t6, 1), g.r8, 1e-9);
        EXPECT_NEAR(lineDistance(geo.t, geo.bottomRight, t5, 1), g.r8, 1e-9);
        EXPECT_NEAR(lineDistance(geo.u, geo.bottomRight, t5, 1), g.r8, 1e-9);
        EXPECT_NEAR(geo.surfaceX(geo.r.x), geo.r.y, 1e-9);
        EXPECT_NEAR(geo.surfaceX(geo.u.x), geo.u.y, 1e-9);
        EXPECT_NEAR(geo.surfaceX(geo.c1.x), geo.c1.y, 1e-9);
        EXPECT_NEAR(geo.r.y - geo.c1.y, g.r8 * std::sin(rad(g.r2)) / std::cos(rad(g.r2 - g.r6)), 1e-9);
        EXPECT_NEAR(g.r0 - geo.u.y, g.r8 * std::sin(rad(g.r2)) / std::cos(rad(g.r2 + g.r5)), 1e-9);
        EXPECT_DOUBLE_EQ(geo.s.y, g.r0 - g.r3 + g.r7);
        EXPECT_DOUBLE_EQ(geo.t.y, g.r0 - g.r3 + g.r7);
    }
}

// The thesis divides by tan R2 and tan R6 (seed §5.3 item 6): a cylinder and vertical flanks.
TEST(GrooveGeometry, Req04CylinderAndVerticalFlanks)
{
    GrooveParameters g;
    g.r2 = 0;
    g.r5 = 0;
    g.r6 = 0;
    const GrooveGeometry geo = grooveGeometry(g);
    expectPoint(geo.c1, 185 - 45, 180, 1e-12);
    EXPECT_NEAR(geo.h1, 0, 1e-12);
    EXPECT_NEAR(geo.h2, 170, 1e-12);
    expectPoint(geo.r, 140.5, 180, 1e-12);
    expectPoint(geo.s, 140.5, 10.5, 1e-12);
    expectPoint(geo.t, 184.5, 10.5, 1e-12);
    expectPoint(geo.u, 184.5, 180, 1e-12);

    g = {};
    g.r2 = 0;  // cylinder, Kod 1's flanks: the corners lie on X = R0
    const GrooveGeometry cyl = grooveGeometry(g);
    EXPECT_NEAR(cyl.r.y, 180, 1e-12);
    EXPECT_NEAR(cyl.u.y, 180, 1e-12);
    EXPECT_NEAR(cyl.c1.x, 185 - 20.000491 - 45 - 170 * std::tan(rad(4.09)), 1e-6);
    EXPECT_NEAR(lineDistance(cyl.r, cyl.bottomLeft, -std::tan(rad(4.09)), 1), 0.5, 1e-9);
    EXPECT_NEAR(lineDistance(cyl.u, cyl.bottomRight, std::tan(rad(6.71)), 1), 0.5, 1e-9);
    // The stock and the offset part are built for it: the groove's offset area is the trapezoid.
    const double groove = geom::totalArea(grooveStock(g)) - geom::totalArea(grooveOffsetPart(g));
    EXPECT_NEAR(groove, (cyl.t.x - cyl.s.x + cyl.u.x - cyl.r.x) / 2 * (180 - 10.5), 1e-6);
}

}  // namespace
}  // namespace camwb::sim
