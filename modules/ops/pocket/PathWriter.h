// Turns 2D cut geometry into CL records at a given Z: lines, flat arcs (full circles as two
// halves), helical arcs (z changing along the sweep) and rapids, each record with the
// operation's SourceRef, while tracking where the tool is.
#pragma once

#include "ops/OpCommon.h"
#include "ops/pocket/CutPath.h"
#include "toolpath/Toolpath.h"

#include <optional>

namespace camwb::ops::pocket {

class PathWriter {
public:
    PathWriter(toolpath::Toolpath& out, int operationIndex) : m_out(out), m_operationIndex(operationIndex) {}

    void add(toolpath::Record record);
    void rapid(toolpath::Vec3 to);
    void feed(toolpath::Vec3 to, Feed feed);
    // The segment from z0 at its start to z1 at its end (z0 == z1: flat), z linear in length.
    void segment(const Segment& s, double z0, double z1, Feed feed);
    void path(const std::vector<Segment>& path, double z, Feed feed);

    bool hasPosition() const { return m_position.has_value(); }
    toolpath::Vec3 position() const { return *m_position; }

private:
    void arc(const Segment& s, double z0, double z1, Feed feed);

    toolpath::Toolpath& m_out;
    int m_operationIndex;
    int m_index = 0;
    std::optional<toolpath::Vec3> m_position;
};

}  // namespace camwb::ops::pocket
