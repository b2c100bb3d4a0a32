// Long programs through LinuxCNC: 10,000 random lines, arcs in all three planes and helices must
// read back within the output precision, so rounding does not drift or add up along a program.
// The times are printed (and recorded as test properties), never asserted.
#include "LinuxCncModel.h"
#include "MotionCompare.h"
#include "RoundTripFixture.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

namespace camwb::external::test {
namespace {

using namespace toolpath;

// A continuous path of `moves` moves: two in five are arcs (random plane, sweep 5..350 degrees,
// sometimes helical or with extra turns), the rest lines; it stays within about +-150 mm.
Toolpath randomProgram(int moves, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto between = [&](double a, double b) { return a + (b - a) * unit(random); };

    Toolpath path;
    path.add(SectionBegin{"Long program", "pocket", 1, {}});
    path.add(ToolChange{Tool{1, "D6", "flat", 6}});
    path.add(Spindle{6000, true});
    Vec3 position{0, 0, 5};
    path.add(Rapid{position});
    const Vec3 normals[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
    for (int i = 0; i < moves; ++i) {
        const double feed = std::round(between(100, 2000));
        if (unit(random) < 0.6) {
            // Pull back towards the origin so the path stays in a machine-sized box.
            const Vec3 target{between(-100, 100), between(-100, 100), between(-20, 10)};
            position = position + (target - position) * between(0.05, 0.5);
            path.add(Linear{position, feed});
            continue;
        }
        const Vec3 n = normals[random() % 4];
        // Two in-plane unit vectors u, v with u x v = n.
        const Vec3 u = std::abs(n.z) > 0.5 ? Vec3{1, 0, 0} : std::abs(n.y) > 0.5 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
        const Vec3 v = n.cross(u);
        const double radius = between(0.5, 40);
        const double a0 = between(0, 2 * std::numbers::pi);
        const Vec3 centre = position - (u * std::cos(a0) + v * std::sin(a0)) * radius;
        const bool clockwise = unit(random) < 0.5;
        const int turns = unit(random) < 0.05 ? 1 : 0;
        const double sweep = between(5, 350) * std::numbers::pi / 180;
        const double a1 = a0 + (clockwise ? -sweep : sweep);
        const double rise = unit(random) < 0.3 ? between(-3, 3) : 0;
        position = centre + (u * std::cos(a1) + v * std::sin(a1)) * radius + n * rise;
        path.add(Arc{position, centre, n, clockwise, turns, feed});
    }
    path.add(Rapid{{position.x, position.y, 30}});
    return path;
}

TEST_F(LinuxCncRoundTrip, TenThousandMovesStayWithinOutputPrecision)
{
    const Toolpath path = randomProgram(10000, 20261122);
    std::optional<RoundTrip> trip = postAndRead(path);
    ASSERT_TRUE(trip);
    const auto start = std::chrono::steady_clock::now();
    const Toolpath expected = expectedMotion(path);
    const std::optional<std::string> difference = compareMotion(expected, trip->program.motion);
    const double compareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(difference) << *difference << "\n(NC: " << trip->ngcPath << ")";

    const std::size_t blocks = std::count(trip->posted.text.begin(), trip->posted.text.end(), '\n');
    std::cout << "10,000 CL moves: " << blocks << " NC lines, " << trip->program.motion.size()
              << " records read back; post " << trip->postSeconds << " s, rs274 " << trip->run.seconds
              << " s, trace reading " << trip->readSeconds << " s, comparison " << compareSeconds << " s\n";
    RecordProperty("nc_lines", static_cast<int>(blocks));
    RecordProperty("rs274_ms", static_cast<int>(trip->run.seconds * 1000));
    RecordProperty("post_ms", static_cast<int>(trip->postSeconds * 1000));
}

}  // namespace
}  // namespace camwb::external::test
