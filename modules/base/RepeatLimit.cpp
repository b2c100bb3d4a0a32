#include "base/RepeatLimit.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <cmath>

namespace camwb::base {

namespace {

std::string fmt(double v) { return NumberFormat{4, true}.format(v); }

// A value that may be far below four decimals (a slip's), to its first significant digits.
std::string significant(double v)
{
    return NumberFormat{std::clamp(4 - int(std::floor(std::log10(v))), 4, 12), true}.format(v);
}

}  // namespace

std::optional<std::string> tooManyRepeats(const std::string& parameter, double valueMm, double spanMm,
                                          const std::string& repeats, const std::string& who)
{
    if (!(valueMm > 0) || !(spanMm > 0) || spanMm / valueMm <= kMaxRepeats)
        return std::nullopt;
    return parameter + " " + significant(valueMm) + " mm makes " + fmt(std::ceil(spanMm / valueMm)) + " " + repeats +
           " over " + fmt(spanMm) + " mm, more than the " + fmt(kMaxRepeats) + " " + who + " may make; use at least " +
           significant(spanMm / kMaxRepeats) + " mm";
}

}  // namespace camwb::base
