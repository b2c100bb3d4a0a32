// The tool's lower surface grown by the stock to leave, as the tests measure it independently of
// the drop-cutter's CutterProfile: by brute force from sim::ToolShape::lowerSurface, and tabulated.
#pragma once

#include "sim/ToolShape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace camwb::ops::test {

// The tool's lower surface grown by `stock`, from sim::ToolShape::lowerSurface alone: the lowest
// point of the balls of radius `stock` round the profile's points (a dense minimum), measured from
// the ungrown tip. +infinity beyond the grown radius.
struct GrownProfile {
    const sim::ToolShape& shape;
    double stock;
    double operator()(double d) const
    {
        const double R = shape.radiusMm();
        if (d > R + stock + 1e-12)
            return std::numeric_limits<double>::infinity();
        if (stock == 0)
            return shape.lowerSurface(std::min(d, R));
        double best = std::numeric_limits<double>::infinity();
        constexpr int kSteps = 4000;
        for (int i = 0; i <= kSteps; ++i) {
            const double e =
                std::max(0.0, d - stock) + (std::min(R, d + stock) - std::max(0.0, d - stock)) * i / kSteps;
            const double off = d - e;
            best = std::min(best, shape.lowerSurface(e) - std::sqrt(std::max(0.0, stock * stock - off * off)));
        }
        return best;
    }
};

// The grown profile tabulated (GrownProfile is slow with stock): linear between 4001 heights, a
// hair above the convex profile between them.
struct ProfileTable {
    std::vector<double> z;
    double radius;
    explicit ProfileTable(const GrownProfile& h) : radius(h.shape.radiusMm() + h.stock)
    {
        for (int i = 0; i <= 4000; ++i)
            z.push_back(h(radius * i / 4000));
    }
    double operator()(double d) const
    {
        const double f = std::clamp(d / radius, 0.0, 1.0) * 4000;
        const int i = std::min(3999, int(f));
        return z[i] + (z[i + 1] - z[i]) * (f - i);
    }
};

}  // namespace camwb::ops::test
