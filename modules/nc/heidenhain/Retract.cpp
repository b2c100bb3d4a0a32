// Moves the trace cannot place: M91/M92 positions in machine coordinates, and retracts along the
// tool axis: M140 MB, and the MB of a PLANE block before the rotary axes turn
// (iTNC 530 User's Manual, "Retraction from the contour in the tool-axis direction: M140" and the
// PLANE function's automatic positioning). MB with a distance moves that far; MB MAX moves to the
// end of the traverse range, where the first linear axis reaches its travel limit. Only a machine
// whose kinematic chain places the workpiece in its axes (kinematics.workpieceZero) tells where
// that is in the workpiece frame; without one the retract is not traced and the axes it moves
// become unknown, so that nothing is drawn from the old position.
#include "nc/heidenhain/Machine.h"

#include <variant>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

// `distance` in program units, nullopt for MB MAX; `what` names the word in messages ("M140 MB").
void Machine::retract(const Block& b, std::optional<double> distance, const std::string& what)
{
    const bool turned = m_five.active() && m_five.fiveAxisMove();
    if (distance) {
        if (turned) {
            retractAlongToolAxis(*distance * m_scale);
        } else if (needKnown(b, axisBit(2), kNoAxes, kNoAxes, (what + " (a retract from the current Z)").c_str())) {
            m_pos.z += *distance * m_scale;
            m_sink.rapid(Rapid{m_pos, m_known.mask()});
        }
        return;
    }
    std::string why;
    if (!m_five.active()) {
        if (m_options.machine)
            why = "the " + (m_options.machine->name.empty() ? m_options.machine->id : m_options.machine->name) +
                  "'s file gives no kinematic chain that places the workpiece in its travel";
    } else if (!m_known.complete()) {
        why = "the position before it is not known";
    } else if (!turned && m_five.inPlane() && !m_five.angles().complete()) {
        why = "the rotary axes have not been positioned for the tilted working plane";
    } else {
        // The tip and tool axis in the workpiece frame; in a working plane (or three-axis) the tool
        // stands along the plane's Z.
        Vec3 tip = m_plane.toWorkpiece(m_pos), axis = m_plane.zAxis;
        if (turned) {
            const kinematics::ToolPose pose = m_five.toolPose(m_pos);
            tip = pose.tip;
            axis = pose.axis.normalized();
        }
        const auto end = m_five.travelEnd(tip, axis);
        if (const auto* reached = std::get_if<FiveAxisState::TravelEnd>(&end)) {
            if (turned) {
                retractAlongToolAxis(reached->distanceMm);
            } else {
                m_pos.z += reached->distanceMm;
                m_sink.rapid(Rapid{m_pos, m_known.mask()});
            }
            return;
        }
        why = std::get<std::string>(end);
    }
    // Up the tool axis to somewhere unknown: Z (with the rotary axes turned, X Y Z) unknown until
    // given again.
    source(b);
    if (!m_known.lose(turned ? AxisMask{} : axisBit(2), m_sink).none()) {
        warnOnce(
            kWarnM140, b,
            what + " MAX: the retract to the travel limit is not traced" + (why.empty() ? "" : " (" + why + ")") +
                "; " +
                (turned ? "X, Y and Z are unknown until a block gives them" : "Z is unknown until a block gives it"));
    }
}

bool Machine::inMachineCoordinates(const BlockWords& w)
{
    for (int i = 0; i < w.mCount; ++i)
        if (w.m[static_cast<std::size_t>(i)] == 91 || w.m[static_cast<std::size_t>(i)] == 92)
            return true;
    return false;
}

// L ... M91 (from the machine datum) or M92 (from a position the machine maker sets): where those
// lie in the workpiece frame is the control's knowledge (its preset table), so the linear axes the
// block gives become unknown until a block gives them again, and rotary words leave the rotary
// axes unknown. "L Z+0 R0 FMAX M91" (the top of Z) traced as workpiece Z0 would run the next rapid
// through the part.
void Machine::moveInMachineCoordinates(const Block& b, const BlockWords& w)
{
    AxisMask axes{0};
    for (int i = 0; i < 3; ++i)
        if (w.axes[static_cast<std::size_t>(i)] || w.axes[static_cast<std::size_t>(i + 9)])  // X or IX, ...
            axes.bits |= axisBit(i).bits;
    const bool turned = m_five.active() && m_five.fiveAxisMove();
    if (turned && !axes.none())
        axes = AxisMask{};  // a machine axis then moves the tip along a turned direction
    if (w.rotary)
        m_five.setAngles(JointAngles{});
    warnOnce(kWarnM91, b,
             "M91/M92: a move in machine coordinates is not traced (the datums are the control's); the axes it "
             "gives are unknown until a block gives them");
    source(b);
    m_known.lose(axes, m_sink);
}

// With the rotary axes turned: back along the tool axis by `distanceMm`, the machine's axes moving
// as the chain turns that direction (a five-axis record).
void Machine::retractAlongToolAxis(double distanceMm)
{
    const kinematics::ToolPose tool = m_five.toolPose(m_pos);
    m_pos = m_five.programmedFor(tool.tip + tool.axis * distanceMm);
    m_sink.toolAxisMove(m_five.move(m_pos, 0));
}

}  // namespace camwb::nc::heidenhain
