// Locale-independent formatting of numbers for NC, traces and files: fixed decimals with
// "-0" normalised to "0", optional trimming of trailing zeros and optional forced sign.
#pragma once

#include <string>

namespace camwb::base {

struct NumberFormat {
    int decimals = 3;
    bool trimTrailingZeros = false;  // "1.500" -> "1.5", "2.000" -> "2" (or "2." with keepDecimalPoint)
    bool keepDecimalPoint = false;   // with trimming: keep the point on whole numbers ("2.")
    bool forceSign = false;          // "+1.000"
    bool leadingZero = true;         // "0.5" vs ".5"

    std::string format(double value) const;
};

// Fixed decimals, rounded (never truncated) from the binary value as printf does:
// 3.3333 * 60 = 199.998 -> "200" at 0 decimals. Independent of the C locale.
std::string formatFixed(double value, int decimals);

}  // namespace camwb::base
