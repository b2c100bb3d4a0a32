// Reads CAM Workbench's canonical CL trace (TraceWriter's format, docs/architecture.md) back into
// a toolpath, so that a trace can be the input of a golden post test holding every CL record type
// exactly, and traceOf(readTrace(t)) == t holds. Blank lines and lines starting with '#' are
// allowed for notes in hand-written test inputs.
#pragma once

#include "base/LineReader.h"
#include "toolpath/ClImport.h"

#include <string>
#include <string_view>

namespace camwb::toolpath {

// SourceRefs as the CL importers give them (ClImport.h): section index and 1-based line.
// A malformed line gives an Error with its line and the column of the offending field.
base::Result<ClImport> readTrace(std::string_view text, const std::string& fileName);
base::Result<ClImport> readTrace(base::LineReader& lines, const std::string& fileName);

}  // namespace camwb::toolpath
