// Writes the contour's CL records: moves from the current position with their source reference,
// arcs split so no record sweeps more than half a turn, and cuts along a path with Z varying
// linearly (ramps) and raised over holding tabs.
#pragma once

#include "ops/OpCommon.h"
#include "ops/contour/Path.h"
#include "toolpath/Toolpath.h"

#include <vector>

namespace camwb::ops::contour {

using toolpath::Vec3;

// Arclength spans of a path over which the tool stays at or above `topZ`.
struct Tabs {
    std::vector<std::pair<double, double>> spans;  // from < to; may run past the length (wrap)
    double topZ = 0;
    double pathLength = 0;
    bool contains(double s) const;
};

// The feeds a cut along a path uses: cutting, plunging straight down, ramping (an entry).
struct Feeds {
    Feed cut, plunge, ramp;
};

class Emitter {
public:
    Emitter(toolpath::Toolpath& toolpath, int operationIndex) : m_toolpath(toolpath), m_operationIndex(operationIndex)
    {
    }

    void add(toolpath::Record record);
    void rapid(Vec3 to);
    void linear(Vec3 to, Feed feed);
    // The XY piece from the current position, Z going linearly to z1 (a helix when it changes).
    void piece(const Segment& s, double z1, Feed feed);
    void vertical(double z, Feed feed) { linear({m_position.x, m_position.y, z}, feed); }
    Vec3 position() const { return m_position; }

private:
    void arc(const Segment& s, double z1, Feed feed);

    toolpath::Toolpath& m_toolpath;
    int m_operationIndex;
    int m_index = 0;
    Vec3 m_position;
};

// Cuts `path` from arclength `from` to `to` (to > from wraps round a closed path; to < from runs
// backwards on an open one) with Z going linearly from zFrom to zTo; over tab spans the tool
// stays at the tabs' top (straight up at a tab's start, down at its end). Ramp feed where Z
// changes along the path, cutting feed elsewhere.
void cutAlong(Emitter& out, const Path& path, double from, double to, double zFrom, double zTo, const Tabs* tabs,
              const Feeds& feeds);

}  // namespace camwb::ops::contour
