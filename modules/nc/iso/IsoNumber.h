// The decimal number scanner of the ISO reader, the innermost loop of the interpreter: digits with
// an optional sign and point, blanks allowed anywhere (RS274NGC removes them before reading), no
// exponent. Most program numbers convert exactly from a 64-bit mantissa and a power of ten; the
// rest go through std::from_chars, so every result is the correctly rounded double.
#pragma once

#include <charconv>
#include <cstdint>

namespace camwb::nc::iso {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
inline bool isDigit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

enum class NumberStatus { Ok, NotANumber, TooLong };

// Reads an unsigned decimal number (digits, at most one point, at least one digit) at `p`. On
// success `p` is past the number (and any blanks inside it, not after it).
inline NumberStatus scanUnsigned(const char*& p, const char* end, double& out)
{
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char* q = p;
    std::uint64_t mantissa = 0;
    int digits = 0;    // significant digits kept in the mantissa
    int fraction = 0;  // digits after the point
    int any = 0;       // digits seen at all
    bool point = false;
    const char* last = q;  // just past the last digit or point
    while (q < end) {
        const char c = *q;
        if (isDigit(c)) {
            if (mantissa != 0 || c != '0') {
                if (++digits > 19)
                    break;
                mantissa = mantissa * 10 + static_cast<unsigned>(c - '0');
            }
            if (point)
                ++fraction;
            ++any;
            last = ++q;
        } else if (c == '.' && !point) {
            point = true;
            last = ++q;
        } else if (isBlank(c)) {
            ++q;
        } else {
            break;
        }
    }
    if (any == 0)
        return NumberStatus::NotANumber;
    if (digits <= 19 && mantissa < (std::uint64_t{1} << 53) && fraction <= 22 &&
        !(q < end && (isDigit(*q) || *q == '.'))) {
        const double m = static_cast<double>(mantissa);
        out = fraction == 0 ? m : m / kPow10[fraction];
        p = last;
        return NumberStatus::Ok;
    }
    // Rare: many digits. Copy the digits without blanks and let the library round.
    char buffer[128];
    int n = 0;
    q = p;
    bool seenPoint = false;
    while (q < end) {
        const char c = *q;
        if (isDigit(c) || (c == '.' && !seenPoint)) {
            if (n >= static_cast<int>(sizeof buffer))
                return NumberStatus::TooLong;
            seenPoint = seenPoint || c == '.';
            buffer[n++] = c;
            last = ++q;
        } else if (isBlank(c)) {
            ++q;
        } else {
            break;
        }
    }
    const auto result = std::from_chars(buffer, buffer + n, out, std::chars_format::fixed);
    if (result.ec != std::errc())
        return NumberStatus::TooLong;
    p = last;
    return NumberStatus::Ok;
}

}  // namespace camwb::nc::iso
