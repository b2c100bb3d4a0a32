#include "toolpath/Toolpath.h"

#include "toolpath/MachineSink.h"

#include <type_traits>

namespace camwb::toolpath {

void Toolpath::add(Record record, SourceRef source)
{
    m_records.push_back(std::move(record));
    m_sources.push_back(source);
}

void Toolpath::reserve(std::size_t records)
{
    m_records.reserve(records);
    m_sources.reserve(records);
}

void Toolpath::append(const Toolpath& other)
{
    m_records.insert(m_records.end(), other.m_records.begin(), other.m_records.end());
    m_sources.insert(m_sources.end(), other.m_sources.begin(), other.m_sources.end());
}

ToolpathStats statistics(const Toolpath& toolpath)
{
    ToolpathStats stats;
    for (const Record& record : toolpath.records()) {
        if (std::holds_alternative<Rapid>(record))
            ++stats.rapids;
        else if (std::holds_alternative<Linear>(record))
            ++stats.lines;
        else if (const Arc* arc = std::get_if<Arc>(&record)) {
            // A helix is an arc whose end leaves the plane through its centre.
            const bool helix = std::abs((arc->to - arc->center).dot(arc->normal)) > 1e-9;
            ++(helix ? stats.helices : stats.arcs);
        } else if (std::holds_alternative<Cycle>(record))
            ++stats.cycles;
        else if (std::holds_alternative<ToolChange>(record))
            ++stats.toolChanges;
        else if (std::holds_alternative<ToolAxisMove>(record))
            ++stats.fiveAxis;
    }
    return stats;
}

void dispatch(const Record& record, MachineSink& sink)
{
    std::visit(
        [&sink](const auto& r) {
            using T = std::decay_t<decltype(r)>;
            if constexpr (std::is_same_v<T, Rapid>)
                sink.rapid(r);
            else if constexpr (std::is_same_v<T, Linear>)
                sink.linear(r);
            else if constexpr (std::is_same_v<T, Arc>)
                sink.arc(r);
            else if constexpr (std::is_same_v<T, ToolChange>)
                sink.toolChange(r);
            else if constexpr (std::is_same_v<T, Spindle>)
                sink.spindle(r);
            else if constexpr (std::is_same_v<T, Coolant>)
                sink.coolant(r);
            else if constexpr (std::is_same_v<T, FeedModeChange>)
                sink.feedMode(r);
            else if constexpr (std::is_same_v<T, WorkOffset>)
                sink.workOffset(r);
            else if constexpr (std::is_same_v<T, Dwell>)
                sink.dwell(r);
            else if constexpr (std::is_same_v<T, Cycle>)
                sink.cycle(r);
            else if constexpr (std::is_same_v<T, ToolAxisMove>)
                sink.toolAxisMove(r);
            else if constexpr (std::is_same_v<T, CutterComp>)
                sink.cutterComp(r);
            else if constexpr (std::is_same_v<T, Comment>)
                sink.comment(r);
            else if constexpr (std::is_same_v<T, SectionBegin>)
                sink.sectionBegin(r);
            else if constexpr (std::is_same_v<T, SectionEnd>)
                sink.sectionEnd(r);
            else if constexpr (std::is_same_v<T, ProgramStop>)
                sink.programStop(r);
            else if constexpr (std::is_same_v<T, PassThrough>)
                sink.passThrough(r);
            else if constexpr (std::is_same_v<T, WorkingPlane>)
                sink.workingPlane(r);
            else if constexpr (std::is_same_v<T, UnknownAxes>)
                sink.unknownAxes(r);
            else
                static_assert(sizeof(T) == 0, "every CL record needs a sink method");
        },
        record);
}

void play(const Toolpath& toolpath, MachineSink& sink)
{
    sink.begin();
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        sink.setSource(toolpath.source(i));
        dispatch(toolpath.record(i), sink);
    }
    sink.end();
}

}  // namespace camwb::toolpath
