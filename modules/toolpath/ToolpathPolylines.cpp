#include "toolpath/ToolpathPolylines.h"

#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/Toolpath.h"

#include <algorithm>

namespace camwb::toolpath {

using base::Vec3;

namespace {

// Even where the chord tolerance allows longer chords, helices and small arcs look round only
// with a few dozen segments per turn.
constexpr double kMaxStepDeg = 10;

}  // namespace

ToolpathPolylines::ToolpathPolylines(double chordToleranceMm) :
    m_chordToleranceMm(chordToleranceMm > 0 ? chordToleranceMm : 0.01)
{
}

ToolpathPolylines ToolpathPolylines::fromToolpath(const Toolpath& toolpath, double chordToleranceMm,
                                                  const std::vector<bool>& recordsInError)
{
    ToolpathPolylines polylines(chordToleranceMm);
    polylines.begin();
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        polylines.setCurrentRecord(static_cast<std::uint32_t>(i));
        polylines.setCurrentRecordInError(i < recordsInError.size() && recordsInError[i]);
        polylines.setSource(toolpath.source(i));
        toolpath::dispatch(toolpath.record(i), polylines);
    }
    polylines.end();
    return polylines;
}

std::size_t ToolpathPolylines::segmentCount(PathSegmentKind kind) const
{
    return static_cast<std::size_t>(
        std::count_if(m_segments.begin(), m_segments.end(), [kind](const PathSegment& s) { return s.kind == kind; }));
}

std::pair<std::size_t, std::size_t> ToolpathPolylines::segmentsOfRecords(std::uint32_t first, std::uint32_t last) const
{
    auto begin = std::lower_bound(m_segments.begin(), m_segments.end(), first,
                                  [](const PathSegment& s, std::uint32_t r) { return s.record < r; });
    auto end = std::upper_bound(begin, m_segments.end(), last,
                                [](std::uint32_t r, const PathSegment& s) { return r < s.record; });
    return {static_cast<std::size_t>(begin - m_segments.begin()), static_cast<std::size_t>(end - m_segments.begin())};
}

void ToolpathPolylines::clear()
{
    m_points.clear();
    m_segments.clear();
    m_record = 0;
    m_tool = 0;
    m_inError = false;
    m_hasPosition = false;
    m_positionStored = false;
    m_partial.forget();
    m_plane = {};
    m_tilted = false;
}

// Moves after a tilted working plane are in its frame; the view shows the workpiece's.
void ToolpathPolylines::workingPlane(const WorkingPlane& plane)
{
    if (m_hasPosition)
        m_position = plane.toLocal(m_plane.toWorkpiece(m_position));  // the same point, stored or not
    m_partial.forget();
    m_plane = plane;
    m_tilted = plane.tilted();
}

// The tool went somewhere the program does not say: nothing is drawn from the old place; the path
// goes on from where the moves make every axis known again.
void ToolpathPolylines::unknownAxes(const UnknownAxes& u)
{
    if (m_hasPosition)
        m_partial.set(m_position);
    m_partial.forget(u.axes);
    m_hasPosition = false;
    m_positionStored = false;
}

void ToolpathPolylines::setStartPosition(const Vec3& position)
{
    m_position = position;
    m_hasPosition = true;
    m_positionStored = false;
}

std::uint32_t ToolpathPolylines::currentIndex()
{
    if (!m_positionStored) {
        m_points.push_back(shown(m_position));
        m_positionStored = true;
    }
    return static_cast<std::uint32_t>(m_points.size() - 1);
}

void ToolpathPolylines::lineTo(const Vec3& to, PathSegmentKind kind)
{
    if (!m_hasPosition) {
        setStartPosition(to);
        return;
    }
    if (base::distance(to, m_position) < 1e-12)
        return;
    const std::uint32_t from = currentIndex();
    m_points.push_back(shown(to));
    m_segments.push_back({from, static_cast<std::uint32_t>(m_points.size() - 1), m_record, m_tool, kind});
    m_position = to;
    m_positionStored = true;
}

// Dashes along the straight line from the current position: what the block claims is not drawn,
// so a wrong block cannot look like a path (or blow up the view with a huge circle).
void ToolpathPolylines::errorTo(const Vec3& to)
{
    if (!m_hasPosition) {
        setStartPosition(to);
        return;
    }
    const Vec3 from = m_position;
    if (base::distance(to, from) < 1e-12)
        return;
    constexpr int kPieces = 2 * kErrorDashes - 1;  // dash, gap, ..., dash: the last ends at `to`
    for (int i = 0; i < kPieces; i += 2) {
        m_points.push_back(shown(from + (to - from) * (double(i) / kPieces)));
        m_points.push_back(shown(from + (to - from) * (double(i + 1) / kPieces)));
        const auto last = static_cast<std::uint32_t>(m_points.size() - 1);
        m_segments.push_back({last - 1, last, m_record, m_tool, PathSegmentKind::Error});
    }
    m_points.back() = shown(to);
    m_position = to;
    m_positionStored = true;
}

// A move that gives only some axes keeps the others; until all three are known (a CL that
// retracts in Z before its first X/Y) nothing is drawn rather than a line from a guessed point.
void ToolpathPolylines::straightTo(const Vec3& to, AxisMask axes, PathSegmentKind kind)
{
    if (m_hasPosition)
        m_partial.set(m_position);
    m_partial.moveTo(to, axes);
    const std::optional<Vec3> point = m_partial.point();
    if (!point)
        return;
    if (m_inError)
        errorTo(*point);
    else
        lineTo(*point, kind);
}

void ToolpathPolylines::rapid(const Rapid& r)
{
    m_toolAxisMoves = 0;
    straightTo(r.to, r.axes, PathSegmentKind::Rapid);
}

void ToolpathPolylines::linear(const Linear& l)
{
    m_toolAxisMoves = 0;
    straightTo(l.to, l.axes, PathSegmentKind::Feed);
}

void ToolpathPolylines::toolAxisMove(const ToolAxisMove& m)
{
    if (m_inError)
        errorTo(m.tip);
    else
        lineTo(m.tip, m.feedMmPerMin > 0 ? PathSegmentKind::Feed : PathSegmentKind::Rapid);
    if (m_hasPosition && m_toolAxisMoves++ % kToolAxisEvery == 0)
        toolAxisAt(m.axis);
}

// A segment of its own from the tip along the axis: no run of the path continues from its end.
void ToolpathPolylines::toolAxisAt(const Vec3& axis)
{
    const double length = axis.length();
    if (length < 1e-12)
        return;
    const std::uint32_t from = currentIndex();
    m_points.push_back(shown(m_position + axis * (kToolAxisLengthMm / length)));
    m_segments.push_back(
        {from, static_cast<std::uint32_t>(m_points.size() - 1), m_record, m_tool, PathSegmentKind::ToolAxis});
    m_positionStored = false;  // m_points.back() is the axis' end, not the tip
}

// Start = the current position (toolpath/ArcGeometry.h says how helices and inconsistent radii go).
void ToolpathPolylines::arc(const Arc& a)
{
    m_toolAxisMoves = 0;
    if (m_inError) {
        errorTo(a.to);
        return;
    }
    if (!m_hasPosition) {
        setStartPosition(a.to);
        return;
    }
    for (const Vec3& p : toolpath::linearizeArc(m_position, a, m_chordToleranceMm, kMaxStepDeg, kMaxSegmentsPerArc))
        lineTo(p, PathSegmentKind::Arc);
}

// Canned cycles are drawn as the moves a control makes for each hole: the same expansion posts
// without native cycles write (pecks, dwells and the return plane included).
void ToolpathPolylines::cycle(const Cycle& c)
{
    // A cycle block with an error: its holes' expansions are drawn dashed (the moves dispatched
    // below see m_inError).
    for (const Vec3& hole : c.holes) {
        // Without a position the drawing starts over the hole (the first move only sets it).
        const KnownPosition from = m_hasPosition ? KnownPosition(m_position)
                                   : m_partial.known(2)
                                       ? m_partial
                                       : KnownPosition(Vec3{hole.x, hole.y, toolpath::cycleReturnZ(c)});
        for (const Record& record : toolpath::expandCycleHole(c, hole, from, {}))
            toolpath::dispatch(record, *this);
    }
}

}  // namespace camwb::toolpath
