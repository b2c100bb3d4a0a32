// Forward and inverse kinematics against every test vector of the three five-axis references
// (seed 000's B = 30, C = 40 check; seed 002's B/C and A/C table-table vectors; seed 003's A/C
// vectors with r = -100, P = 150), and IK(FK(q)) = q over random poses of each chain type.
#include "kinematics/KinematicChain.h"
#include "kinematics/Machine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace camwb;
using namespace camwb::kinematics;

namespace {

constexpr double kPi = 3.14159265358979323846;

void expectNear(const Vec3& actual, const Vec3& expected, double tolerance, const std::string& what)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

RotaryJoint joint(const char* axis, bool onTable, Vec3 direction, Vec3 pivot = {})
{
    return {axis, onTable, direction, pivot};
}

KinematicChain mcvl1000()
{
    auto machine = findMachine("mas-mcvl1000", defaultMachineDirs());
    EXPECT_TRUE(machine.ok()) << machine.error().toString();
    return machine.ok() ? machine->kinematics : KinematicChain{};
}

// Seed 002 §2.6: Rot(Z,C)·Trans(-Dx,0,Dz)·Rot(Y,B)·Trans(Tx+Dx, Ty, Tz-Dz), the tool relative to
// the workpiece; the machine turns the workpiece the other way: directions -Y and -Z.
KinematicChain seed002BC(double dx = 30, double dz = 80)
{
    KinematicChain c;
    c.type = ChainType::TableTable;
    c.joints = {joint("B", true, {0, -1, 0}, {-dx, 0, dz}), joint("C", true, {0, 0, -1})};
    return c;
}

// Seed 002 §2.5.3 (eq. 3 corrected): Rot(Z,C)·Trans(0,-Dy,Dz)·Rot(X,A)·Trans(Tx, Ty+Dy, Tz-Dz).
KinematicChain seed002AC(double dy = 50, double dz = 100)
{
    KinematicChain c;
    c.type = ChainType::TableTable;
    c.joints = {joint("A", true, {-1, 0, 0}, {0, -dy, dz}), joint("C", true, {0, 0, -1})};
    return c;
}

// Seed 003 eq. 9: machine = Tz(r)·Rx(-A)·Rz(-C)·Tz(P)·workpiece.
KinematicChain seed003AC(double r = -100, double p = 150)
{
    KinematicChain c;
    c.type = ChainType::TableTable;
    c.joints = {joint("A", true, {-1, 0, 0}, {0, 0, r}), joint("C", true, {0, 0, -1}, {0, 0, r})};
    c.workpieceZero = {0, 0, r + p};
    return c;
}

// The IK solution nearest `rotary` (whole turns allowed).
const IkSolution* nearest(const std::vector<IkSolution>& solutions, std::array<double, 2> rotary)
{
    const IkSolution* best = nullptr;
    double bestDistance = 1e300;
    for (const IkSolution& s : solutions) {
        double d = 0;
        for (int i = 0; i < 2; ++i)
            d += std::abs(std::remainder(s.pose.rotaryDeg[i] - rotary[i], 360.0));
        if (d < bestDistance) {
            bestDistance = d;
            best = &s;
        }
    }
    return best;
}

struct Vector {
    Vec3 machine;
    double r1, r2;
    Vec3 tip, axis;
};

// Forward gives the reference's workpiece point and tool axis (to its 4 decimals); inverse of the
// exact forward result gives back the machine axes on the branch the reference names (the rounded
// axis would tilt the solution by up to 1e-4 rad, 0.01 mm at these lever arms).
void checkVectors(const KinematicChain& chain, const std::vector<Vector>& vectors, double tolerance)
{
    for (const Vector& v : vectors) {
        const std::string what = "pose " + std::to_string(v.r1) + ", " + std::to_string(v.r2);
        const ToolPose tool = forwardKinematics(chain, {v.machine, {v.r1, v.r2}});
        expectNear(tool.tip, v.tip, tolerance, what + " tip");
        expectNear(tool.axis, v.axis, 1e-4, what + " axis");
        const auto solutions = inverseKinematics(chain, tool, {v.r1, v.r2});
        ASSERT_FALSE(solutions.empty()) << what;
        const IkSolution* s = nearest(solutions, {v.r1, v.r2});
        expectNear(s->pose.linear, v.machine, 1e-9, what + " inverse");
        EXPECT_NEAR(std::remainder(s->pose.rotaryDeg[0] - v.r1, 360.0), 0, 1e-3) << what;
        EXPECT_NEAR(std::remainder(s->pose.rotaryDeg[1] - v.r2, 360.0), 0, 1e-3) << what;
    }
}

}  // namespace

TEST(KinematicChain, Seed000ToolAxisForB30C40)
{
    // Seed 000 eq. 14 with the machine's B and C: K = (-cosC sinB, sinC sinB, cosB).
    const ToolPose tool = forwardKinematics(mcvl1000(), {{0, 0, 0}, {30, 40}});
    expectNear(tool.axis, {-0.3830, 0.3214, 0.8660}, 1e-4, "K");
    // The corrected C formula (B > 0): C = atan2(Ky, -Kx) = 40, not the printed atan2(Ky, Kx) = 140.
    const auto solutions = inverseKinematics(mcvl1000(), tool);
    ASSERT_EQ(solutions.size(), 2u);
    const IkSolution* positive = nearest(solutions, {30, 40});
    EXPECT_NEAR(positive->pose.rotaryDeg[0], 30, 1e-9);
    EXPECT_NEAR(positive->pose.rotaryDeg[1], 40, 1e-9);
    // The other branch: (-B, C ± 180).
    const IkSolution* negative = nearest(solutions, {-30, -140});
    EXPECT_NEAR(negative->pose.rotaryDeg[0], -30, 1e-9);
    EXPECT_NEAR(negative->pose.rotaryDeg[1], -140, 1e-9);
}

TEST(KinematicChain, Seed000LinearAxesAreXTransposeQ)
{
    // Eqs. 22-24: P = Xᵀ·Q about MRZP.
    const double b = 25 * kPi / 180, c = -70 * kPi / 180;
    const Vec3 q{12.5, -40, 33};
    const Vec3 p{std::cos(c) * std::cos(b) * q.x - std::sin(c) * std::cos(b) * q.y + std::sin(b) * q.z,
                 std::sin(c) * q.x + std::cos(c) * q.y,
                 -std::cos(c) * std::sin(b) * q.x + std::sin(c) * std::sin(b) * q.y + std::cos(b) * q.z};
    expectNear(linearAxesFor(mcvl1000(), q, {25, -70}), p, 1e-9, "P");
    expectNear(forwardKinematics(mcvl1000(), {p, {25, -70}}).tip, q, 1e-9, "Q");
}

TEST(KinematicChain, Seed002BCVectors)
{
    checkVectors(seed002BC(),
                 {
                     {{10, 20, 30}, 30, 45, {-28.5381, -0.2538, 16.6987}, {0.3536, 0.3536, 0.8660}},
                     {{-18.0385, -20, 0}, -30, -135, {-28.5381, -0.2538, 16.6987}, {0.3536, 0.3536, 0.8660}},
                     {{0, 0, 0}, 90, 0, {-110, 0, 50}, {1, 0, 0}},
                     {{-60, 0, -60}, -90, -180, {-110, 0, 50}, {1, 0, 0}},
                     {{-5, 12, 40}, -45, 200, {-10.8951, -16.7356, 69.3934}, {0.6645, 0.2418, 0.7071}},
                     {{-12.5736, -12, 82.4264}, 45, 20, {-10.8951, -16.7356, 69.3934}, {0.6645, 0.2418, 0.7071}},
                 },
                 1e-4);
}

TEST(KinematicChain, Seed002ACVectors)
{
    checkVectors(seed002AC(),
                 {
                     {{10, 20, 30}, 30, 45, {-25.1884, 39.3305, 74.3782}, {0.3536, -0.3536, 0.8660}},
                     {{-10, -33.3975, 80}, -30, -135, {-25.1884, 39.3305, 74.3782}, {0.3536, -0.3536, 0.8660}},
                     {{0, 0, 0}, 90, 0, {0, 50, 150}, {0, -1, 0}},
                     {{-25, 40, 15}, 45, -120, {76.3639, -15.2212, 103.5355}, {-0.6124, 0.3536, 0.7071}},
                     {{5, -10, 60}, 60, 90, {-4.6410, 5.0000, 114.6410}, {0.8660, 0, 0.5}},
                 },
                 1e-4);
}

TEST(KinematicChain, Seed002ACPoleKeepsThePreviousC)
{
    const auto solutions = inverseKinematics(seed002AC(), {{0, 0, 0}, {0, 0, 1}}, {0, 77});
    ASSERT_EQ(solutions.size(), 1u);
    EXPECT_EQ(solutions[0].pole, 1);
    EXPECT_NEAR(solutions[0].pose.rotaryDeg[0], 0, 1e-9);
    EXPECT_EQ(solutions[0].pose.rotaryDeg[1], 77);
    expectNear(solutions[0].pose.linear, {0, 0, 0}, 1e-9, "linear at the pole");
}

TEST(KinematicChain, Seed003Vectors)
{
    // Seed 003 §2.4: workpiece point, A, C -> machine tip and tool axis (r = -100, P = 150).
    const KinematicChain chain = seed003AC();
    struct Row {
        Vec3 w;
        double a, c;
        Vec3 machine, k;
    };
    const Row rows[] = {
        {{0, 0, 0}, 0, 0, {0, 0, 50}, {0, 0, 1}},
        {{0, 0, 0}, 90, 0, {0, 150, -100}, {0, -1, 0}},
        {{10, 0, 0}, 0, 90, {0, -10, 50}, {0, 0, 1}},
        {{10, 20, 30}, 30, 45, {21.2132, 96.1237, 52.3490}, {0.353553, -0.353553, 0.866025}},
        {{50, -20, 5}, -45, 200, {-40.1442, -84.2201, 34.9830}, {0.241845, -0.664463, 0.707107}},
    };
    for (const Row& r : rows) {
        const std::string what = "A" + std::to_string(r.a) + " C" + std::to_string(r.c);
        expectNear(linearAxesFor(chain, r.w, {r.a, r.c}), r.machine, 1e-4, what + " machine");
        const ToolPose tool = forwardKinematics(chain, {r.machine, {r.a, r.c}});
        expectNear(tool.tip, r.w, 1e-3, what + " round trip");
        expectNear(tool.axis, r.k, 1e-6, what + " k");
    }
}

namespace {

// Random poses within `limits` (and away from the pole): IK given the pose's own angles as the
// free ones returns a solution equal to it, and FK of every solution gives the same tool.
void checkRoundTrips(const KinematicChain& chain, std::array<std::pair<double, double>, 2> limits, double toolLength,
                     unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> linear(-300, 300);
    std::uniform_real_distribution<double> first(limits[0].first, limits[0].second);
    std::uniform_real_distribution<double> second(limits[1].first, limits[1].second);
    int checked = 0;
    for (int n = 0; n < 3000; ++n) {
        const MachinePose q{{linear(random), linear(random), linear(random)}, {first(random), second(random)}};
        const ToolPose tool = forwardKinematics(chain, q, toolLength);
        const auto solutions = inverseKinematics(chain, tool, q.rotaryDeg, toolLength);
        ASSERT_FALSE(solutions.empty());
        if (solutions.front().poleDistanceDeg < 0.01)
            continue;  // C is free there: nothing to compare
        for (const IkSolution& s : solutions) {
            const ToolPose back = forwardKinematics(chain, s.pose, toolLength);
            expectNear(back.tip, tool.tip, 1e-8, "FK(IK) tip");
            expectNear(back.axis, tool.axis, 1e-10, "FK(IK) axis");
        }
        const IkSolution* s = nearest(solutions, q.rotaryDeg);
        EXPECT_NEAR(std::remainder(s->pose.rotaryDeg[0] - q.rotaryDeg[0], 360.0), 0, 1e-7);
        EXPECT_NEAR(std::remainder(s->pose.rotaryDeg[1] - q.rotaryDeg[1], 360.0), 0, 1e-7);
        expectNear(s->pose.linear, q.linear, 1e-7, "IK(FK(q)) linear");
        ++checked;
    }
    EXPECT_GT(checked, 2900);
}

}  // namespace

TEST(KinematicChain, TableTableBCRoundTrips)
{
    checkRoundTrips(mcvl1000(), {{{-120, 30}, {-720, 720}}}, 0, 1);
    checkRoundTrips(seed002BC(), {{{-179, 179}, {-180, 180}}}, 0, 2);
}

TEST(KinematicChain, TableTableACRoundTrips)
{
    checkRoundTrips(seed003AC(), {{{-120, 120}, {-180, 180}}}, 0, 3);
    checkRoundTrips(seed002AC(), {{{-179, 179}, {-180, 180}}}, 0, 4);
}

TEST(KinematicChain, HeadTableRoundTrips)
{
    KinematicChain chain;
    chain.type = ChainType::HeadTable;
    chain.joints = {joint("C", true, {0, 0, 1}, {15, -5, 0}), joint("B", false, {0, 1, 0}, {2, 0, 180})};
    chain.workpieceZero = {40, 30, 10};
    checkRoundTrips(chain, {{{-180, 180}, {-110, 110}}}, 95, 5);
}

TEST(KinematicChain, HeadHeadRoundTrips)
{
    KinematicChain chain;
    chain.type = ChainType::HeadHead;
    chain.joints = {joint("C", false, {0, 0, 1}, {0, 0, 250}), joint("A", false, {1, 0, 0}, {0, 10, 120})};
    checkRoundTrips(chain, {{{-180, 180}, {-100, 100}}}, 60, 6);
}

TEST(KinematicChain, HeadTableTurnsTheToolAboutItsPivot)
{
    // B head about Y through a pivot 200 above the gauge point, a 100 mm tool: the tip hangs 300
    // below the pivot, and B = 90 swings it to 300 along -X of the pivot.
    KinematicChain chain;
    chain.type = ChainType::HeadTable;
    chain.joints = {joint("C", true, {0, 0, 1}), joint("B", false, {0, 1, 0}, {0, 0, 200})};
    const ToolPose tool = forwardKinematics(chain, {{0, 0, 0}, {0, 90}}, 100);
    expectNear(tool.axis, {1, 0, 0}, 1e-12, "axis");
    expectNear(tool.tip, {-300, 0, 300}, 1e-9, "tip");
}

TEST(KinematicChain, UnreachableDirectionHasNoSolution)
{
    // A head-table machine whose B is tilted 45 degrees out of the XZ plane cannot reach every direction.
    KinematicChain chain;
    chain.type = ChainType::HeadHead;
    const double s = std::sqrt(0.5);
    chain.joints = {joint("C", false, {0, 0, 1}), joint("B", false, {0, s, s})};
    // R(B) turns Z on a cone of half-angle 45 degrees about (0, s, s): at most 90 degrees from Z.
    EXPECT_TRUE(inverseKinematics(chain, {{0, 0, 0}, {0, 0, -1}}).empty());
    EXPECT_FALSE(inverseKinematics(chain, {{0, 0, 0}, {1, 0, 0}}).empty());
}
