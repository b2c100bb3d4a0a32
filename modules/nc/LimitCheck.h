// Checks an interpreted program against the machine it is meant for (`nc trace --machine`):
// spindle speed range, cutting feed, tool stations, and whether the program's span on each
// linear axis fits the axis travel. A MachineSink in front of the real one, so every dialect
// gets the same checks; each finding is a warning on the first line that causes it.
#pragma once

#include "nc/Diagnostic.h"
#include "toolpath/MachineSink.h"

#include <string>
#include <vector>

namespace camwb::kinematics {
struct Machine;
}

namespace camwb::nc {

class LimitCheck : public toolpath::MachineSink {
public:
    // `files` names the program files (InterpretResult::files) by the time diagnostics() is called.
    LimitCheck(const kinematics::Machine& machine, toolpath::MachineSink& next);

    // Warnings so far, the span checks included (call after the interpreter is done).
    std::vector<Diagnostic> diagnostics(const std::vector<std::string>& files) const;

    void begin() override { m_next.begin(); }
    void end() override { m_next.end(); }
    void setSource(const toolpath::SourceRef& source) override;
    void rapid(const toolpath::Rapid& r) override;
    void linear(const toolpath::Linear& r) override;
    void arc(const toolpath::Arc& r) override;
    void toolChange(const toolpath::ToolChange& r) override;
    void spindle(const toolpath::Spindle& r) override;
    void coolant(const toolpath::Coolant& r) override { m_next.coolant(r); }
    void feedMode(const toolpath::FeedModeChange& r) override;
    void workOffset(const toolpath::WorkOffset& r) override { m_next.workOffset(r); }
    void dwell(const toolpath::Dwell& r) override { m_next.dwell(r); }
    void cycle(const toolpath::Cycle& r) override;
    void toolAxisMove(const toolpath::ToolAxisMove& r) override;
    void cutterComp(const toolpath::CutterComp& r) override { m_next.cutterComp(r); }
    void comment(const toolpath::Comment& r) override { m_next.comment(r); }
    void sectionBegin(const toolpath::SectionBegin& r) override { m_next.sectionBegin(r); }
    void sectionEnd(const toolpath::SectionEnd& r) override { m_next.sectionEnd(r); }
    void programStop(const toolpath::ProgramStop& r) override { m_next.programStop(r); }
    void passThrough(const toolpath::PassThrough& r) override { m_next.passThrough(r); }

private:
    struct Finding {
        toolpath::SourceRef where;
        std::string message;
    };
    void reach(const toolpath::Vec3& p);
    void checkFeed(double feed);
    void warnOnce(const std::string& key, std::string message);

    const kinematics::Machine& m_machine;
    toolpath::MachineSink& m_next;
    toolpath::SourceRef m_source;
    bool m_perMinute = true;
    bool m_any = false;
    toolpath::Vec3 m_min, m_max;
    toolpath::SourceRef m_minAt[3], m_maxAt[3];
    std::vector<std::string> m_keys;
    std::vector<Finding> m_findings;
};

}  // namespace camwb::nc
