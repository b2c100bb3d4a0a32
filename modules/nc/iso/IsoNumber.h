// The decimal number scanner of the ISO reader, the innermost loop of the interpreter: digits with
// an optional sign and point, blanks allowed anywhere (RS274NGC removes them before reading), no
// exponent. Most program numbers convert exactly from a 64-bit mantissa and a power of ten; the
// rest go through std::from_chars, so every result is the correctly rounded double.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>

namespace camwb::nc::iso {

// Character classes by table: one load and test per character in the scanning loops.
inline constexpr unsigned char kBlankClass = 1, kLetterClass = 2;
inline constexpr auto kCharClass = [] {
    std::array<unsigned char, 256> table{};
    table[' '] = table['\t'] = table['\r'] = kBlankClass;
    for (int c = 'a'; c <= 'z'; ++c)
        table[static_cast<std::size_t>(c)] = table[static_cast<std::size_t>(c - 32)] = kLetterClass;
    return table;
}();

inline bool isBlank(char c) { return kCharClass[static_cast<unsigned char>(c)] & kBlankClass; }
inline bool isLetter(char c) { return kCharClass[static_cast<unsigned char>(c)] & kLetterClass; }
inline bool isDigit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

enum class NumberStatus { Ok, NotANumber, TooLong };

inline constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// The general case: blanks inside the number or more digits than a 64-bit mantissa holds. The
// digits are copied without blanks and the library rounds.
inline NumberStatus scanUnsignedSlow(const char*& p, const char* end, double& out)
{
    char buffer[128];
    int n = 0;
    int digits = 0;
    const char* q = p;
    const char* last = p;
    bool point = false;
    while (q < end) {
        const char c = *q;
        if (isDigit(c) || (c == '.' && !point)) {
            if (n >= static_cast<int>(sizeof buffer))
                return NumberStatus::TooLong;
            point = point || c == '.';
            digits += c != '.';
            buffer[n++] = c;
            last = ++q;
        } else if (isBlank(c)) {
            ++q;
        } else {
            break;
        }
    }
    if (digits == 0)
        return NumberStatus::NotANumber;
    const auto result = std::from_chars(buffer, buffer + n, out, std::chars_format::fixed);
    if (result.ec != std::errc())
        return NumberStatus::TooLong;
    p = last;
    return NumberStatus::Ok;
}

// Reads an unsigned decimal number (digits, at most one point, at least one digit) at `p`. On
// success `p` is past the number (and any blanks inside it, not after it). Up to 19 digits the
// value is mantissa / 10^decimals, exact in both and so correctly rounded (as strtod would).
inline NumberStatus scanUnsigned(const char*& p, const char* end, double& out)
{
    const char* q = p;
    std::uint64_t mantissa = 0;
    long fraction = 0;
    while (q < end && isDigit(*q))
        mantissa = mantissa * 10 + static_cast<unsigned>(*q++ - '0');
    const long whole = q - p;
    if (q < end && *q == '.') {
        const char* first = ++q;
        while (q < end && isDigit(*q))
            mantissa = mantissa * 10 + static_cast<unsigned>(*q++ - '0');
        fraction = q - first;
    }
    if (q < end && isBlank(*q)) {  // usually the blank before the next word; rarely inside this number
        const char* after = q + 1;
        while (after < end && isBlank(*after))
            ++after;
        if (after < end && (isDigit(*after) || *after == '.'))
            return scanUnsignedSlow(p, end, out);
    }
    if (static_cast<unsigned long>(whole + fraction - 1) >= 19 || mantissa >= (std::uint64_t{1} << 53))
        return scanUnsignedSlow(p, end, out);
    const double m = static_cast<double>(mantissa);
    out = fraction == 0 ? m : m / kPow10[fraction];
    p = q;
    return NumberStatus::Ok;
}

}  // namespace camwb::nc::iso
