// A parameter repeated over a span (a step-down over a depth, a pitch or a peck down a hole): the
// one message for a count beyond the limit. Such a count is a slip of the keyboard (0.0001 for 1)
// whose toolpath, or whose expansion in the simulator, would fill the memory before anyone saw it.
#pragma once

#include <optional>
#include <string>

namespace camwb::base {

// The most times one parameter repeats in an operation or in a cycle's hole.
inline constexpr double kMaxRepeats = 10000;

// Nothing when `parameter` of `valueMm` repeats at most kMaxRepeats times over `spanMm` (or either
// is not positive); else "<parameter> <value> mm makes <n> <repeats> over <span> mm, more than the
// 10000 <who> may make; use at least <least> mm".
std::optional<std::string> tooManyRepeats(const std::string& parameter, double valueMm, double spanMm,
                                          const std::string& repeats, const std::string& who);

}  // namespace camwb::base
