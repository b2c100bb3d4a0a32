#include "base/NumberFormat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>

namespace camwb::base {

namespace {

constexpr std::size_t kFixedCapacity = NumberFormat::kBufferSize - 2;  // formatTo keeps a spare byte in front

constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12};

// The common case without std::to_chars (a third of a post's time went there): value * 10^d rounded
// to an integer. The product of two doubles is off the exact one by at most half an ulp, below
// 2^-13 while |product| < 2^40, so the rounding is certain unless the fraction is within 0.001 of
// a half: then (and for large values) nullopt sends the caller to std::to_chars. Same text either way.
std::optional<std::size_t> fastFixedTo(double value, int decimals, char* out)
{
    const double scaled = value * kPowersOfTen[decimals];
    if (!(std::abs(scaled) < 1099511627776.0))  // 2^40; also false for NaN
        return std::nullopt;
    const double whole = std::floor(std::abs(scaled));
    const double fraction = std::abs(scaled) - whole;
    if (std::abs(fraction - 0.5) < 0.001)
        return std::nullopt;
    unsigned long long digits = static_cast<unsigned long long>(whole) + (fraction > 0.5 ? 1 : 0);
    char reversed[24];
    int count = 0;
    do {
        reversed[count++] = static_cast<char>('0' + digits % 10);
        digits /= 10;
    } while (digits > 0 || count <= decimals);  // at least one digit before the point
    std::size_t length = 0;
    const bool zero = count == decimals + 1 && std::all_of(reversed, reversed + count, [](char c) { return c == '0'; });
    if (scaled < 0 && !zero)  // "-0.000" is never written
        out[length++] = '-';
    for (int i = count - 1; i >= 0; --i) {
        out[length++] = reversed[i];
        if (i == decimals && decimals > 0)
            out[length++] = '.';
    }
    return length;
}

// Fixed text of `value` into out (kFixedCapacity bytes); "-0.000" becomes "0.000".
std::size_t fixedTo(double value, int decimals, char* out)
{
    if (decimals >= 0 && decimals <= 12)
        if (const std::optional<std::size_t> length = fastFixedTo(value, decimals, out))
            return *length;
    if (!std::isfinite(value)) {
        std::memcpy(out, "nan", 3);
        return 3;
    }
    // std::to_chars is locale-independent and correctly rounded from the binary value.
    auto [end, ec] = std::to_chars(out, out + kFixedCapacity, value, std::chars_format::fixed, decimals);
    if (ec != std::errc()) {
        std::memcpy(out, "nan", 3);
        return 3;
    }
    std::size_t length = static_cast<std::size_t>(end - out);
    if (out[0] == '-') {
        bool allZero = true;
        for (std::size_t i = 1; i < length && allZero; ++i)
            allZero = out[i] == '0' || out[i] == '.';
        if (allZero) {
            std::memmove(out, out + 1, length - 1);
            --length;
        }
    }
    return length;
}

}  // namespace

std::string formatFixed(double value, int decimals)
{
    char buffer[kFixedCapacity];
    return std::string(buffer, fixedTo(value, decimals, buffer));
}

std::size_t NumberFormat::formatTo(double value, char* out) const
{
    // One spare byte at the front so that a forced '+' can be prepended without moving the text.
    char* text = out + 1;
    std::size_t length = fixedTo(value * scale, decimals, text);
    if (trimTrailingZeros && std::memchr(text, '.', length)) {
        while (text[length - 1] == '0')
            --length;
        if (text[length - 1] == '.' && !keepDecimalPoint)
            --length;
        if (length == 0 || (length == 1 && text[0] == '-') || (length == 2 && text[0] == '-' && text[1] == '.')) {
            text[0] = '0';
            length = 1;
        }
    }
    if (!leadingZero) {
        if (length > 2 && text[0] == '0' && text[1] == '.') {
            ++text;
            --length;
        } else if (length > 3 && text[0] == '-' && text[1] == '0' && text[2] == '.') {
            text[1] = '-';
            ++text;
            --length;
        }
    }
    if (forceSign && text[0] != '-') {
        --text;
        text[0] = '+';
        ++length;
    }
    std::memmove(out, text, length);
    return length;
}

std::string NumberFormat::format(double value) const
{
    char buffer[kBufferSize];
    return std::string(buffer, formatTo(value, buffer));
}

}  // namespace camwb::base
