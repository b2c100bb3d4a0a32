#include "base/NumberFormat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <type_traits>
#include <utility>

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

[[gnu::always_inline]] inline std::optional<ScaledDigits> fastScaled(double value, int decimals)
{
    if (decimals < 0 || decimals > 12)
        return std::nullopt;
    const double scaled = value * kPowersOfTen[decimals];
    if (!(std::abs(scaled) < 1099511627776.0))  // 2^40; also false for NaN
        return std::nullopt;
    // Below 2^40 the conversion truncates exactly (a floor, without calling floor()).
    const unsigned long long whole = static_cast<unsigned long long>(std::abs(scaled));
    const double fraction = std::abs(scaled) - static_cast<double>(whole);
    if (std::abs(fraction - 0.5) < 0.001)
        return std::nullopt;
    return ScaledDigits{whole + (fraction > 0.5 ? 1 : 0), scaled < 0};
}

// "00" to "99": two digits per division.
constexpr char kDigitPairs[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                               "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                               "8081828384858687888990919293949596979899";

// Exactly Count digits of `value` (below 10^Count) ending just before `end`, two at a time.
template <int Count, class Unsigned> void writeDigits(Unsigned value, char* end)
{
    if constexpr (Count >= 2) {
        std::memcpy(end - 2, kDigitPairs + 2 * (value % 100), 2);
        writeDigits<Count - 2>(static_cast<Unsigned>(value / 100), end - 2);
    } else if constexpr (Count == 1) {
        end[-1] = static_cast<char>('0' + value);
    }
}

// All digits of `value` ending just before `end`, two at a time.
template <class Unsigned> void writeDigits(Unsigned value, char* end)
{
    while (value >= 100) {
        end -= 2;
        std::memcpy(end, kDigitPairs + 2 * (value % 100), 2);
        value /= 100;
    }
    if (value >= 10)
        std::memcpy(end - 2, kDigitPairs + 2 * value, 2);
    else
        end[-1] = static_cast<char>('0' + value);
}

// The whole part, the point and the decimals of scaled.digits written in place (no std::to_chars,
// no copies): the trace writes eight numbers a block, and this was most of its time. The
// decimals are a template argument so that the split at the point and the digits of the fraction
// are divisions by constants, in 32 bits where the numbers fit.
template <int Decimals> std::size_t fastFixedTo(const ScaledDigits& scaled, char* out)
{
    char* p = out;
    if (scaled.negative && scaled.digits != 0)  // "-0.000" is never written
        *p++ = '-';
    constexpr unsigned long long power = kIntegerPowersOfTen[Decimals];
    const unsigned long long whole = scaled.digits / power;
    int wholeDigits = 1;  // fastScaled keeps scaled.digits below 2^40 < 10^13
    while (wholeDigits < 13 && whole >= kIntegerPowersOfTen[wholeDigits])
        ++wholeDigits;
    p += wholeDigits;
    if (whole <= 0xffffffffull)
        writeDigits(static_cast<std::uint32_t>(whole), p);
    else
        writeDigits(whole, p);
    if constexpr (Decimals > 0) {
        *p++ = '.';
        using Fraction = std::conditional_t<(Decimals <= 9), std::uint32_t, unsigned long long>;
        writeDigits<Decimals>(static_cast<Fraction>(scaled.digits % power), p + Decimals);
        p += Decimals;
    }
    return static_cast<std::size_t>(p - out);
}

template <std::size_t... D>
std::size_t fastFixedTo(const ScaledDigits& scaled, int decimals, char* out, std::index_sequence<D...>)
{
    using Writer = std::size_t (*)(const ScaledDigits&, char*);
    static constexpr Writer writers[] = {&fastFixedTo<static_cast<int>(D)>...};
    return writers[decimals](scaled, out);
}

// decimals: 0 to 12, as fastScaled checked.
std::size_t fastFixedTo(const ScaledDigits& scaled, int decimals, char* out)
{
    return fastFixedTo(scaled, decimals, out, std::make_index_sequence<13>());
}

// fixedTo() for what the shortcut leaves: large values, ties, NaN and infinities.
[[gnu::noinline]] std::size_t slowFixedTo(double value, int decimals, char* out)
{
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

// Fixed text of `value` into out (kFixedCapacity bytes); "-0.000" becomes "0.000". Inlined: the
// shortcut is a few dozen instructions, and calls around it cost as much.
[[gnu::always_inline]] inline std::size_t fixedTo(double value, int decimals, char* out)
{
    if (const std::optional<ScaledDigits> scaled = fastScaled(value, decimals))
        return fastFixedTo(*scaled, decimals, out);
    return slowFixedTo(value, decimals, out);
}

}  // namespace

std::string formatFixed(double value, int decimals)
{
    char buffer[kFixedCapacity];
    return std::string(buffer, fixedTo(value, decimals, buffer));
}

std::string formatGeneral(double value, int significant)
{
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general,
                                         std::clamp(significant, 1, 17));
    return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
}

std::size_t NumberFormat::formatTo(double value, char* out) const
{
    if (!trimTrailingZeros && leadingZero && !forceSign)  // plain fixed decimals: nothing to adjust
        return fixedTo(value * scale, decimals, out);
    // A spare byte at the front when a '+' may be prepended; otherwise the text is written in place.
    char* text = forceSign ? out + 1 : out;
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
    if (text != out)
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
