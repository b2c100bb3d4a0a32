// One spelling for the names of CL records and their enums, shared by the text trace, the post
// scripts' arguments and messages, so a name means the same thing everywhere.
#pragma once

#include "toolpath/ClRecords.h"

#include <optional>
#include <string>
#include <string_view>

namespace camwb::toolpath {

const char* name(CutterCompSide side);  // "off", "left", "right"
const char* name(CoolantMode mode);     // "off", "flood", "mist", "throughTool"
const char* name(FeedMode mode);        // "perMinute", "perRevolution", "inverseTime"
const char* name(CycleKind kind);       // "drill", "drillDwell", "peck", "chipBreak", "tap", "bore"
const char* name(FeedKind kind);        // "cutting", "plunge", "entry", "exit", "finishing"; "" unspecified
// The kind a name spells (one of name(FeedKind)'s, not the empty one); nullopt for any other word.
std::optional<FeedKind> feedKindNamed(std::string_view word);
const char* recordName(const Record& record);  // the record's type name: "Rapid", "Arc", ...
// The axes of a mask by name, with blanks between: "x y z" ('x' first), "X Z" ('X' first).
std::string axisNames(AxisMask axes, char first = 'x');

}  // namespace camwb::toolpath
