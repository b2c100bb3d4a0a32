// The Klartext interpreter's machine: modal state (position, datum shift, pole CC, feed, tool,
// spindle, compensation, cycle definition, Q parameters), the program counter with its call
// stack (CALL LBL repeats and subprograms, CALL PGM), and the MachineSink it drives. Control flow
// and M functions live in Machine.cpp, contour elements in Contour.cpp, cycles in Cycles.cpp.
#pragma once

#include "base/NumberFormat.h"
#include "nc/CutterCompensation.h"
#include "nc/FiveAxis.h"
#include "nc/Interpreter.h"
#include "nc/KnownAxes.h"
#include "nc/ToolTable.h"
#include "nc/heidenhain/Expression.h"
#include "nc/heidenhain/Geometry.h"
#include "nc/heidenhain/Lexer.h"
#include "nc/heidenhain/Program.h"
#include "toolpath/ClRecords.h"
#include "toolpath/MachineSink.h"

#include <array>
#include <bitset>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace camwb::nc::heidenhain {

inline constexpr double kMaxCoordinate = 99999.9999;  // the control's input range
inline constexpr int kMaxLabelNesting = 64;
inline constexpr int kMaxProgramNesting = 16;
inline constexpr std::size_t kMaxPrograms = 64;  // different programs one run may load (memory bound)

// Millimetres in messages: four decimals, independent of the C locale (the GUI sets the user's).
inline std::string mm(double v) { return base::formatFixed(v, 4); }

// Keys of the warnings given once per run.
enum WarnKey : int {
    kWarnRotary,
    kWarnTcpm,
    kWarnM91,
    kWarnM140,
    kWarnToolAxis,
    kWarnSurfaceSpeed,
    kWarnFeedTooth,
    kWarnApproach,
    kWarnCycleRadius,
    kWarnBackBoring,
    kWarnAutoFeed,
    kWarnCalledEnd,
    kWarnRapidArc,
    kWarnZeroFeed,
    kWarnParallelAxes,
    kWarnNoChain,
    kWarnCompTilted,
    kWarnTcpmRefCenter,
    kWarnTcpmFeed,
    kWarnFiveAxisUnknown,
};

// The evaluated words of one block (values in program units, not yet scaled or shifted).
struct BlockWords {
    std::array<std::optional<double>, 18> axes;  // Key::X .. Key::IW
    std::optional<double> pr, pa, ipr, ipa, radius, len, angle, mb, length, deltaLength;
    int direction = 0;  // +1 DR+, -1 DR-, 0 none
    int comp = -1;      // 0 R0, 1 RL, 2 RR
    enum class FeedWord { None, Value, Max, Auto, PerRev, PerTooth } feed = FeedWord::None;
    double feedValue = 0;
    std::array<int, 8> m{};
    int mCount = 0;
    int mColumn = 0;
    bool mbMax = false;
    bool rotary = false;  // A/B/C/U/V/W were written
    bool hasXyz() const;
};

struct CycleDefinition {
    int number = 0;
    int line = 0;
    std::array<double, 400> q{};  // Q200..Q599
    std::bitset<400> set;
    bool defined = false;
    bool depthWarned = false;
    double get(int n, double fallback = 0) const;
    bool has(int n) const { return n >= 200 && n < 600 && set.test(static_cast<std::size_t>(n - 200)); }
};

// The circle centre and pole of the last CC, in the coordinates (u, v) of its plane: the plane its
// two axes name (17 XY, 18 ZX, 19 YZ; nc/detail/PlaneAxes.h), which C, CP and LP work in.
struct Pole {
    Vec2 at;
    int plane = 17;
    bool set = false;
};

// The last direction of travel in each main plane (index plane - 17), for CT and DEP LT: a move
// that does not move in a plane leaves that plane's tangent as it was.
using Tangents = std::array<std::optional<Vec2>, 3>;

// The plane a circle block works in (17, 18, 19): CR and CT name it with two axes, else the pole's.
int circlePlane(BlockKind kind, const BlockWords& w, const Pole& pole);

// A corner rounding or chamfer planned when the element before it was sent, with the element
// after it as planned from the corner (so that incremental words and CR/CP keep their geometry).
struct Corner {
    bool valid = false;
    int program = -1;
    std::size_t block = 0;
    bool arc = false;
    Vec3 from, to;
    Vec2 center;
    bool clockwise = false;
    std::size_t nextBlock = 0;
    Element next;
    bool nextPending = false;
};

class Machine {
public:
    // `sink` compensates the cutter radius (CutterCompensation.h) in front of the caller's sink.
    Machine(const InterpretOptions& options, CutterCompensation& sink, InterpretResult& result);
    void run(std::string_view text);

private:
    struct Frame {
        int program = 0;
        std::size_t callPc = 0;  // the CALL block
        std::size_t returnPc = 0;
        std::size_t target = 0;  // the label's block (repeats jump after it)
        std::int64_t remaining = 0;
        bool isProgram = false;
    };

    // Machine.cpp: control flow, state, M functions, tools, parameters.
    void execute(const Block& b);
    void reportModal(const Block& b);  // to options.onBlock
    void source(const Block& b);
    void source(int line);
    void report(Severity s, int line, int column, std::string message);
    void warnOnce(int key, const Block& b, const std::string& message);
    bool gather(const Block& b, BlockWords& w, bool quiet);
    void applySpindleAndCoolant(const Block& b, const BlockWords& w);
    void applyStop(const Block& b, const BlockWords& w, bool moved);
    void applyFeedRate(const BlockWords& w);
    void setFeedMode(toolpath::FeedMode mode);
    void applyCompensation(const BlockWords& w);
    void setCompensationRadius();
    void endProgram(bool completed);
    void sortDiagnostics();
    void returnFromProgram();
    void toolCall(const Block& b);
    void toolDef(const Block& b);
    void callLabel(const Block& b);
    void callProgram(const Block& b);
    void label(const Block& b);
    void fnAssign(const Block& b);
    void fnJump(const Block& b);
    void spindleOn(bool clockwise, const Block& b, int column);
    void spindleOff();
    void coolant(toolpath::CoolantMode mode);
    std::optional<std::size_t> findLabel(std::string_view ref, bool isName);
    const Program& program() const { return *m_programs[static_cast<std::size_t>(m_prog)]; }
    std::optional<double> eval(int expr, bool quiet = false);

    // Contour.cpp: elements, corners, sending moves; Circles.cpp: CC, circles and polar moves.
    void motionBlock(const Block& b);
    bool applyMotion(const Block& b, const BlockWords& w);  // true: an element was sent
    void circleCenter(const Block& b);
    void corner(const Block& b);
    std::optional<Element> plan(const Block& b, const BlockWords& w, const Vec3& from, const Pole& pole,
                                const Tangents& tangents, bool quiet);
    std::optional<Element> planCircle(const Block& b, const BlockWords& w, Element e, const Pole& pole,
                                      const Tangents& tangents, bool quiet);
    std::optional<Element> planPolarCircle(const Block& b, const BlockWords& w, Element e, const Pole& pole,
                                           bool quiet);
    bool needPole(const Block& b, const Pole& pole, bool quiet);
    bool direction(const Block& b, const BlockWords& w, bool quiet, bool& clockwise);
    std::optional<Pole> centreOf(const Block& b, const BlockWords& w, const Vec3& from, const Pole& previous,
                                 bool quiet);
    std::optional<Vec3> target(const Block& b, const BlockWords& w, const Vec3& from, bool quiet);
    void planCorner(Element& element, std::size_t cornerIndex);
    void send(const Element& e, bool rapid, double feed);
    bool checkKnown(const Block& b, const BlockWords& w, toolpath::AxisMask& given);
    bool needKnown(const Block& b, toolpath::AxisMask before, toolpath::AxisMask after, toolpath::AxisMask given,
                   const char* need);

    // FiveAxis.cpp: rotary words, tool-tip control (M128/M129, FUNCTION TCPM), M126/M127, moves
    // through the machine's kinematic chain.
    struct RotaryTarget {
        JointAngles angles;    // after the block
        bool spatial = false;  // AXIS SPAT: the angles come from m_spatial once the tip is known
        bool changed = false;  // the block turns a rotary axis
    };
    bool rotaryTarget(const Block& b, const BlockWords& w, RotaryTarget& target);
    // False: an error, the block is not run. `traced` false: a five-axis move the trace cannot show
    // (a linear axis is still unknown); the block runs without a record.
    bool fiveAxisReady(const Block& b, const RotaryTarget& target, toolpath::AxisMask given, bool& traced);
    bool orientSpatial(const Block& b, const Vec3& end);
    void tcpmFunction(const Block& b);
    void setTcpm(bool on);
    void sendFiveAxis(const Element& e, bool rapid, double feed);
    void updateToolLength();

    // Retract.cpp: M140 MB and PLANE ... MB, by a distance (program units) or, nullopt, MB MAX.
    static bool inMachineCoordinates(const BlockWords& w);  // M91 or M92 in the block
    void moveInMachineCoordinates(const Block& b, const BlockWords& w);
    void retract(const Block& b, std::optional<double> distance, const std::string& what);
    void retractAlongToolAxis(double distanceMm);

    // Planes.cpp: tilted working planes (PLANE, CYCL DEF 19) with the datum shift.
    void planeFunction(const Block& b);
    void workingPlaneCycle(const Block& b, const BlockWords& w);
    std::optional<toolpath::WorkingPlane> planeOfVectors(const Block& b,
                                                         const std::array<std::optional<double>, kPlaneWordCount>& v);
    std::optional<toolpath::WorkingPlane>
    planeOfAxisAngles(const Block& b, const std::array<std::optional<double>, 3>& abc, const std::string& what);
    void tilt(const Block& b, const toolpath::WorkingPlane& rotation);
    void rotationCycle(const Block& b);
    void positionForPlane(const Block& b, const toolpath::WorkingPlane& plane);
    void checkToolAlongPlane(const Block& b);

    // Cycles.cpp: CYCL DEF, CYCL CALL, M99/M89.
    void cycleDef(const Block& b);
    void datumSetting(const Block& b);
    void cycleCall(const Block& b);
    void runCycle(const Block& b, Vec2 hole);
    void cycleRecord(const Block& b, Vec2 hole);
    void boreMilling(const Block& b, Vec2 hole);
    void backBoring(const Block& b, Vec2 hole);

    const InterpretOptions& m_options;
    toolpath::MachineSink& m_sink;
    CutterCompensation& m_compensation;
    InterpretResult& m_result;
    Reporter m_rep;

    std::vector<std::unique_ptr<Program>> m_programs;
    std::unordered_map<std::string, int> m_programByName;
    int m_prog = 0;
    std::size_t m_pc = 0;
    bool m_jumped = false;
    bool m_stop = false;
    std::vector<Frame> m_frames;
    int m_programDepth = 0;

    Parameters m_params;
    Vec3 m_pos;                      // 0 on axes not yet known
    KnownAxes m_known;               // axes given in absolute terms so far (none at the start)
    Vec3 m_shift;                    // the datum shift, in the tilted plane's frame while one is tilted
    toolpath::WorkingPlane m_plane;  // the working plane in force: the tilt turned by the rotation
    toolpath::WorkingPlane m_tilt;   // the tilt PLANE / CYCL DEF 19 set (default: none)
    double m_rotationDeg = 0;        // CYCL DEF 10 ROT: about the working plane's tool axis
    std::optional<std::array<double, 2>> m_planeAngles;  // the joint angles PLANE AXIAL / CYCL DEF 19 gave
    bool m_planeChecked = false;                         // the tool's axis was checked against the plane
    double m_scale = 1;                                  // mm per program unit
    double m_feedScale = 1;                              // mm/min per programmed feed unit
    Pole m_pole;
    Tangents m_tangents;
    toolpath::AxisMask m_programmed = kNoAxes;  // absolute X/Y/Z since the start or the last "..." of a fragment
    int m_lastDirection = 0;
    double m_feed = 0;
    double m_autoFeed = 0;
    toolpath::FeedMode m_feedMode = toolpath::FeedMode::PerMinute;
    bool m_m136 = false;  // M136 until M137: F per spindle revolution
    toolpath::CutterCompSide m_comp = toolpath::CutterCompSide::Off;
    int m_tool = 0;
    double m_rpm = 0;
    bool m_spindleOn = false;
    bool m_spindleCw = true;
    toolpath::CoolantMode m_coolant = toolpath::CoolantMode::Off;
    std::unordered_map<int, double> m_toolRadius;  // TOOL DEF R, mm
    double m_deltaRadius = 0;                      // DR of the last TOOL CALL, mm
    char m_toolAxis = 'Z';                         // of the last TOOL CALL
    CycleDefinition m_cycle;
    bool m_modalCycleCall = false;
    Corner m_corner;
    std::bitset<64> m_warned;
    FiveAxisState m_five;
    bool m_axisSpat = false;                       // FUNCTION TCPM AXIS SPAT in force
    std::array<double, 3> m_spatial{0, 0, 0};      // its spatial angles A, B, C
    std::unordered_map<int, double> m_toolLength;  // TOOL DEF L, mm
    double m_deltaLength = 0;                      // DL of the last TOOL CALL, mm
    int m_cornerWarnedProgram = -1;
    std::size_t m_cornerWarnedBlock = 0;
};

}  // namespace camwb::nc::heidenhain
