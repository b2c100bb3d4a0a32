// The SINUMERIK interpreter's run time: modal state, R parameters and DEF variables, the call
// stack over parsed programs, and what it sends to the MachineSink. Split over Machine.cpp (run
// loop, control flow, calls), Evaluate.cpp, Execute*.cpp (ordinary blocks), Arcs.cpp, Cycles.cpp.
#pragma once

#include "nc/CutterCompensation.h"
#include "nc/FiveAxis.h"
#include "nc/Interpreter.h"
#include "nc/KnownAxes.h"
#include "nc/ToolTable.h"
#include "nc/sinumerik/Program.h"
#include "toolpath/ClRecords.h"
#include "toolpath/MachineSink.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace camwb::nc::sinumerik {

using toolpath::Vec3;

struct Modal {
    int motion = 0;  // 0 rapid, 1 linear, 2 cw, 3 ccw
    int plane = 17;  // 17, 18, 19
    bool incremental = false;
    bool inch = false;      // G70/G700
    bool inchFeed = false;  // G700: feeds in inch too
    int unitsCode = 71;     // as programmed: 70, 700, 71, 710 (G71 until one is)
    toolpath::FeedMode feedMode = toolpath::FeedMode::PerMinute;
    bool constantSurfaceSpeed = false;  // G96
    bool diameter = false;              // DIAMON: X is a diameter
    toolpath::CutterCompSide comp = toolpath::CutterCompSide::Off;
    int workOffset = -1;  // not yet programmed
    bool traori = false;  // TRAORI: X Y Z the tool tip in the workpiece frame (a five-axis machine only)
};

// A modal call (MCALL): a cycle with its arguments evaluated when it was set, or a subprogram.
struct ModalCall {
    int cycle = 0;  // 81..89; -1: subprogram `name`
    std::string name;
    std::vector<std::optional<double>> args;
    int line = 0;
    std::size_t level = 0;  // call-stack depth it was set at: it does not fire inside its own call
};

struct Frame {
    int program = 0;
    int pc = 0;
    std::size_t localsBase = 0;
    int repeatsLeft = 0;       // P repetitions still to run after this one
    int callPc = 0;            // the calling block (its program is the previous frame's)
    std::vector<double> args;  // parameter values, kept for the repetitions of a P call
};

class Machine {
public:
    // `sink` compensates the cutter radius (CutterCompensation.h) in front of the caller's sink.
    Machine(const InterpretOptions& options, CutterCompensation& sink, InterpretResult& result) :
        m_options(options),
        m_sink(sink),
        m_compensation(sink),
        m_result(result),
        m_five(options.machine)
    {
        if (options.start)
            m_pos = *options.start;
        m_known = knownAtStart(options);
    }
    void run(std::string_view mainText);

    // Evaluate.cpp: the value of expression `e` of program `p`; nullopt after an error (reported).
    std::optional<double> eval(const Program& p, std::int32_t e);
    std::optional<double> wordValue(const Program& p, const Word& w)
    {
        return w.expr < 0 ? std::optional<double>(w.value) : eval(p, w.expr);
    }

private:
    std::optional<double> evalOperand(const Program& p, const Expr& e);
    std::optional<double> evalFailure(const Program& p, const Expr& e, const std::string& message);

    // Machine.cpp
    void runLoop();
    bool step();         // one block; false: the program ended or stopped
    void reportModal();  // to options.onBlock
    void jumpBack(int target);
    bool callProgram(const std::string& name, const Block& block, const Program& caller, int repeats,
                     const std::vector<std::optional<double>>& args);
    int loadProgram(const std::string& name, Pos callPos, const Program& caller);
    bool returnFromCall();
    void checkProcName(const Program& p, std::string_view expected);
    void reportRunaway();
    int jumpTarget(const Program& p, const std::string& label, int pc, GotoDir dir, bool& anyTarget) const;
    void addParseDiagnostics(const Program& p);

    // Execute.cpp, ExecuteWords.cpp: an ordinary block, its words read first, then applied group by
    // group in the control's order.
    struct ArcWords {
        std::array<std::optional<double>, 3> centre;  // I J K in mm, with their mode
        std::array<ValueMode, 3> centreMode{};
        std::optional<double> cr, ar;
        int turn = 0;
        Pos pos;
    };
    struct BlockWords {
        int line = 0;
        int motion = -1, plane = 0, units = 0, absInc = 0, workOffset = -1, comp = -1, feedMode = -1, css = -1;
        int corners = 0;  // G450 transition circle, G451 intersection
        bool dwell = false, g53 = false, ret = false;
        std::array<std::optional<double>, 6> axis{};
        std::array<ValueMode, 6> axisMode{};
        std::array<Pos, 6> axisPos{};
        ArcWords arc;
        std::optional<double> feed, speed, lims, tool, edge;
        int m[8];
        int mCount = 0;
        const Word* callWord = nullptr;                     // the block's cycle or subprogram call
        std::array<std::optional<double>, 3> toolVector{};  // A3 B3 C3
        Pos toolVectorPos;
        int transform = -1;                 // 1 TRAORI, 0 TRAFOOF
        int approach = 0;                   // 74 G74 (reference point), 75 G75 (fixed point)
        toolpath::AxisMask machineAxes{0};  // X1= Y1= Z1=
        Pos machineAxisPos;
    };
    // Rotary.cpp: rotary words, TRAORI/TRAFOOF and A3/B3/C3 through the machine's kinematic chain.
    struct RotaryMove {
        JointAngles angles;   // after the block
        bool vector = false;  // A3/B3/C3: the angles come from the tool vector once the tip is known
        Vec3 axis;
        bool moves = false;  // the block turns the tool or the table in a way the trace shows
    };
    bool rotaryTarget(const Program& p, const BlockWords& w, RotaryMove& r);
    bool toolVector(const Program& p, const BlockWords& w, RotaryMove& r);
    // False: an error, the block is left out. `traced` false: a five-axis move the trace cannot
    // show (a linear axis is still unknown); the block runs without a record.
    bool fiveAxisReady(const Program& p, const BlockWords& w, const RotaryMove& r, toolpath::AxisMask given,
                       bool& traced);
    bool turnTo(const Program& p, const BlockWords& w, const RotaryMove& r, const Vec3& target);
    bool moveFiveAxis(const Program& p, const BlockWords& w, const Vec3& target);
    void applyTransformation(const Program& p, const BlockWords& w);
    bool executeNormal(const Program& p, const Block& block);
    bool readWords(const Program& p, const Block& block, BlockWords& w);
    void readG(const Program& p, const Word& word, BlockWords& w);
    bool readKeyword(const Program& p, const Block& block, const Word& word, BlockWords& w);
    bool readPosition(const Program& p, const Word& word, std::optional<double>& value, ValueMode& mode);
    void applyUnits(const BlockWords& w);
    void applyDistanceMode(const BlockWords& w);
    void applyPlane(const BlockWords& w);
    void applyWorkOffset(const Program& p, const BlockWords& w);
    void applyFeedMode(const BlockWords& w);
    void applyFeedRate(const BlockWords& w);
    void applyToolChange(const BlockWords& w);
    void applySpindle(const Program& p, const BlockWords& w);
    void applyCoolant(const BlockWords& w);
    void applyToolOffset(const Program& p, const BlockWords& w);
    void applyCompensation(const BlockWords& w);
    void setCompensationRadius();
    void applyDwell(const Program& p, const BlockWords& w);
    bool applyMotion(const Program& p, const BlockWords& w);
    bool moveInMachineCoordinates(const Program& p, const BlockWords& w);  // true: the tool moved
    bool approachFixedPoint(const Program& p, const BlockWords& w);        // G74/G75
    bool loseMachineAxes(int line, toolpath::AxisMask axes);
    void applyCalls(const Program& p, const Block& block, const BlockWords& w, bool moved);
    bool applyStop(const Program& p, const Block& block, const BlockWords& w);
    Vec3 blockTarget(const BlockWords& w) const;
    bool checkKnown(const Program& p, const BlockWords& w, toolpath::AxisMask& given);
    bool needKnown(const Program& p, const BlockWords& w, toolpath::AxisMask before, toolpath::AxisMask after,
                   toolpath::AxisMask given, const char* need, Pos fallback);
    void emitComment(const Program& p, const Block& block);
    double toMm(double v) const { return m_modal.inch ? v * 25.4 : v; }
    double feedToInternal(double f) const;
    bool checkRange(const Program& p, Pos pos, double mm);
    void setSource(int line);
    void setFeedMode(toolpath::FeedMode mode, int line);
    void emitSpindle(int line);
    void assign(const Program& p, const Word& w, double value);

    // Arcs.cpp: circle or helix from m_pos to `to`; false when the arc is inconsistent (reported).
    bool arc(const Program& p, const Vec3& to, bool clockwise, const ArcWords& words, int line);

    // Cycles.cpp: one hole of CYCLE8x at the current position (the tool is over the hole).
    bool runCycle(const Program& p, int number, const std::vector<std::optional<double>>& args, Pos pos, int line);
    std::vector<std::optional<double>> evalArgs(const Program& p, const Block& block);
    // Swivel.cpp: CYCLE800, the swivelled working plane.
    void swivel(const Program& p, const Block& block, const Word& word);
    void setPlane(int line, const toolpath::WorkingPlane& plane);

public:
    // Diagnostics, deduplicated per place and message: loops report a problem once.
    void diag(Severity severity, const Program& p, Pos pos, const std::string& message);
    void error(const Program& p, Pos pos, const std::string& message) { diag(Severity::Error, p, pos, message); }
    void warning(const Program& p, Pos pos, const std::string& message) { diag(Severity::Warning, p, pos, message); }

private:
    const InterpretOptions& m_options;
    toolpath::MachineSink& m_sink;
    CutterCompensation& m_compensation;
    InterpretResult& m_result;

    std::vector<std::unique_ptr<Program>> m_programs;  // index = file index
    std::unordered_map<std::string, int> m_byName;     // upper-case called name -> program (-1: not found)
    std::vector<Frame> m_stack;
    std::vector<double> m_locals;
    std::array<double, 1000> m_r{};
    std::unordered_set<std::uint64_t> m_reported;
    std::vector<std::vector<std::uint32_t>> m_loopCounts;  // per program, per block: back jumps
    bool m_stopped = false;
    bool m_evalFailed = false;
    bool m_toolChangeOnM6 = true;

    Modal m_modal;
    Vec3 m_pos;          // 0 on axes not yet known
    KnownAxes m_known;   // axes given in absolute terms so far (none at the start)
    double m_feed = 0;   // mm/min, mm/rev or 1/min by the feed mode
    double m_speed = 0;  // S: rpm, or m/min under G96
    double m_lims = 0;
    int m_spindleDir = 0;  // 0 stopped, 3 cw, 4 ccw
    bool m_spindleEmitted = false;
    int m_tool = 0;        // selected with T
    int m_activeTool = 0;  // changed in (M6; T at once without M6)
    int m_edge = 0;        // the cutting edge D (tool offsets): D1 after a tool change, D0 none
    // $TC_DP6 (radius) and $TC_DP15 (its wear) per (tool, edge) as the program set them.
    struct EdgeData {
        std::optional<double> radius;
        double radiusWear = 0;
    };
    std::map<std::pair<int, int>, EdgeData> m_edges;
    std::string m_toolName;
    std::string m_message;  // the text of the last MSG("..."), empty after MSG(): SETAL reports it
    std::optional<ModalCall> m_modalCall;
    bool m_fiveAxisWarned = false;
    bool m_warnedMachineCoordinates = false;  // G53/G153/SUPA warned once
    bool m_warnedApproach = false;            // G74/G75 warned once
    FiveAxisState m_five;
    toolpath::WorkingPlane m_plane;  // CYCLE800's swivelled frame (default: none)
    int m_currentFile = 0;
    int m_currentLine = 0;
};

}  // namespace camwb::nc::sinumerik
