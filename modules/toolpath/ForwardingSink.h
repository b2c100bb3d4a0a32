// Sinks that pass records on: NullSink drops everything (a filter used alone, e.g. the machine
// check of a whole toolpath), ForwardingSink passes every call on to the next sink. Filters that
// look at the records going by (the machine limit check) or change them (cutter compensation)
// derive from ForwardingSink, override what they need and call the base to pass a record on.
#pragma once

#include "toolpath/MachineSink.h"

namespace camwb::toolpath {

class NullSink : public MachineSink {
public:
    void rapid(const Rapid&) override {}
    void linear(const Linear&) override {}
    void arc(const Arc&) override {}
    void toolChange(const ToolChange&) override {}
    void spindle(const Spindle&) override {}
    void coolant(const Coolant&) override {}
    void feedMode(const FeedModeChange&) override {}
    void workOffset(const WorkOffset&) override {}
    void dwell(const Dwell&) override {}
    void cycle(const Cycle&) override {}
    void toolAxisMove(const ToolAxisMove&) override {}
    void cutterComp(const CutterComp&) override {}
    void comment(const Comment&) override {}
    void sectionBegin(const SectionBegin&) override {}
    void sectionEnd(const SectionEnd&) override {}
    void programStop(const ProgramStop&) override {}
    void passThrough(const PassThrough&) override {}
    void workingPlane(const WorkingPlane&) override {}
    void unknownAxes(const UnknownAxes&) override {}
};

class ForwardingSink : public MachineSink {
public:
    explicit ForwardingSink(MachineSink& next) : m_next(next) {}

    void begin() override { m_next.begin(); }
    void end() override { m_next.end(); }
    void setSource(const SourceRef& s) override { m_next.setSource(s); }

    void rapid(const Rapid& r) override { m_next.rapid(r); }
    void linear(const Linear& r) override { m_next.linear(r); }
    void arc(const Arc& r) override { m_next.arc(r); }
    void toolChange(const ToolChange& r) override { m_next.toolChange(r); }
    void spindle(const Spindle& r) override { m_next.spindle(r); }
    void coolant(const Coolant& r) override { m_next.coolant(r); }
    void feedMode(const FeedModeChange& r) override { m_next.feedMode(r); }
    void workOffset(const WorkOffset& r) override { m_next.workOffset(r); }
    void dwell(const Dwell& r) override { m_next.dwell(r); }
    void cycle(const Cycle& r) override { m_next.cycle(r); }
    void toolAxisMove(const ToolAxisMove& r) override { m_next.toolAxisMove(r); }
    void cutterComp(const CutterComp& r) override { m_next.cutterComp(r); }
    void comment(const Comment& r) override { m_next.comment(r); }
    void sectionBegin(const SectionBegin& r) override { m_next.sectionBegin(r); }
    void sectionEnd(const SectionEnd& r) override { m_next.sectionEnd(r); }
    void programStop(const ProgramStop& r) override { m_next.programStop(r); }
    void passThrough(const PassThrough& r) override { m_next.passThrough(r); }
    void workingPlane(const WorkingPlane& r) override { m_next.workingPlane(r); }
    void unknownAxes(const UnknownAxes& r) override { m_next.unknownAxes(r); }

protected:
    MachineSink& next() { return m_next; }

private:
    MachineSink& m_next;
};

}  // namespace camwb::toolpath
