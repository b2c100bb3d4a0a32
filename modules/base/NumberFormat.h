// Locale-independent formatting of numbers for NC, traces and files: fixed decimals with
// "-0" normalised to "0", optional trimming of trailing zeros, forced sign and scaling (mm -> inch).
#pragma once

#include <cstddef>
#include <string>

namespace camwb::base {

struct NumberFormat {
    int decimals = 3;
    bool trimTrailingZeros = false;  // "1.500" -> "1.5", "2.000" -> "2" (or "2." with keepDecimalPoint)
    bool keepDecimalPoint = false;   // with trimming: keep the point on whole numbers ("2.")
    bool forceSign = false;          // "+1.000"
    bool leadingZero = true;         // "0.5" vs ".5"
    double scale = 1.0;              // the value is multiplied by this before formatting

    // Buffer size for formatTo(): the longest text (sign, 309 integer digits, point, 12 decimals)
    // plus room to spare.
    static constexpr std::size_t kBufferSize = 344;

    std::string format(double value) const;
    // The same text into `out` (kBufferSize bytes) without allocating; returns its length.
    std::size_t formatTo(double value, char* out) const;
    // The value a reader of format(value) gets back (rounded to the decimals, scale undone).
    double roundedValue(double value) const;
};

// Fixed decimals, rounded (never truncated) from the binary value as printf does:
// 3.3333 * 60 = 199.998 -> "200" at 0 decimals. Independent of the C locale.
std::string formatFixed(double value, int decimals);

// At most `significant` significant digits, fixed or with an exponent, whichever is shorter, and
// without trailing zeros, as printf's "%g" writes them ("1e+300", "0.0001", "1.5"): for a message
// about a value of any size. Independent of the C locale; "inf", "-inf" and "nan" where not finite.
std::string formatGeneral(double value, int significant);

}  // namespace camwb::base
