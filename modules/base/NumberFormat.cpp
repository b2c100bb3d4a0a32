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
constexpr unsigned long long kIntegerPowersOfTen[] = {
    1ull,        10ull,        100ull,        1000ull,        10000ull,        100000ull,       1000000ull,
    10000000ull, 100000000ull, 1000000000ull, 10000000000ull, 100000000000ull, 1000000000000ull};

// value * 10^d rounded to an integer, without std::to_chars (a third of a post's time went there).
// The product of two doubles is off the exact one by at most half an ulp, below 2^-13 while
// |product| < 2^40, so the rounding is certain unless the fraction is within 0.001 of a half: then
// (and for large values) nullopt sends the caller to std::to_chars. Same result either way.
struct ScaledDigits {
    unsigned long long digits;  // |value| * 10^d, rounded
    bool negative;
};

std::optional<ScaledDigits> fastScaled(double value, int decimals)
{
    if (decimals < 0 || decimals > 12)
        return std::nullopt;
    const double scaled = value * kPowersOfTen[decimals];
    if (!(std::abs(scaled) < 1099511627776.0))  // 2^40; also false for NaN
        return std::nullopt;
    const double whole = std::floor(std::abs(scaled));
    const double fraction = std::abs(scaled) - whole;
    if (std::abs(fraction - 0.5) < 0.001)
        return std::nullopt;
    return ScaledDigits{static_cast<unsigned long long>(whole) + (fraction > 0.5 ? 1 : 0), scaled < 0};
}

std::size_t fastFixedTo(const ScaledDigits& scaled, int decimals, char* out)
{
    char* p = out;
    if (scaled.negative && scaled.digits != 0)  // "-0.000" is never written
        *p++ = '-';
    const unsigned long long power = kIntegerPowersOfTen[decimals];
    p = std::to_chars(p, p + 24, scaled.digits / power).ptr;
    if (decimals > 0) {
        *p++ = '.';
        char fraction[16];
        const char* end = std::to_chars(fraction, fraction + sizeof fraction, scaled.digits % power).ptr;
        const int length = static_cast<int>(end - fraction);
        std::memset(p, '0', static_cast<std::size_t>(decimals - length));  // leading zeros of the fraction
        std::memcpy(p + decimals - length, fraction, static_cast<std::size_t>(length));
        p += decimals;
    }
    return static_cast<std::size_t>(p - out);
}

// Fixed text of `value` into out (kFixedCapacity bytes); "-0.000" becomes "0.000".
std::size_t fixedTo(double value, int decimals, char* out)
{
    if (const std::optional<ScaledDigits> scaled = fastScaled(value, decimals))
        return fastFixedTo(*scaled, decimals, out);
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

double NumberFormat::roundedValue(double value) const
{
    if (const std::optional<ScaledDigits> scaled = fastScaled(value * scale, decimals)) {
        // An integer over a power of ten, both exact: the division is the double nearest the decimal
        // text, just as reading the text back would give.
        const double read = static_cast<double>(scaled->digits) / kPowersOfTen[decimals];
        return (scaled->negative ? -read : read) / scale;
    }
    char buffer[kBufferSize];
    const std::size_t length = formatTo(value, buffer);
    const char* begin = buffer[0] == '+' ? buffer + 1 : buffer;
    double read = value;
    if (std::from_chars(begin, buffer + length, read).ec != std::errc())
        return value;
    return read / scale;
}

std::string NumberFormat::format(double value) const
{
    char buffer[kBufferSize];
    return std::string(buffer, formatTo(value, buffer));
}

}  // namespace camwb::base
