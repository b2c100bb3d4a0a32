// The canonical trace of an interpreted NC program (`camwb-cli nc trace`, the NC goldens): one
// entry per motion (rapid, linear, arc, helix, one per cycle hole) and per dwell, with the
// program line that made it and the state it ran with: feed and its mode, spindle, tool.
// Text: "<line> <kind> <x> <y> <z> [...] f <feed> s <rpm> t <tool>", lines of called programs as
// "<file name>:<line>". JSONL: one object per entry with the same fields. Formats documented in
// docs/architecture.md; 4 decimals, no locale.
#pragma once

#include "toolpath/Toolpath.h"

#include <string>
#include <vector>

namespace camwb::nc {

enum class TraceFormat { Text, Jsonl };

// `program` holds records with SourceRef line/file as the interpreters set them; `files` names
// the files SourceRef::file indexes (InterpretResult::files).
std::string motionTrace(const toolpath::Toolpath& program, const std::vector<std::string>& files, TraceFormat format);

}  // namespace camwb::nc
