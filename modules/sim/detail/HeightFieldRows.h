// What the height field's sweeps share row by row: the column index of an x, and the loop that
// lowers a row's span of columns. In a header so that each sweep's file inlines them (a call per
// span cost as much as an arc piece's span of a column or two).
#pragma once

#include "sim/HeightField.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace camwb::sim::detail {

constexpr double kEps = 1e-6;  // heights closer than this are the same (float storage)

// floor and ceil to int for the column indices (well within int's range): the same values as
// std::floor and std::ceil, without the checks for huge arguments that x86-64's baseline (no
// SSE4.1 rounding instruction) makes them take, a good part of a row's cost.
inline int floorToInt(double u)
{
    const int t = int(u);  // towards zero
    return t - int(double(t) > u);
}
inline int ceilToInt(double u)
{
    const int t = int(u);
    return t + int(double(t) < u);
}

// The highest float at or below x (no library call: a span's setup is on the hot path).
inline float floatAtOrBelow(double x)
{
    const float f = float(x);
    if (double(f) <= x)
        return f;
    if (f == 0)
        return -std::numeric_limits<float>::denorm_min();
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    bits = f > 0 ? bits - 1 : bits + 1;  // one step towards -infinity
    float down;
    std::memcpy(&down, &bits, sizeof down);
    return down;
}

// The columns whose centres lie at or right of an x, or at or left of it, from x by one
// multiplication (the rows' critical path was a division). x must lie within a grid's width or so
// of the grid (an int's range).
struct ColumnIndex {
    ColumnIndex(double minX, double dx) : perColumn(1 / dx), offset(minX * perColumn + 0.5) {}
    int atOrRight(double x) const { return ceilToInt(x * perColumn - offset); }
    int atOrLeft(double x) const { return floorToInt(x * perColumn - offset); }
    double perColumn, offset;
};

}  // namespace camwb::sim::detail

namespace camwb::sim {

// Lowers the columns i0..i1 of row j to `height` (never below their bottoms): the level flat
// cut's inner loop, with the changed rectangle grown once per row rather than per column. Inlined
// by force: an arc piece's crescent is a column or two a row, where a call costs as much as the
// loop (GCC would not inline it into cutVertical, and the 20k-block benchmark ran 4 % slower).
[[gnu::always_inline]] inline void HeightField::lowerSpan(int j, int i0, int i1, double height, std::size_t moveIndex,
                                                          CutResult& result)
{
    const std::size_t row = index(0, j);
    float* top = &m_top[row];
    const float* bottom = m_bottom.empty() ? nullptr : &m_bottom[row];
    const double level = std::max(height, double(m_floor));  // a block's columns' new top
    const float* design = m_design.empty() ? nullptr : &m_design[row];
    std::int32_t* lastCut = m_lastCut.empty() ? nullptr : &m_lastCut[row];
    int first = -1, last = -1;
    // Summed here and added once: kept in `result`, the sum would go through memory each column
    // (a store and a load a column's critical path; the loop ran at half speed).
    double removed = 0;
    const double limit = height + detail::kEps;  // a column at or below this is left
    auto lowerColumn = [&](int i) {
        if (top[i] <= limit)
            return;
        const double newTop = bottom ? std::max(height, double(bottom[i])) : level;
        if (newTop >= top[i] - detail::kEps)
            return;
        // What the column loses as stored: the losses of cuts in any order add up to the same.
        const float stored = float(newTop);
        removed += double(top[i]) - stored;
        top[i] = stored;
        first = first < 0 ? i : first, last = i;
        if (design) {
            lastCut[i] = std::int32_t(moveIndex);
            if (newTop < design[i] - m_tolerance)
                noteGouge(i, j, newTop, result);
        }
    };
    int i = i0;
#ifdef __SSE2__
    // A long span passes runs of columns that are left four at a time: most of an arc's span lies
    // on ground the cut before cleared. The float bound is at or below `limit`, so a column passed
    // here would have been left by lowerColumn too.
    if (i1 - i0 >= 7) {
        const __m128 skip = _mm_set1_ps(detail::floatAtOrBelow(limit));
        for (; i + 3 <= i1; i += 4)
            if (_mm_movemask_ps(_mm_cmpgt_ps(_mm_loadu_ps(top + i), skip)) != 0)
                lowerColumn(i), lowerColumn(i + 1), lowerColumn(i + 2), lowerColumn(i + 3);
    }
#endif
    for (; i <= i1; ++i)
        lowerColumn(i);
    if (first >= 0)
        m_cutNow.add(first, j), m_cutNow.add(last, j), result.removedMm3 += removed * m_dx * m_dy;
}

}  // namespace camwb::sim
