#include "toolpath/ProgramStats.h"

#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"

#include <algorithm>
#include <type_traits>

namespace camwb::toolpath {

namespace {

// Walks the records with the modal state the time estimate needs.
class StatsWalker {
public:
    StatsWalker(ProgramStats& stats, double rapidMmPerMin, std::optional<Vec3> start) :
        m_stats(stats),
        m_rapidMmPerMin(rapidMmPerMin),
        m_position(start)
    {
    }

    void record(const Record& r)
    {
        std::visit(
            [this](const auto& rec) {
                using T = std::decay_t<decltype(rec)>;
                if constexpr (std::is_same_v<T, Rapid>) {
                    if (const std::optional<Vec3> end = straightEnd(rec.to, rec.axes))
                        rapid(*end);
                    else
                        ++m_stats.rapids;  // from or to a position not known yet: no length
                } else if constexpr (std::is_same_v<T, Linear>) {
                    if (const std::optional<Vec3> end = straightEnd(rec.to, rec.axes))
                        linear(*end, rec.feedMmPerMin);
                    else
                        addFeed(0, rec.feedMmPerMin);
                } else if constexpr (std::is_same_v<T, Arc>)
                    arc(rec);
                else if constexpr (std::is_same_v<T, ToolAxisMove>) {
                    if (rec.feedMmPerMin > 0)
                        linear(rec.tip, rec.feedMmPerMin);
                    else
                        rapid(rec.tip);
                } else if constexpr (std::is_same_v<T, Cycle>)
                    cycle(rec);
                else if constexpr (std::is_same_v<T, Dwell>)
                    addDwell(rec.seconds);
                else if constexpr (std::is_same_v<T, Spindle>)
                    m_spindle = {rec.rpm, rec.clockwise};
                else if constexpr (std::is_same_v<T, FeedModeChange>)
                    m_feedMode = rec.mode;
                else if constexpr (std::is_same_v<T, ToolChange>)
                    toolChange(rec.tool.number);
                else if constexpr (std::is_same_v<T, WorkingPlane>)
                    workingPlane(rec);
                else if constexpr (std::is_same_v<T, UnknownAxes>)
                    unknownAxes(rec.axes);
            },
            r);
    }

    // A motion of a block with an error: the next move starts where it ends, nothing else counts.
    void leaveOut(const Record& r)
    {
        std::visit(
            [this, &r](const auto& rec) {
                using T = std::decay_t<decltype(rec)>;
                if constexpr (std::is_same_v<T, Rapid> || std::is_same_v<T, Linear> || std::is_same_v<T, Arc>)
                    m_position = rec.to;
                else if constexpr (std::is_same_v<T, ToolAxisMove>)
                    m_position = rec.tip;
                else if constexpr (std::is_same_v<T, Cycle>) {
                    if (!rec.holes.empty())
                        m_position = Vec3{rec.holes.back().x, rec.holes.back().y, cycleReturnZ(rec)};
                } else {
                    record(r);  // not a motion: tools, spindle and feed modes still apply
                    return;
                }
                ++m_stats.movesLeftOut;
            },
            r);
    }

private:
    MotionTotals& toolTotals()
    {
        if (m_tool < 0) {
            auto it = std::find_if(m_stats.tools.begin(), m_stats.tools.end(),
                                   [&](const ToolStats& t) { return t.toolNumber == m_toolNumber; });
            if (it == m_stats.tools.end()) {
                m_stats.tools.push_back({m_toolNumber, {}});
                it = std::prev(m_stats.tools.end());
            }
            m_tool = static_cast<int>(it - m_stats.tools.begin());
        }
        return m_stats.tools[static_cast<std::size_t>(m_tool)].totals;
    }

    // The end of a straight move that gives `axes`; nullopt while an axis it leaves out is unknown.
    std::optional<Vec3> straightEnd(const Vec3& to, AxisMask axes)
    {
        if (m_position)
            m_partial.set(*m_position);
        m_partial.moveTo(to, axes);
        return m_partial.point();
    }

    void toolChange(int number)
    {
        ++m_stats.toolChanges;
        m_toolNumber = number;
        m_tool = -1;
    }

    // Lengths and times are the same in any frame; extents are the workpiece's.
    void addPoint(const Vec3& local, bool cutting)
    {
        const Vec3 p = m_plane.toWorkpiece(local);
        for (MotionTotals* t : {&m_stats.totals, &toolTotals()}) {
            (cutting ? t->cuttingExtents : t->rapidExtents).add(p);
            t->allExtents.add(p);
        }
    }

    void workingPlane(const WorkingPlane& plane)
    {
        if (m_position)
            m_position = plane.toLocal(m_plane.toWorkpiece(*m_position));
        m_partial = {};
        m_plane = plane;
    }

    // No length is counted to or from a place the program does not give.
    void unknownAxes(AxisMask axes)
    {
        if (m_position)
            m_partial.set(*m_position);
        m_partial.forget(axes);
        m_position.reset();
    }

    void rapid(const Vec3& to)
    {
        ++m_stats.rapids;
        if (m_position) {
            addPoint(*m_position, false);
            const double length = base::distance(*m_position, to);
            for (MotionTotals* t : {&m_stats.totals, &toolTotals()}) {
                t->rapidLengthMm += length;
                t->rapidSeconds += length / m_rapidMmPerMin * 60.0;
            }
        }
        addPoint(to, false);
        m_position = to;
    }

    // Seconds a feed move of `length` takes at `feed` in the current mode; nullopt when it cannot run.
    std::optional<double> feedSeconds(double length, double feed) const
    {
        if (feed <= 0)
            return std::nullopt;
        switch (m_feedMode) {
        case FeedMode::PerMinute:
            return length / feed * 60.0;
        case FeedMode::PerRevolution:
            if (m_spindle.rpm <= 0)
                return std::nullopt;
            return length / (feed * m_spindle.rpm) * 60.0;
        case FeedMode::InverseTime:
            return 60.0 / feed;
        }
        return std::nullopt;
    }

    void addFeed(double length, double feed)
    {
        ++m_stats.feedMoves;
        const std::optional<double> seconds = m_position ? feedSeconds(length, feed) : 0.0;
        if (!seconds)
            ++m_stats.movesWithoutFeed;
        for (MotionTotals* t : {&m_stats.totals, &toolTotals()}) {
            t->feedLengthMm += length;
            t->feedSeconds += seconds.value_or(0.0);
        }
    }

    void linear(const Vec3& to, double feed)
    {
        double length = 0;
        if (m_position) {
            addPoint(*m_position, true);
            length = base::distance(*m_position, to);
        }
        addFeed(length, feed);
        addPoint(to, true);
        m_position = to;
    }

    void arc(const Arc& a)
    {
        ++m_stats.arcs;
        if (!m_position) {
            addFeed(0, a.feedMmPerMin);
            addPoint(a.to, true);
            m_position = a.to;
            return;
        }
        const Vec3 start = *m_position;
        Vec3 min = start, max = start;
        extendByArc(min, max, start, a);
        if (m_plane.tilted()) {  // in a turned frame the arc lies within its box's corners
            for (const Vec3& corner : base::boxCorners(min, max))
                addPoint(corner, true);
        } else {
            addPoint(min, true);
            addPoint(max, true);
        }
        const double length = arcLength(start, a);
        addFeed(length, a.feedMmPerMin);
        m_position = a.to;
    }

    void cycle(const Cycle& c)
    {
        for (const Vec3& hole : c.holes) {
            ++m_stats.cycleHoles;
            const Vec3 from = m_position.value_or(Vec3{hole.x, hole.y, cycleReturnZ(c)});
            if (!m_position)
                m_position = from;
            const SpindleState spindle{m_spindle.rpm, m_spindle.clockwise};
            for (const Record& r : expandCycleHole(c, hole, from, spindle))
                record(r);
        }
    }

    void addDwell(double seconds)
    {
        for (MotionTotals* t : {&m_stats.totals, &toolTotals()})
            t->dwellSeconds += std::max(0.0, seconds);
    }

    ProgramStats& m_stats;
    double m_rapidMmPerMin;
    std::optional<Vec3> m_position;
    KnownPosition m_partial;  // the axes given so far, while m_position is unknown
    WorkingPlane m_plane;     // the frame the moves are in (3+2)
    SpindleState m_spindle;
    FeedMode m_feedMode = FeedMode::PerMinute;
    int m_toolNumber = 0;
    int m_tool = -1;  // index into m_stats.tools, -1: look up on first use
};

}  // namespace

ProgramStats programStats(const Toolpath& program, const StatsOptions& options)
{
    ProgramStats stats;
    stats.rapidMmPerMin = options.rapidMmPerMin > 0 ? options.rapidMmPerMin : kDefaultRapidMmPerMin;
    StatsWalker walker(stats, stats.rapidMmPerMin, options.startPosition);
    const std::vector<bool>* inError = options.recordsInError;
    for (std::size_t i = 0; i < program.size(); ++i) {
        if (inError != nullptr && i < inError->size() && (*inError)[i])
            walker.leaveOut(program.record(i));
        else
            walker.record(program.record(i));
    }
    return stats;
}

}  // namespace camwb::toolpath
