#include "gui/sim/MachineFrame.h"

#include "gui/sim/SimRun.h"
#include "kinematics/Machine.h"
#include "sim/MachineAxes.h"

#include <algorithm>
#include <cmath>

namespace camwb::gui {

MachineFrameSupport machineFrameSupport(const SimRun* run)
{
    if (run == nullptr)
        return MachineFrameSupport::NoRun;
    if (!run->machineChosen || !run->machine)
        return MachineFrameSupport::NoMachine;
    if (!run->machine->kinematics.fiveAxis() || run->rotaryAtStart.size() != run->moves.moves.size())
        return MachineFrameSupport::NoChain;
    return MachineFrameSupport::Available;
}

std::array<double, 2> rotaryAt(const SimRun& run, const MovePoint& at)
{
    if (!run.machine || at.move >= run.rotaryAtStart.size())
        return run.rotaryAtStart.empty() ? std::array<double, 2>{0, 0} : run.rotaryAtStart.back();
    const sim::Move& move = run.moves.moves[at.move];
    const std::array<double, 2>& start = run.rotaryAtStart[at.move];
    if (!move.moves() || !move.positionKnown)
        return start;
    const toolpath::Tool* tool = run.moves.tool(move.tool);
    return sim::machinePoseAt(run.machine->kinematics, move, at.fraction, start, tool ? tool->lengthMm : 0).rotaryDeg;
}

kinematics::RigidMotion machineFrameAt(const SimRun& run, const MovePoint& at)
{
    if (machineFrameSupport(&run) != MachineFrameSupport::Available)
        return {};
    return kinematics::machineFrameMotion(run.machine->kinematics, rotaryAt(run, at));
}

std::optional<RotaryTable> rotaryTableOf(const SimRun& run)
{
    if (machineFrameSupport(&run) != MachineFrameSupport::Available)
        return std::nullopt;
    const kinematics::KinematicChain& chain = run.machine->kinematics;
    const kinematics::RotaryJoint* table = nullptr;  // the innermost table joint carries the workpiece
    for (const kinematics::RotaryJoint& joint : chain.joints)
        if (joint.onTable)
            table = &joint;
    if (table == nullptr)
        return std::nullopt;
    const base::Vec3 axis = table->direction.normalized();
    if (std::abs(axis.z) < 0.9)
        return std::nullopt;
    // What stands on the table: the stock, else (a program without one) where the tool went.
    base::Box3 part;
    if (run.stock)
        part = run.stock->bounds();
    else
        for (const sim::Move& move : run.moves.moves)
            if (move.moves() && move.positionKnown) {
                part.add(move.from);
                part.add(move.to);
            }
    if (part.empty)
        return std::nullopt;
    RotaryTable t;
    t.normal = axis.z > 0 ? axis : axis * -1.0;
    const base::Vec3 pivot = table->pivot - chain.workpieceZero;  // on the axis, workpiece frame
    t.centre = pivot + axis * ((part.min.z - pivot.z) / axis.z);
    const base::Vec3 x{1, 0, 0};
    t.zero = (x - t.normal * t.normal.dot(x)).normalized();
    // No machine file gives its table's size (the format has no field for it): the disc reaches
    // past the stock's footprint corners by a sixth, at least 10 mm, so the rim and its C = 0 mark
    // stay in sight beside the part; its thickness follows its size.
    double reach = 0;
    for (double cx : {part.min.x, part.max.x})
        for (double cy : {part.min.y, part.max.y}) {
            const base::Vec3 d = base::Vec3{cx, cy, t.centre.z} - t.centre;
            reach = std::max(reach, (d - t.normal * t.normal.dot(d)).length());
        }
    t.radiusMm = std::max(reach * 7.0 / 6.0, reach + 10.0);
    t.thicknessMm = std::clamp(0.12 * t.radiusMm, 5.0, 40.0);
    return t;
}

}  // namespace camwb::gui
