#include "document/Job.h"

namespace camwb::document {

const ops::ToolController* Job::tool(int number) const
{
    for (const ops::ToolController& tc : tools)
        if (tc.tool.number == number)
            return &tc;
    return nullptr;
}

}  // namespace camwb::document
