// Turns CL records into display line segments for the 3D backplot: a MachineSink that walks the
// toolpath, tracks the current position and tessellates arcs and helices within a chord
// tolerance. Plain data, no VTK, so it is unit-testable.
#pragma once

#include "base/Vec.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/MachineSink.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace camwb::toolpath {

class Toolpath;

// Error: a dash of a record from a block with an error, drawn straight from where it starts to
// where it ends instead of what it claims (an arc whose radii disagree would be a huge circle).
// ToolAxis: no motion but the tool's axis at a five-axis move's tip, kToolAxisLengthMm long
// towards the spindle, drawn at every kToolAxisEvery-th such move (and at the first of each run).
enum class PathSegmentKind : std::uint8_t { Rapid, Feed, Arc, Error, ToolAxis };

// One straight display segment between two entries of ToolpathPolylines::points(). `record` is
// the index of the toolpath record that made it (the NC inspector links segments to lines with
// it) and `tool` the tool number of the last tool change before it (0 = none yet).
struct PathSegment {
    std::uint32_t from = 0;
    std::uint32_t to = 0;
    std::uint32_t record = 0;
    std::int32_t tool = 0;
    PathSegmentKind kind = PathSegmentKind::Feed;
};

class ToolpathPolylines : public MachineSink {
public:
    // chordToleranceMm: largest distance between a tessellated arc and its chords.
    explicit ToolpathPolylines(double chordToleranceMm = 0.01);

    // Convenience: plays `toolpath` into a fresh instance; records flagged in `recordsInError`
    // (nc::recordsInError: one flag per record, or empty) are drawn as Error dashes.
    static ToolpathPolylines fromToolpath(const Toolpath& toolpath, double chordToleranceMm = 0.01,
                                          const std::vector<bool>& recordsInError = {});

    const std::vector<base::Vec3>& points() const { return m_points; }
    const std::vector<PathSegment>& segments() const { return m_segments; }
    std::size_t segmentCount(PathSegmentKind kind) const;
    bool empty() const { return m_segments.empty(); }
    void clear();

    // Where the walk starts; without it the first move only sets the position.
    void setStartPosition(const base::Vec3& position);
    bool hasPosition() const { return m_hasPosition; }
    base::Vec3 position() const { return m_position; }

    // The record index stamped on the segments made from now on (fromToolpath sets it per record).
    void setCurrentRecord(std::uint32_t record) { m_record = record; }
    // Whether the moves from now on come from a block with an error (drawn as Error dashes).
    void setCurrentRecordInError(bool inError) { m_inError = inError; }
    // Dashes of one Error move (with gaps between them), whatever its length.
    static constexpr int kErrorDashes = 8;
    // Segments of records [first, last] (segments are in record order): [begin, end) indices.
    std::pair<std::size_t, std::size_t> segmentsOfRecords(std::uint32_t first, std::uint32_t last) const;

    // The tool axis along five-axis moves: its length and how often it is drawn.
    static constexpr double kToolAxisLengthMm = 10;
    static constexpr int kToolAxisEvery = 5;

    // Hard cap on the segments of one arc (huge helices with many turns).
    static constexpr int kMaxSegmentsPerArc = 200000;

    void rapid(const Rapid&) override;
    void linear(const Linear&) override;
    void arc(const Arc&) override;
    void toolChange(const ToolChange& change) override { m_tool = change.tool.number; }
    void spindle(const Spindle&) override {}
    void coolant(const Coolant&) override {}
    void feedMode(const FeedModeChange&) override {}
    void workOffset(const WorkOffset&) override {}
    void dwell(const Dwell&) override {}
    void cycle(const Cycle&) override;
    void toolAxisMove(const ToolAxisMove&) override;
    void cutterComp(const CutterComp&) override {}
    void comment(const Comment&) override {}
    void sectionBegin(const SectionBegin&) override {}
    void sectionEnd(const SectionEnd&) override {}
    void programStop(const ProgramStop&) override {}
    void passThrough(const PassThrough&) override {}
    void workingPlane(const WorkingPlane&) override;
    void unknownAxes(const UnknownAxes&) override;

private:
    void lineTo(const base::Vec3& to, PathSegmentKind kind);
    void errorTo(const base::Vec3& to);
    void straightTo(const base::Vec3& to, AxisMask axes, PathSegmentKind kind);
    void toolAxisAt(const base::Vec3& axis);
    std::uint32_t currentIndex();
    base::Vec3 shown(const base::Vec3& p) const { return m_tilted ? m_plane.toWorkpiece(p) : p; }

    double m_chordToleranceMm;
    std::vector<base::Vec3> m_points;
    std::vector<PathSegment> m_segments;
    base::Vec3 m_position;
    bool m_hasPosition = false;
    bool m_positionStored = false;  // m_points.back() == m_position
    KnownPosition m_partial;        // the axes known so far, while no whole position is
    std::uint32_t m_record = 0;
    std::int32_t m_tool = 0;
    bool m_inError = false;
    int m_toolAxisMoves = 0;  // five-axis moves since the last other move
    WorkingPlane m_plane;     // the frame of the moves (3+2)
    bool m_tilted = false;
};

}  // namespace camwb::toolpath
