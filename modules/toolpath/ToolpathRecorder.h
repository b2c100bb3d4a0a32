// A MachineSink that keeps what it is sent: every record, with the source set before it, appended
// to a Toolpath. Collects an NC interpreter's output for the trace, the backplot and round trips.
#pragma once

#include "toolpath/MachineSink.h"
#include "toolpath/Toolpath.h"

namespace camwb::toolpath {

class ToolpathRecorder : public MachineSink {
public:
    void setSource(const SourceRef& source) override { m_source = source; }

    void rapid(const Rapid& r) override { m_path.add(r, m_source); }
    void linear(const Linear& r) override { m_path.add(r, m_source); }
    void arc(const Arc& r) override { m_path.add(r, m_source); }
    void toolChange(const ToolChange& r) override { m_path.add(r, m_source); }
    void spindle(const Spindle& r) override { m_path.add(r, m_source); }
    void coolant(const Coolant& r) override { m_path.add(r, m_source); }
    void feedMode(const FeedModeChange& r) override { m_path.add(r, m_source); }
    void workOffset(const WorkOffset& r) override { m_path.add(r, m_source); }
    void dwell(const Dwell& r) override { m_path.add(r, m_source); }
    void cycle(const Cycle& r) override { m_path.add(r, m_source); }
    void toolAxisMove(const ToolAxisMove& r) override { m_path.add(r, m_source); }
    void cutterComp(const CutterComp& r) override { m_path.add(r, m_source); }
    void comment(const Comment& r) override { m_path.add(r, m_source); }
    void sectionBegin(const SectionBegin& r) override { m_path.add(r, m_source); }
    void sectionEnd(const SectionEnd& r) override { m_path.add(r, m_source); }
    void programStop(const ProgramStop& r) override { m_path.add(r, m_source); }
    void passThrough(const PassThrough& r) override { m_path.add(r, m_source); }
    void workingPlane(const WorkingPlane& r) override { m_path.add(r, m_source); }
    void unknownAxes(const UnknownAxes& r) override { m_path.add(r, m_source); }

    const Toolpath& toolpath() const { return m_path; }
    Toolpath take() { return std::move(m_path); }

private:
    Toolpath m_path;
    SourceRef m_source;
};

}  // namespace camwb::toolpath
