// The Fusion 360 tool library reader behind importFusionLibrary (ToolLibraryImport.h): the parsed
// JSON to our tools. Throws base::jsonread::JsonFieldError naming the field.
#pragma once

#include "document/ToolLibraryImport.h"

#include <nlohmann/json.hpp>

#include <string>

namespace camwb::document::detail {

ImportedTools readFusionLibrary(const nlohmann::json& root, const std::string& path);

}  // namespace camwb::document::detail
