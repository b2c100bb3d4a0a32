// Checks a program against the machine it is meant for: one set of rules for posting (CL
// records), `nc trace --machine` and the NC inspector (interpreted NC). Travel: the program's span
// on each linear axis (arcs by their exact extremes, cycles down to the hole bottom; the work
// offset is not known, so only a span longer than the travel is certain to fail); spindle speed
// range; cutting feed range (per minute); tool stations (T0 empties the spindle: cutting after it
// is flagged); tool diameter and length; coolants. A filter: every record passes on unchanged.
// Rotary axes: the positions a five-axis move gives (ToolAxisMove::machine, from NC read back or a
// post's solved pose) against their range, an endless axis having none; with both angles of the
// machine's chain known, the linear spans are the machine's (through the chain), not the tip's.
#pragma once

#include "base/Diagnostic.h"
#include "kinematics/Machine.h"
#include "toolpath/ForwardingSink.h"
#include "toolpath/KnownPosition.h"

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace camwb::kinematics {

class LimitCheck : public toolpath::ForwardingSink {
public:
    LimitCheck(const Machine& machine, toolpath::MachineSink& next);

    // One finding per kind of violation, at the first record that breaks the limit.
    struct Finding {
        toolpath::SourceRef source;  // as set before that record
        std::size_t record = 0;      // its index among the records this check saw
        int count = 0;               // records that break the limit
        std::string message;
    };
    // In the order they were first met; the travel spans (known only at the end) last.
    std::vector<Finding> findings() const;

    // The findings as warnings at the program line of interpreted NC (`files` names
    // SourceRef::file, as nc::InterpretResult::files does) ...
    std::vector<base::Diagnostic> ncDiagnostics(const std::vector<std::string>& files) const;
    // ... or naming the CL record of a toolpath that was played into this check.
    std::vector<base::Diagnostic> clDiagnostics() const;

    void setSource(const toolpath::SourceRef& source) override;
    void rapid(const toolpath::Rapid& r) override;
    void linear(const toolpath::Linear& r) override;
    void arc(const toolpath::Arc& r) override;
    void toolChange(const toolpath::ToolChange& r) override;
    void spindle(const toolpath::Spindle& r) override;
    void coolant(const toolpath::Coolant& r) override;
    void feedMode(const toolpath::FeedModeChange& r) override;
    void workOffset(const toolpath::WorkOffset& r) override;
    void dwell(const toolpath::Dwell& r) override;
    void cycle(const toolpath::Cycle& r) override;
    void toolAxisMove(const toolpath::ToolAxisMove& r) override;
    void cutterComp(const toolpath::CutterComp& r) override;
    void comment(const toolpath::Comment& r) override;
    void sectionBegin(const toolpath::SectionBegin& r) override;
    void sectionEnd(const toolpath::SectionEnd& r) override;
    void programStop(const toolpath::ProgramStop& r) override;
    void passThrough(const toolpath::PassThrough& r) override;
    void workingPlane(const toolpath::WorkingPlane& r) override;
    void unknownAxes(const toolpath::UnknownAxes& r) override;

private:
    struct Reach {  // the lowest and highest value met on one axis, and where
        double value = 0;
        toolpath::SourceRef source;
        std::size_t record = 0;
    };
    void nextRecord();
    void flag(const std::string& key, const std::string& message);
    void reach(const toolpath::Vec3& p, toolpath::AxisMask axes = {});         // in the working plane's frame
    void reachMachine(const toolpath::Vec3& p, toolpath::AxisMask axes = {});  // only the axes given
    void cutting(double feed);
    void rotary(const toolpath::RotaryAxes& machine);
    toolpath::Vec3 linearAxes(const toolpath::ToolAxisMove& r) const;
    std::vector<Finding> spanFindings() const;

    const Machine& m_machine;
    std::string m_name;
    bool m_lathe = false;  // X and Z, no Y: moves must stay at Y = 0
    toolpath::SourceRef m_source;
    std::size_t m_records = 0;  // records seen, the current one included
    bool m_perMinute = true;
    bool m_noTool = false;  // after a change to T0
    toolpath::KnownPosition m_position;
    toolpath::WorkingPlane m_plane;          // the frame moves are in (3+2)
    std::optional<MachinePose> m_planePose;  // the pose that tilts the tool along it
    toolpath::AxisMask m_reached{0};         // the axes some move has given
    std::array<Reach, 3> m_low, m_high;
    std::vector<Finding> m_findings;
    std::map<std::string, std::size_t> m_findingOfKey;
};

}  // namespace camwb::kinematics
