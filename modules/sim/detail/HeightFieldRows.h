// What the height field's sweeps share row by row: the column index of an x, and the loop that
// lowers a row's span of columns. In a header so that each sweep's file inlines them (a call per
// span cost as much as an arc piece's span of a column or two).
#pragma once

#include "sim/HeightField.h"

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
    const float* bottom = &m_bottom[row];
    const float* design = m_design.empty() ? nullptr : &m_design[row];
    std::int32_t* lastCut = &m_lastCut[row];
    int first = -1, last = -1;
    // Summed here and added once: kept in `result`, the sum would go through memory each column
    // (a store and a load a column's critical path; the loop ran at half speed).
    double removed = 0;
    for (int i = i0; i <= i1; ++i) {
        if (top[i] <= height + detail::kEps)
            continue;
        const double newTop = std::max(height, double(bottom[i]));
        if (newTop >= top[i] - detail::kEps)
            continue;
        removed += top[i] - newTop;
        top[i] = float(newTop);
        lastCut[i] = std::int32_t(moveIndex);
        first = first < 0 ? i : first, last = i;
        if (design && newTop < design[i] - m_tolerance)
            noteGouge(i, j, newTop, result);
    }
    if (first >= 0)
        m_cutNow.add(first, j), m_cutNow.add(last, j), result.removedMm3 += removed * m_dx * m_dy;
}

}  // namespace camwb::sim
