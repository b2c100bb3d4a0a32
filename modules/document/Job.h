// The job: what the user edits and saves (.camwb). Derived data (model shape, toolpaths, NC)
// is never stored here; JobPipeline recomputes it.
#pragma once

#include "base/Vec.h"
#include "ops/ProfileOp.h"

#include <map>
#include <string>
#include <vector>

namespace camwb::document {

struct Stock {
    base::Vec3 min;
    base::Vec3 max;
};

// One operation of the job. Only the outer-boundary profile exists so far; `type` names it in
// the file so that later operation kinds extend the format instead of changing it.
struct Operation {
    std::string type = "profile";
    int toolNumber = 1;
    ops::ProfileParams profile;
};

struct Job {
    std::string name;
    std::string modelPath;  // as written in the file: relative to the job file's folder
    Stock stock;
    int workOffset = 1;  // 1 = G54
    std::vector<ops::ToolController> tools;
    std::vector<Operation> operations;
    std::string postId = "sinumerik828d-emco";
    std::map<std::string, std::string> postProperties;  // values as text, by property name
    std::string machineId;                              // empty: the post's default machine

    const ops::ToolController* tool(int number) const;
};

}  // namespace camwb::document
