// The rotary axes of a five-axis machine as an NC program moves them, read through the machine's
// kinematic chain (kinematics/KinematicChain.h): which angles are known, tool-tip control on or off
// (Heidenhain M128 / FUNCTION TCPM, SINUMERIK TRAORI) and what a block's programmed position and
// angles mean for the tool tip and axis in the workpiece frame. Shared by the SINUMERIK and
// Heidenhain interpreters; without a machine whose chain is five-axis nothing here is active.
#pragma once

#include "kinematics/KinematicChain.h"
#include "kinematics/Machine.h"
#include "kinematics/PoseSolver.h"
#include "toolpath/ClRecords.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace camwb::nc {

// How a rotary word gives its angle: absolute, incremental, the shorter way round (Heidenhain M126,
// SINUMERIK DC) or in the positive / negative sense only (SINUMERIK ACP / ACN).
enum class RotaryMode { Absolute, Incremental, Shortest, Positive, Negative };

// Joint angles in KinematicChain::joints order, each known or not.
struct JointAngles {
    std::array<double, 2> deg{0, 0};
    std::array<bool, 2> known{false, false};

    bool complete() const { return known[0] && known[1]; }
    // Some known angle is not zero: the tool or the workpiece is turned away from the 3-axis pose.
    bool turned() const;
    // Every known angle at a whole turn: the tool and table stand as in the 3-axis pose (C360 too).
    bool atHome() const;
};

// What a rotary word means on this machine.
enum class RotaryAxisUse {
    NoMachine,  // no machine given: the word is warned about and ignored, as before five-axis
    Missing,    // the machine has no such axis: an error
    NoChain,    // the machine has the axis but its file gives no five-axis chain: warned, ignored
    Traced,     // a joint of the chain
};

class FiveAxisState {
public:
    explicit FiveAxisState(const kinematics::Machine* machine);
    ~FiveAxisState();

    bool active() const { return m_chain != nullptr; }
    const kinematics::Machine* machine() const { return m_machine; }

    // What `axis` ('A', 'B', 'C') is on this machine; `joint` gets its index in the chain.
    RotaryAxisUse use(char axis, int* joint = nullptr) const;
    // "the MAS MCVL 1000 has no A axis" and the like, for the diagnostics of use().
    std::string useMessage(char axis, RotaryAxisUse use) const;

    const JointAngles& angles() const { return m_angles; }
    // The angle `joint` takes for a word; nullopt when an incremental or directed word needs an
    // angle that is not known yet.
    std::optional<double> angleFor(int joint, double value, RotaryMode mode) const;
    // The angle for an absolute word with M126 (Heidenhain) in force: the shorter way on an
    // endless axis, as written otherwise.
    void setShortestPath(bool on) { m_shortestPath = on; }
    bool shortestPath() const { return m_shortestPath; }
    void setAngles(const JointAngles& a) { m_angles = a; }

    // Tool-tip control: programmed X/Y/Z are the tip in the workpiece frame (on) or the machine's
    // linear axes (off). Switching converts `programmed` so the tool stays where it is, when the
    // whole pose is known.
    bool tcpm() const { return m_tcpm; }
    void setTcpm(bool on, toolpath::Vec3& programmed, bool linearKnown);

    // The tool's length (a head joint turns the tool about a pivot above the tip); nullopt: unknown.
    void setToolLength(std::optional<double> mm) { m_toolLength = mm; }
    // The chain turns the tool (a head joint) and programmed positions are machine axes: the tip
    // then depends on the tool length.
    bool needsToolLength() const;
    bool toolLengthKnown() const { return m_toolLength.has_value(); }

    // A move to `programmed` with the current angles is five-axis: they or the last pose sent
    // were turned. Plain 3-axis moves otherwise, so 3-axis programs trace as before. In a tilted
    // working plane (PLANE, CYCL DEF 19, CYCLE800) moves are 3-axis moves in the plane's frame.
    bool fiveAxisMove() const { return !m_inPlane && (m_angles.turned() || m_lastSentTurned); }
    // What a block turning the rotary axes to `target` (or, `orientation`, asking for a tool
    // vector) can be traced as: the one decision of both interpreters' fiveAxisReady, which add
    // their dialect's diagnostics. `tipKnown`: X, Y and Z known after the block; `linearGiven`:
    // the block gives some linear axis.
    enum class BlockTrace {
        ThreeAxis,        // no machine, a tilted plane's move, nothing turned: a 3-axis move
        HomeUntraced,     // home from a turned pose, the tool somewhere up its axis: not drawn
        TipUnknown,       // turned with X, Y or Z unknown (after a retract to the travel limit)
        NeedsToolLength,  // a head turns the tool without tool-tip control, its length unknown
        FiveAxis,
    };
    BlockTrace blockTrace(const JointAngles& target, bool orientation, bool tipKnown, bool linearGiven) const;
    void setInPlane(bool tilted);
    bool inPlane() const { return m_inPlane; }
    // The frame of a tilted plane given by the machine's axis angles (CYCL DEF 19): the machine's
    // X and Z as the angles turn them (kinematics::tiltedAxes); the chain must be active.
    toolpath::WorkingPlane planeOfAngles(const std::array<double, 2>& deg) const;
    // Turns the rotary axes so the tool points along `axis` (a plane's Z) for PLANE ... TURN and
    // CYCLE800: the pose whose branch joint has the sign `branch` (+1, -1), or with 0 (or where
    // that branch cannot reach it) the one nearest the current angles; else the reason.
    std::optional<std::string> orientPlane(const toolpath::Vec3& axis, int branch);
    // A known programmed position as a new working plane's frame has it: the tip stays where it is.
    // Outside a plane, with the rotary axes turned and no tool-tip control, programmed positions
    // are the machine's linear axes (so after a plane's reset on a turned table, too).
    toolpath::Vec3 reframe(const toolpath::WorkingPlane& old, const toolpath::WorkingPlane& next,
                           const toolpath::Vec3& programmed) const;
    // The tool axis of the current angles (complete) in the workpiece frame.
    toolpath::Vec3 toolAxis() const;
    // A move the trace does not show (the tip unknown): the next move starts from this pose.
    void moveUntraced() { m_lastSentTurned = m_angles.turned(); }

    // The tool in the workpiece frame at `programmed` with the current angles (complete).
    kinematics::ToolPose toolPose(const toolpath::Vec3& programmed) const;
    // The programmed position that puts the tip at `tip` with the current angles (complete).
    toolpath::Vec3 programmedFor(const toolpath::Vec3& tip) const;
    // The record of a straight move to `programmed`; feed 0: rapid. Remembers the pose as sent.
    toolpath::ToolAxisMove move(const toolpath::Vec3& programmed, double feedMmPerMin);
    // An arc in programmed coordinates as the tip moves in the workpiece frame (the linear axes
    // move on a circle while the angles stay: a rigid map of it without tool-tip control).
    toolpath::Arc arcInWorkpiece(const toolpath::Arc& programmed);
    // How far the tip at `tip` (workpiece frame) can go along unit `direction` until the first of
    // the machine's linear axes reaches the end of its travel (Heidenhain M140 MB MAX), with the
    // rotary axes standing at the current angles (one not programmed yet at 0, as the three-axis
    // trace has it) and the machine's axes where the chain puts them (its workpieceZero). Travel
    // in the machine's own coordinates: only this places it in the workpiece frame.
    struct TravelEnd {
        double distanceMm = 0;
        std::string axis;  // the linear axis that stops the move
    };
    // The travel end, or why it is not known (no axis limits the direction, the tip already past
    // the end, a head's tool length unknown).
    std::variant<TravelEnd, std::string> travelEnd(const toolpath::Vec3& tip, const toolpath::Vec3& direction) const;
    // The known angles as the record carries them.
    toolpath::RotaryAxes machineAxes() const;
    // A tool axis asked for directly (SINUMERIK A3= B3= C3=, spatial angles): the angles the
    // machine takes for it, nearest the current ones; else the reason (out of the limits).
    std::optional<std::string> orient(const toolpath::Vec3& tip, const toolpath::Vec3& axis);

private:
    kinematics::MachinePose pose(const toolpath::Vec3& linear) const;
    kinematics::PoseSolver& solver() const;

    const kinematics::Machine* m_machine = nullptr;
    const kinematics::KinematicChain* m_chain = nullptr;  // five-axis, or nullptr
    JointAngles m_angles;
    bool m_tcpm = false;
    bool m_shortestPath = false;
    bool m_lastSentTurned = false;
    bool m_inPlane = false;
    std::optional<double> m_toolLength;
    mutable std::unique_ptr<kinematics::PoseSolver> m_solver;
    mutable double m_solverToolLength = 0;
};

// The tool axis of spatial angles A, B, C in degrees (Heidenhain PLANE SPATIAL and FUNCTION TCPM
// AXIS SPAT): the machine frame turned about X by A, then about Y by B, then about Z by C.
toolpath::Vec3 spatialToolAxis(double aDeg, double bDeg, double cDeg);

}  // namespace camwb::nc
