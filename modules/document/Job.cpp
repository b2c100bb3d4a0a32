#include "document/Job.h"

#include <algorithm>

namespace camwb::document {

const ops::ToolController* Job::tool(int number) const
{
    for (const ops::ToolController& tc : tools)
        if (tc.tool.number == number)
            return &tc;
    return nullptr;
}

const std::string& Operation::name() const
{
    return std::visit([](const auto& p) -> const std::string& { return p.name; }, params);
}

void Operation::setName(const std::string& name)
{
    std::visit([&](auto& p) { p.name = name; }, params);
}

const char* kindName(OperationKind kind)
{
    switch (kind) {
    case OperationKind::Contour:
        return "contour";
    case OperationKind::Pocket:
        return "pocket";
    case OperationKind::Helix:
        return "helix";
    case OperationKind::Drill:
        return "drill";
    case OperationKind::Swarf:
        return "swarf";
    case OperationKind::Pocket3d:
        return "pocket3d";
    case OperationKind::Waterline:
        return "waterline";
    case OperationKind::Parallel:
        return "parallel";
    case OperationKind::Groove:
        return "groove";
    }
    return "operation";
}

const char* kindLabel(OperationKind kind)
{
    if (kind == OperationKind::Drill)
        return "drilling";
    if (kind == OperationKind::Groove)
        return "groove roughing";
    return kind == OperationKind::Pocket3d ? "3D pocket" : kindName(kind);
}

}  // namespace camwb::document

namespace camwb::document {

void Stock::resolve(const base::Vec3& modelMin, const base::Vec3& modelMax)
{
    if (!fromModel)
        return;
    min = modelMin - fromModel->below;
    max = modelMax + fromModel->above;
    if (shape != Shape::Cylinder)
        return;
    // Round stock about the grown box's centre; its bounding box is square in XY.
    const double diameter = std::max(max.x - min.x, max.y - min.y);
    const double cx = (min.x + max.x) / 2, cy = (min.y + max.y) / 2;
    min.x = cx - diameter / 2;
    max.x = cx + diameter / 2;
    min.y = cy - diameter / 2;
    max.y = cy + diameter / 2;
}

std::string workOffsetName(int offset, const std::string& postId)
{
    const std::string n = std::to_string(offset);
    if (postId.rfind("sinumerik", 0) == 0) {
        if (offset >= 1 && offset <= 4)
            return "G" + std::to_string(53 + offset);
        if (offset >= 5 && offset <= 99)
            return "G" + std::to_string(500 + offset);
    } else if (postId.rfind("heidenhain", 0) == 0) {
        if (offset >= 1)
            return "preset " + n;
    } else {
        if (offset >= 1 && offset <= 6)
            return "G" + std::to_string(53 + offset);
        if (offset >= 7 && offset <= 9)
            return "G59." + std::to_string(offset - 6);
    }
    return "offset " + n;
}

}  // namespace camwb::document
