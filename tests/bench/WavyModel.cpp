#include "WavyModel.h"

#include <cmath>

namespace camwb::bench {

const sim::TriangleMesh& wavyModel()
{
    static const sim::TriangleMesh mesh = [] {
        constexpr int n = 708;
        auto f = [](double x, double y) {
            const double r2 = (x - 50) * (x - 50) + (y - 50) * (y - 50);
            return 3 * std::sin(x / 7) * std::cos(y / 9) + 1.5 * std::sin((x + 2 * y) / 4) +
                   (r2 < 900 ? std::sqrt(900 - r2) - 15 : -15) * 0.5;
        };
        sim::TriangleMesh m;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = 100.0 * i / n, y = 100.0 * j / n;
                m.positions.insert(m.positions.end(), {float(x), float(y), float(f(x, y))});
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
            }
        return m;
    }();
    return mesh;
}

std::vector<base::Vec2> wavyGridPoints()
{
    std::vector<base::Vec2> points;
    for (int j = 0; j < 200; ++j)
        for (int i = 0; i < 200; ++i)
            points.push_back({0.25 + 0.5 * i, 0.25 + 0.5 * j});
    return points;
}

}  // namespace camwb::bench
