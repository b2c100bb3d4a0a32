// A tool library: the tools a shop keeps (geometry, holder, cutting data per material), in a JSON
// file of its own ("format": "camwb-tools"), from which tools are copied into jobs so that a job
// file stays self-contained. The user's library lives in the user data dir (the GUI finds it);
// a default library ships in resources/tools/. Imports from other CAM systems: ToolLibraryImport.h.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "ops/OpCommon.h"

#include <string>
#include <vector>

namespace camwb::document {

inline constexpr int kToolLibraryFormatVersion = 1;

struct ToolLibrary {
    std::string name;
    std::vector<ops::ToolController> tools;  // the same tool as a job's; speeds may be 0 in a library
};

// Errors name the file and the field ("lib.json: library.tools[2].diameter: expected a number")
// or the line and column of malformed JSON. A newer version is refused, not guessed.
base::Result<ToolLibrary> parseToolLibrary(const std::string& text, const std::string& pathForMessages);
base::Result<ToolLibrary> loadToolLibrary(const std::string& path);
std::string serializeToolLibrary(const ToolLibrary& library);
// Atomic: the file on disk is the old one or the complete new one.
base::Status saveToolLibrary(const ToolLibrary& library, const std::string& path);

// The lowest tool number from `wanted` up that no tool of `tools` has.
int nextFreeToolNumber(const std::vector<ops::ToolController>& tools, int wanted);

// Copies `tools` into the job; a tool whose number the job already has gets the next free one,
// and a note says so ("T1 \"Flat end mill D10\" added as T4: T1 is taken"). The notes, in order.
std::vector<std::string> addToolsToJob(Job& job, const std::vector<ops::ToolController>& tools);

}  // namespace camwb::document
