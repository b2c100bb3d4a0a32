// Reading and writing one operation of a .camwb file (JobFile.cpp does the rest of the job).
// Version 3 layout: {"type", "name", "tool", "geometry": {"faces", "edges", "holes"},
// "heights": {only the overridden ones of "clearance", "safe", "start", "final"}, "params": {...}}.
// Versions 1-2 had only {"type": "profile", "face", "finalDepth", "safeHeight", "clearanceHeight",
// "direction"}; it is read as an outside contour of that face with those heights overridden.
#pragma once

#include "base/JsonRead.h"
#include "document/Job.h"

namespace camwb::document::detail {

// Throws base::jsonread::JsonFieldError naming the field ("job.operations[1].params.stepover: ...").
Operation readOperation(const base::jsonread::Json& o, const std::string& where);
// A "postProperties" object (the job's, or an operation's own): values kept as text, the post's
// declaration decides their type when the job is posted.
std::map<std::string, std::string> readPostProperties(const base::jsonread::Json& object, const std::string& where);
nlohmann::ordered_json writeOperation(const Operation& op);

// Reads the parameters `params` gives into op's (the others keep their values), as the file's
// "params" object is read: by key or alias, unknown keys and wrong types are errors.
void readOperationParams(Operation& op, const base::jsonread::Json& params, const std::string& where);
// The keys of op's parameters in the file, then their aliases (the groove's R names).
std::vector<std::string> operationParamNames(const Operation& op);

}  // namespace camwb::document::detail
