// Canonical text trace of CL records: one line per record, fixed number formats, no locale.
// Tests compare traces; the format is stable and documented in docs/architecture.md.
#pragma once

#include "toolpath/MachineSink.h"

#include <string>

namespace camwb::toolpath {

class TraceWriter : public MachineSink {
public:
    explicit TraceWriter(std::string& out) : m_out(out) {}

    void rapid(const Rapid&) override;
    void linear(const Linear&) override;
    void arc(const Arc&) override;
    void toolChange(const ToolChange&) override;
    void spindle(const Spindle&) override;
    void coolant(const Coolant&) override;
    void feedMode(const FeedModeChange&) override;
    void workOffset(const WorkOffset&) override;
    void dwell(const Dwell&) override;
    void cycle(const Cycle&) override;
    void toolAxisMove(const ToolAxisMove&) override;
    void cutterComp(const CutterComp&) override;
    void comment(const Comment&) override;
    void sectionBegin(const SectionBegin&) override;
    void sectionEnd(const SectionEnd&) override;
    void programStop(const ProgramStop&) override;
    void passThrough(const PassThrough&) override;
    void workingPlane(const WorkingPlane&) override;
    void unknownAxes(const UnknownAxes&) override;

private:
    std::string& m_out;
};

// The trace of a whole toolpath as one string.
std::string traceOf(const class Toolpath& toolpath);

}  // namespace camwb::toolpath
