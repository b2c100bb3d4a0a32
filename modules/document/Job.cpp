#include "document/Job.h"

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
    }
    return "operation";
}

const char* kindLabel(OperationKind kind) { return kind == OperationKind::Drill ? "drilling" : kindName(kind); }

}  // namespace camwb::document
