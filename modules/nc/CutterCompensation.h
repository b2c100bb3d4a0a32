// Cutter radius compensation for all three dialects: a MachineSink between an interpreter and the
// caller's sink that turns the programmed contour of G41/G42 (RL/RR) into the path of the tool
// centre. Like LinuxCNC's interpreter it holds back the last move, because where a move ends
// depends on the next one: at an inside corner both are trimmed to where their offsets meet, at
// an outside corner an arc about the corner joins them. The records after a held move (comments,
// spindle, a retract in Z) wait behind it, so the order never changes.
#pragma once

#include "nc/Diagnostic.h"
#include "nc/detail/CompensationGeometry.h"
#include "toolpath/MachineSink.h"

#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace camwb::nc {

struct InterpretResult;

// The rules of a control where they differ; each interpreter's entry file says which it uses.
struct CompensationRules {
    // LinuxCNC ends the first move r beside its end point, square to the move itself (and then
    // treats the corner to the next move as any other); SINUMERIK (NORM) and Heidenhain end it
    // square to the first element of the contour.
    bool entrySquareToContour = true;
    // LinuxCNC also starts on an arc (its own entry arc); SINUMERIK and Heidenhain refuse it.
    bool arcEntry = false;
    // LinuxCNC refuses an entry move that moves only in Z (its length is not more than r).
    bool entryMustMoveInPlane = false;
    // Corners turning less than this (radians) are tangent: no arc, no trimming. LinuxCNC: 0.05.
    double tangentTolerance = 1e-6;
    // LinuxCNC: a reversal next to an arc the tool runs outside of is an inside corner.
    bool reversalOutsideArcIsInside = false;
    // Around an outside corner a rapid goes straight to the next offset start (LinuxCNC has no
    // arc traverse); otherwise it takes the corner arc like a feed move.
    bool rapidCornersStraight = false;
    // Entry move not longer than the radius: LinuxCNC refuses it (error); others warn.
    bool shortEntryIsError = false;
    // An arc outside the XY plane while compensation is on: Heidenhain compensates in the working
    // plane only (error, whether the radius is known or not); others warn, as it is traced in XY only.
    bool arcOutsideXyIsError = false;
    const char* selectWords = "G41/G42";  // in messages
    const char* cancelWord = "G40";

    // Each control's rules; the interpreters' entry files say where they come from.
    static CompensationRules linuxCnc();
    static CompensationRules sinumerik();
    static CompensationRules heidenhain();
};

class CutterCompensation final : public toolpath::MachineSink {
public:
    // Diagnostics go to `result` (file names from result.files by SourceRef::file), at most
    // `maxDiagnostics` there, each message once per line.
    CutterCompensation(toolpath::MachineSink& out, CompensationRules rules, InterpretResult& result,
                       std::size_t maxDiagnostics);

    // The radius the next selection (a CutterComp record Left/Right) compensates with, and what
    // it is in messages ("tool 3", "T3 D1"); nullopt: unknown, the programmed contour is traced
    // with a warning. A change while compensation is on takes effect at the next selection.
    void setRadius(std::optional<double> radiusMm, std::string what);
    // SINUMERIK G451: outside corners up to `limitDeg` of turn go to the intersection of the
    // offsets instead of around an arc (G450, the default).
    void setOutsideIntersection(bool on, double limitDeg = 100);

    void begin() override { m_out.begin(); }
    void end() override;
    void setSource(const toolpath::SourceRef& source) override;
    void rapid(const toolpath::Rapid& r) override;
    void linear(const toolpath::Linear& r) override;
    void arc(const toolpath::Arc& r) override;
    void cutterComp(const toolpath::CutterComp& r) override;
    void cycle(const toolpath::Cycle& r) override;
    void toolAxisMove(const toolpath::ToolAxisMove& r) override;
    void toolChange(const toolpath::ToolChange& r) override { forward<&MachineSink::toolChange>(r); }
    void spindle(const toolpath::Spindle& r) override { forward<&MachineSink::spindle>(r); }
    void coolant(const toolpath::Coolant& r) override { forward<&MachineSink::coolant>(r); }
    void feedMode(const toolpath::FeedModeChange& r) override { forward<&MachineSink::feedMode>(r); }
    void workOffset(const toolpath::WorkOffset& r) override { forward<&MachineSink::workOffset>(r); }
    void dwell(const toolpath::Dwell& r) override { forward<&MachineSink::dwell>(r); }
    void comment(const toolpath::Comment& r) override { forward<&MachineSink::comment>(r); }
    void sectionBegin(const toolpath::SectionBegin& r) override { forward<&MachineSink::sectionBegin>(r); }
    void sectionEnd(const toolpath::SectionEnd& r) override { forward<&MachineSink::sectionEnd>(r); }
    void programStop(const toolpath::ProgramStop& r) override { forward<&MachineSink::programStop>(r); }
    void passThrough(const toolpath::PassThrough& r) override { forward<&MachineSink::passThrough>(r); }
    void workingPlane(const toolpath::WorkingPlane& r) override { forward<&MachineSink::workingPlane>(r); }
    void unknownAxes(const toolpath::UnknownAxes& r) override { forward<&MachineSink::unknownAxes>(r); }

private:
    enum class State { Off, Starting, On };
    // A call waiting behind the held move: a record with its source, or a source alone (the
    // interpreters announce a calling block that way).
    struct Waiting {
        toolpath::SourceRef source;
        std::optional<toolpath::Record> record;
        bool followsHeld = false;  // a move in Z alone after the held move: its XY moves with it
    };

    void pass(const toolpath::Record& record);  // on now, or behind the held move
    template <auto Method, class R> void forward(const R& record)
    {
        if (m_holding)
            m_waiting.push_back({m_source, toolpath::Record(record), false});
        else
            (m_out.*Method)(record);
    }
    // No compensation on and none ending: the programmed path is the tool's.
    bool uncompensated() const { return m_state == State::Off && !m_leaving; }
    // Without compensation (most of every program) a move goes straight through, and the tool is
    // where the program says (m_tool is set when compensation starts); false: it did not.
    template <auto Method, class R> bool passedThrough(const R& record)
    {
        if (!uncompensated())
            return false;
        (m_out.*Method)(record);
        m_programmed = record.to;
        return true;
    }
    void emit(const toolpath::Record& record, const toolpath::SourceRef& source);
    void move(const toolpath::Record& record, base::Vec3 to, const detail::CompElement* arcElement);
    void moveInZ(const toolpath::Record& record, double z);
    void start(const toolpath::Record& record, base::Vec3 to, const detail::CompElement& element);
    void startOnArc(const toolpath::Record& record, base::Vec3 to, const detail::CompElement& element);
    void turnCorner(const toolpath::Record& record, const detail::CompElement& next);
    void continueWith(const toolpath::Record& record, base::Vec3 to, const detail::CompElement& next);
    void hold(toolpath::Record record, const detail::CompElement& programmed, base::Vec3 toolEnd);
    void moveHeldEnd(base::Vec2 to);
    void flush();
    bool active();
    void report(Severity severity, std::string message);
    bool left() const { return m_side == toolpath::CutterCompSide::Left; }
    void passProgrammed(const toolpath::Record& record, base::Vec3 to);

    toolpath::MachineSink& m_out;
    CompensationRules m_rules;
    InterpretResult& m_result;
    std::size_t m_maxDiagnostics;
    std::unordered_set<std::string> m_reported;

    toolpath::SourceRef m_source;
    State m_state = State::Off;
    toolpath::CutterCompSide m_side = toolpath::CutterCompSide::Off;
    std::optional<double> m_nextRadius;
    std::string m_nextWhat = "the tool";
    double m_radius = 0;
    std::string m_what;
    bool m_radiusKnown = false;
    bool m_warnedUnknown = false;
    bool m_outsideIntersection = false;
    double m_intersectionLimitRad = 0;
    bool m_leaving = false;  // cancelled: the next move in the plane must be straight

    base::Vec3 m_programmed;  // end of the last programmed move
    base::Vec3 m_tool;        // where the tool centre is after everything sent and held (while
                              // compensation is on or being left; else m_programmed)

    // The held move and what waits behind it.
    bool m_holding = false;
    toolpath::Record m_held;
    toolpath::SourceRef m_heldSource;
    detail::CompElement m_heldProgrammed;  // its programmed geometry
    detail::CompElement m_heldOffset;      // its compensated geometry (start, end, centre)
    bool m_entryOpen = false;              // an entry move square to a contour not yet seen
    std::vector<Waiting> m_waiting;
};

}  // namespace camwb::nc
