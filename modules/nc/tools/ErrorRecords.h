// Which records of an interpreted program come from blocks with an error diagnostic (an arc whose
// radii disagree, a malformed word). Such a record is not what the program means: the backplot
// draws it as a marked straight segment and the program statistics leave it out of the extents.
#pragma once

#include "nc/Interpreter.h"
#include "toolpath/Toolpath.h"

#include <vector>

namespace camwb::nc {

// One flag per record of `program` (recorded with the SourceRef file/line the interpreter set):
// true when an error of `result` names the record's file and line. Empty when there is no error.
std::vector<bool> recordsInError(const toolpath::Toolpath& program, const InterpretResult& result);

}  // namespace camwb::nc
