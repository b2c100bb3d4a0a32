// Which axes an NC program has put at a known place: none at the program start, because the
// control does not know where the tool is either, until a block gives an axis in absolute terms
// (issue 11: never invent a coordinate). The three interpreters keep one beside their position:
// moves carry the known axes only (toolpath::AxisMask) while one is unknown, and a block that needs
// an unknown axis's value (incremental word, arc start, cycle, compensation) is an error.
#pragma once

#include "toolpath/MachineSink.h"

#include <string>
#include <string_view>

namespace camwb::nc {

struct InterpretOptions;

inline constexpr toolpath::AxisMask axisBit(int axis)
{
    return toolpath::AxisMask{static_cast<unsigned char>(1u << axis)};
}
inline constexpr toolpath::AxisMask kNoAxes{0};
inline constexpr toolpath::AxisMask kXyAxes{toolpath::AxisMask::kX | toolpath::AxisMask::kY};
inline constexpr toolpath::AxisMask operator|(toolpath::AxisMask a, toolpath::AxisMask b)
{
    return toolpath::AxisMask{static_cast<unsigned char>(a.bits | b.bits)};
}

// The axes of the working plane G17, G18 or G19 (17, 18, 19): those an arc's start needs.
inline constexpr toolpath::AxisMask planeMask(int plane)
{
    return plane == 18 ? axisBit(0) | axisBit(2) : plane == 19 ? axisBit(1) | axisBit(2) : kXyAxes;
}

class KnownAxes {
public:
    // The axes a move carries: all of them once every axis is known.
    toolpath::AxisMask mask() const { return m_known; }
    bool complete() const { return m_known.all(); }
    bool has(int axis) const { return m_known.has(axis); }
    void give(toolpath::AxisMask axes) { m_known.bits |= axes.bits; }
    void forget() { m_known = kNoAxes; }
    void forget(toolpath::AxisMask axes) { m_known.bits &= static_cast<unsigned char>(~axes.bits); }
    // Forgets `axes` for a move to where the program does not say (G53, SUPA, M91, MB MAX): the
    // sink hears of those that were known in an UnknownAxes record (after the caller has set the
    // block's source), so that it forgets them too. Returns them.
    toolpath::AxisMask lose(toolpath::AxisMask axes, toolpath::MachineSink& sink)
    {
        const toolpath::AxisMask lost{static_cast<unsigned char>(m_known.bits & axes.bits)};
        forget(axes);
        if (!lost.none())
            sink.unknownAxes(toolpath::UnknownAxes{lost});
        return lost;
    }

    // The first axis a block cannot do without (0 X, 1 Y, 2 Z), or -1: one of `before` unknown
    // now, or one of `after` neither known now nor given in absolute terms by the block (`given`).
    int missing(toolpath::AxisMask before, toolpath::AxisMask after = kNoAxes, toolpath::AxisMask given = kNoAxes) const
    {
        for (int axis = 0; axis < 3; ++axis)
            if (!has(axis) && (before.has(axis) || (after.has(axis) && !given.has(axis))))
                return axis;
        return -1;
    }

private:
    toolpath::AxisMask m_known = kNoAxes;
};

// The axes known before the first block: all of them when the caller gives the start position;
// Y when the machine has no Y axis (a lathe: the tool works in the XZ plane through the spindle
// axis, so Y is 0 there and nothing is invented by saying so).
KnownAxes knownAtStart(const InterpretOptions& options);

// "X is unknown here: no absolute X has been programmed yet (<need> needs it)": the one wording
// of this error in every dialect. `need` says what wanted the value ("an incremental X", "the arc").
std::string unknownAxisMessage(int axis, std::string_view need);

}  // namespace camwb::nc
