// What the groove tests share: Kod 1 as GrooveParams, the grooving tool, and the moves of a
// toolpath with their positions resolved (each move gives only its axes, AxisMask).
#pragma once

#include "ops/GrooveOp.h"

#include <vector>

namespace camwb::ops::test {

inline ToolController grooveTool(double widthMm = 3)
{
    ToolController tc;
    tc.tool.number = 5;
    tc.tool.name = "grooving insert";
    tc.tool.kind = "groove";
    tc.tool.diameterMm = widthMm;
    return tc;
}

// A straight move with where it ends (X radius, Z); `axes` as the record gives them.
struct ResolvedMove {
    bool rapid = false;
    toolpath::AxisMask axes;
    double x = 0, z = 0;
};

// The Rapid and Linear records of `path` in order, with the axes a move leaves out taken from
// the moves before it (0 until given).
inline std::vector<ResolvedMove> resolvedMoves(const toolpath::Toolpath& path,
                                               bool (*keep)(const toolpath::SourceRef&) = nullptr)
{
    std::vector<ResolvedMove> out;
    double x = 0, z = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const toolpath::Record& r = path.record(i);
        const toolpath::Vec3* to = nullptr;
        ResolvedMove m;
        if (const auto* rapid = std::get_if<toolpath::Rapid>(&r)) {
            to = &rapid->to;
            m.rapid = true;
            m.axes = rapid->axes;
        } else if (const auto* line = std::get_if<toolpath::Linear>(&r)) {
            to = &line->to;
            m.axes = line->axes;
        }
        if (!to)
            continue;
        if (m.axes.has(0))
            x = to->x;
        if (m.axes.has(2))
            z = to->z;
        m.x = x;
        m.z = z;
        if (!keep || keep(path.source(i)))
            out.push_back(m);
    }
    return out;
}

}  // namespace camwb::ops::test
