#include "document/JobSetup.h"

#include "base/NumberFormat.h"
#include "sim/MakeStock.h"

namespace camwb::document {

namespace {

std::string mm(double value) { return base::NumberFormat{3, true}.format(value); }

}  // namespace

std::optional<std::string> stockProblem(const Stock& stock)
{
    if (stock.min == base::Vec3{} && stock.max == base::Vec3{})
        return std::nullopt;
    if (auto far = sim::stockBeyondReach(base::Box3{stock.min, stock.max, false}))
        return far;  // first: the numbers below are then short enough to show
    const std::pair<const char*, std::pair<double, double>> axes[] = {
        {"x", {stock.min.x, stock.max.x}}, {"y", {stock.min.y, stock.max.y}}, {"z", {stock.min.z, stock.max.z}}};
    for (const auto& [name, range] : axes)
        if (!(range.second > range.first))
            return std::string("the stock's max ") + name + " (" + mm(range.second) + ") is not above its min " + name +
                   " (" + mm(range.first) + ")";
    return std::nullopt;
}

base::Vec3 stockAnchor(const Stock& stock, StockAnchor anchor)
{
    const base::Vec3 lo = stock.min, hi = stock.max;
    const double cx = (lo.x + hi.x) / 2, cy = (lo.y + hi.y) / 2;
    switch (anchor) {
    case StockAnchor::TopFrontLeft:
        return {lo.x, lo.y, hi.z};
    case StockAnchor::BottomFrontLeft:
        return lo;
    case StockAnchor::TopCentre:
        return {cx, cy, hi.z};
    case StockAnchor::Centre:
        return {cx, cy, (lo.z + hi.z) / 2};
    case StockAnchor::BottomCentre:
        break;
    }
    return {cx, cy, lo.z};
}

void moveOrigin(Job& job, const base::Vec3& origin)
{
    const base::Vec3 delta = origin - job.origin;
    job.origin = origin;
    if (!job.stock.fromModel) {
        job.stock.min = job.stock.min - delta;
        job.stock.max = job.stock.max - delta;
    }
    for (Operation& op : job.operations)
        for (std::optional<double>* z :
             {&op.heights.clearanceZ, &op.heights.safeZ, &op.heights.startZ, &op.heights.finalZ})
            if (z->has_value())
                **z -= delta.z;
}

std::vector<std::string> travelShortfalls(const kinematics::Machine& machine, const Stock& stock)
{
    std::vector<std::string> out;
    const auto box = stock.box();
    if (!box)
        return out;
    const base::Vec3 size = box->max - box->min;
    const std::pair<const char*, double> sizes[] = {{"X", size.x}, {"Y", size.y}, {"Z", size.z}};
    for (const auto& [name, length] : sizes) {
        const kinematics::Axis* axis = machine.axis(name);
        if (axis == nullptr || axis->rotary)
            continue;
        const double travel = axis->max - axis->min;
        if (length > travel)
            out.push_back(std::string(name) + ": stock " + mm(length) + " mm, travel " + mm(travel) + " mm");
    }
    return out;
}

}  // namespace camwb::document
