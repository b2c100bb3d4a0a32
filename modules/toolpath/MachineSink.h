// MachineSink: the one interface that speaks the CL vocabulary. Posts, the trace writer, the
// backplot and the simulator implement it; the toolpath player and NC interpreters drive it.
#pragma once

#include "toolpath/ClRecords.h"

namespace camwb::toolpath {

class Toolpath;

class MachineSink {
public:
    virtual ~MachineSink() = default;

    virtual void begin() {}
    virtual void end() {}

    virtual void rapid(const Rapid&) = 0;
    virtual void linear(const Linear&) = 0;
    virtual void arc(const Arc&) = 0;
    virtual void toolChange(const ToolChange&) = 0;
    virtual void spindle(const Spindle&) = 0;
    virtual void coolant(const Coolant&) = 0;
    virtual void feedMode(const FeedModeChange&) = 0;
    virtual void workOffset(const WorkOffset&) = 0;
    virtual void dwell(const Dwell&) = 0;
    virtual void cycle(const Cycle&) = 0;
    virtual void toolAxisMove(const ToolAxisMove&) = 0;
    virtual void cutterComp(const CutterComp&) = 0;
    virtual void comment(const Comment&) = 0;
    virtual void sectionBegin(const SectionBegin&) = 0;
    virtual void sectionEnd(const SectionEnd&) = 0;
    virtual void programStop(const ProgramStop&) = 0;
    virtual void passThrough(const PassThrough&) = 0;
    virtual void workingPlane(const WorkingPlane&) = 0;
    virtual void unknownAxes(const UnknownAxes&) = 0;

    // Called before each record with its source, for sinks that link output back to operations.
    virtual void setSource(const SourceRef&) {}
};

// Sends one record to the matching sink method.
void dispatch(const Record& record, MachineSink& sink);

// Plays a whole toolpath: begin(), every record (with setSource), end().
void play(const Toolpath& toolpath, MachineSink& sink);

}  // namespace camwb::toolpath
