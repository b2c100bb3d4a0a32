#include "ops/pocket/PathWriter.h"

#include <cmath>
#include <numbers>

namespace camwb::ops::pocket {

using toolpath::Vec3;

void PathWriter::add(toolpath::Record record) { m_out.add(std::move(record), {m_operationIndex, m_index++}); }

void PathWriter::rapid(Vec3 to)
{
    if (m_position && distance(*m_position, to) < 1e-12)
        return;
    add(toolpath::Rapid{to});
    m_position = to;
}

void PathWriter::feed(Vec3 to, Feed feed)
{
    if (m_position && distance(*m_position, to) < 1e-12)
        return;
    add(feedMove(to, feed));
    m_position = to;
}

void PathWriter::segment(const Segment& s, double z0, double z1, Feed feed)
{
    if (!s.isArc()) {
        this->feed({s.end.x, s.end.y, z1}, feed);
        return;
    }
    if (std::abs(s.sweep()) > std::numbers::pi + 1e-9) {
        // No record ends on its start, and posts split arcs beyond half a turn anyway.
        const double zMid = 0.5 * (z0 + z1);
        arc(subSegment(s, 0, 0.5), z0, zMid, feed);
        arc(subSegment(s, 0.5, 1), zMid, z1, feed);
        return;
    }
    arc(s, z0, z1, feed);
}

void PathWriter::arc(const Segment& s, double z0, double z1, Feed feed)
{
    toolpath::Arc a;
    a.to = {s.end.x, s.end.y, z1};
    a.center = {s.center.x, s.center.y, z0};  // in the start's plane: a helix shows in its end
    a.clockwise = !s.ccw;
    a.feedMmPerMin = feed.mmPerMin;
    a.feedKind = feed.kind;
    add(a);
    m_position = a.to;
}

void PathWriter::path(const std::vector<Segment>& path, double z, Feed feed)
{
    for (const Segment& s : path)
        segment(s, z, z, feed);
}

}  // namespace camwb::ops::pocket
