#include "base/NumberFormat.h"

#include <charconv>
#include <cmath>

namespace camwb::base {

std::string formatFixed(double value, int decimals)
{
    if (!std::isfinite(value))
        return "nan";
    char buffer[64];
    // std::to_chars is locale-independent and correctly rounded from the binary value.
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    if (ec != std::errc())
        return "nan";
    std::string text(buffer, end);
    // "-0.000" -> "0.000": a negative zero is never written.
    if (text[0] == '-' && text.find_first_not_of("0.", 1) == std::string::npos)
        text.erase(0, 1);
    return text;
}

std::string NumberFormat::format(double value) const
{
    std::string text = formatFixed(value, decimals);
    if (trimTrailingZeros && text.find('.') != std::string::npos) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.' && !keepDecimalPoint)
            text.pop_back();
        if (text == "-" || text == "-." || text.empty())
            text = "0";
    }
    if (!leadingZero) {
        if (text.rfind("0.", 0) == 0 && text.size() > 2)
            text.erase(0, 1);
        else if (text.rfind("-0.", 0) == 0 && text.size() > 3)
            text.erase(1, 1);
    }
    if (forceSign && text[0] != '-')
        text.insert(text.begin(), '+');
    return text;
}

}  // namespace camwb::base
