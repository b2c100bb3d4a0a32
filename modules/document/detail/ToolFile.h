// One tool as JSON, the same keys in a job file's "tools" and a tool library's: number, name,
// kind, geometry, holder, speeds and feeds and the optional "cuttingData" per material. Shared by
// JobFile.cpp and ToolLibrary.cpp so that a tool copied from a library into a job reads the same.
#pragma once

#include "ops/OpCommon.h"

#include <nlohmann/json.hpp>

#include <string>

namespace camwb::document::detail {

// Throws base::jsonread::JsonFieldError naming `where` and the field. `speedsRequired`: a job's
// tool must give spindleRpm, cuttingFeed and plungeFeed; a library's may leave them out (0).
ops::ToolController readTool(const nlohmann::json& t, const std::string& where, bool speedsRequired);
// Optional keys are written only when set, so tools that do not use them read as before.
nlohmann::ordered_json writeTool(const ops::ToolController& tc);

}  // namespace camwb::document::detail
