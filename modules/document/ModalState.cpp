#include "document/ModalState.h"

#include "base/NumberFormat.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/RecordNames.h"
#include "toolpath/Toolpath.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

namespace camwb::document {

namespace {

template <class... Ts> struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

const char* cycleName(toolpath::CycleKind kind)
{
    switch (kind) {
    case toolpath::CycleKind::Drill:
        return "drill";
    case toolpath::CycleKind::DrillDwell:
        return "drill with dwell";
    case toolpath::CycleKind::Peck:
        return "peck drill";
    case toolpath::CycleKind::ChipBreak:
        return "chip-break drill";
    case toolpath::CycleKind::Tap:
        return "tap";
    case toolpath::CycleKind::Bore:
        return "bore";
    }
    return "cycle";
}

// A straight move sets only the axes it gives; without a position before it, one that gives only
// some axes leaves the position unknown (the interpreters give all three).
void moveStraight(ModalState& state, const base::Vec3& to, toolpath::AxisMask axes)
{
    toolpath::KnownPosition position =
        state.hasPosition ? toolpath::KnownPosition(state.position) : toolpath::KnownPosition();
    position.moveTo(to, axes);
    if (const std::optional<base::Vec3> point = position.point()) {
        state.position = *point;
        state.hasPosition = true;
    }
}

bool leavesPlane(const ModalState& before, const toolpath::Arc& arc)
{
    if (!before.hasPosition)
        return false;
    const base::Vec3 n = arc.normal;
    const double length = n.length();
    if (length < 1e-12)
        return false;
    return std::abs(n.dot(arc.to - before.position)) / length > 1e-6;
}

// A 3-axis move: the tool along +Z (the rotary axes, where known, stay as they were).
void threeAxis(ModalState& state)
{
    state.toolAxis = {0, 0, 1};
    state.fiveAxis = false;
}

}  // namespace

void applyRecord(ModalState& state, const toolpath::Record& record)
{
    std::visit(Overloaded{
                   [&](const toolpath::Rapid& r) {
                       moveStraight(state, r.to, r.axes);
                       threeAxis(state);
                   },
                   [&](const toolpath::Linear& l) {
                       moveStraight(state, l.to, l.axes);
                       state.feed = l.feedMmPerMin;
                       threeAxis(state);
                   },
                   [&](const toolpath::Arc& a) {
                       threeAxis(state);
                       state.position = a.to;
                       state.hasPosition = true;
                       state.feed = a.feedMmPerMin;
                       state.arcNormal = a.normal;
                       state.hasArcNormal = true;
                   },
                   [&](const toolpath::ToolAxisMove& m) {
                       state.position = m.tip;
                       state.hasPosition = true;
                       state.toolAxis = m.axis;
                       state.fiveAxis = true;
                       state.rotaryAxes = m.machine;
                       if (m.feedMmPerMin > 0)
                           state.feed = m.feedMmPerMin;
                   },
                   [&](const toolpath::Cycle& c) {
                       if (!c.holes.empty()) {
                           const base::Vec3& last = c.holes.back();
                           state.position = {last.x, last.y, toolpath::cycleReturnZ(c)};
                           state.hasPosition = true;
                       }
                       state.feed = c.feedMmPerMin;
                   },
                   [&](const toolpath::ToolChange& t) { state.tool = t.tool.number; },
                   [&](const toolpath::Spindle& s) {
                       state.spindleRpm = s.rpm;
                       state.spindleClockwise = s.clockwise;
                       state.surfaceSpeedMPerMin = s.surfaceSpeedMPerMin;
                   },
                   [&](const toolpath::Coolant& c) { state.coolant = c.mode; },
                   [&](const toolpath::FeedModeChange& f) { state.feedMode = f.mode; },
                   [&](const toolpath::WorkOffset& w) { state.workOffset = w.index; },
                   [&](const toolpath::CutterComp& c) { state.compensation = c.side; },
                   // Until the moves give every axis again (the interpreters' moves give all the known ones).
                   [&](const toolpath::UnknownAxes&) { state.hasPosition = false; },
                   [](const auto&) {},
               },
               record);
}

std::string describeRecord(const toolpath::Record& record)
{
    char buffer[96];
    return std::visit(
        Overloaded{
            [](const toolpath::Rapid&) -> std::string { return "rapid"; },
            [](const toolpath::Linear&) -> std::string { return "linear"; },
            [](const toolpath::Arc& a) -> std::string { return a.clockwise ? "arc CW" : "arc CCW"; },
            [](const toolpath::ToolAxisMove& m) -> std::string {
                return m.feedMmPerMin > 0 ? "5-axis linear" : "5-axis rapid";
            },
            [&](const toolpath::Cycle& c) -> std::string {
                std::snprintf(buffer, sizeof buffer, "cycle %s (%zu hole%s)", cycleName(c.kind), c.holes.size(),
                              c.holes.size() == 1 ? "" : "s");
                return buffer;
            },
            [&](const toolpath::ToolChange& t) -> std::string {
                return "tool change T" + std::to_string(t.tool.number);
            },
            [](const toolpath::Spindle& s) -> std::string { return s.rpm > 0 ? "spindle on" : "spindle stop"; },
            [](const toolpath::Coolant&) -> std::string { return "coolant"; },
            [](const toolpath::FeedModeChange&) -> std::string { return "feed mode"; },
            [](const toolpath::WorkOffset&) -> std::string { return "work offset"; },
            [](const toolpath::Dwell& w) -> std::string { return "dwell " + base::formatGeneral(w.seconds, 3) + " s"; },
            [](const toolpath::CutterComp&) -> std::string { return "compensation"; },
            [](const toolpath::Comment&) -> std::string { return "comment"; },
            [](const toolpath::ProgramStop& p) -> std::string { return p.optional ? "optional stop" : "program stop"; },
            [](const toolpath::WorkingPlane& p) -> std::string {
                return p.tilted() ? "working plane tilted" : "working plane reset";
            },
            [](const toolpath::UnknownAxes& u) -> std::string {
                return "not traced: " + toolpath::axisNames(u.axes, 'X') + " unknown";
            },
            [](const auto&) -> std::string { return {}; },
        },
        record);
}

std::string planeOfNormal(const base::Vec3& normal)
{
    const double length = normal.length();
    if (length > 1e-12) {
        const base::Vec3 n = normal * (1.0 / length);
        if (std::abs(std::abs(n.z) - 1.0) < 1e-9)
            return "G17 (XY)";
        if (std::abs(std::abs(n.y) - 1.0) < 1e-9)
            return "G18 (ZX)";
        if (std::abs(std::abs(n.x) - 1.0) < 1e-9)
            return "G19 (YZ)";
    }
    return "normal (" + base::formatFixed(normal.x, 3) + ", " + base::formatFixed(normal.y, 3) + ", " +
           base::formatFixed(normal.z, 3) + ")";
}

ModalStateTable::ModalStateTable(const toolpath::Toolpath& program, std::size_t stride) :
    m_stride(stride > 0 ? stride : 1024)
{
    ModalState state;
    m_checkpoints.reserve(program.size() / m_stride + 1);
    for (std::size_t i = 0; i < program.size(); ++i) {
        if (i % m_stride == 0)
            m_checkpoints.push_back(state);
        applyRecord(state, program.record(i));
    }
}

ModalState ModalStateTable::before(const toolpath::Toolpath& program, std::size_t index) const
{
    index = std::min(index, program.size());
    if (m_checkpoints.empty())
        return {};
    const std::size_t checkpoint = std::min(index / m_stride, m_checkpoints.size() - 1);
    ModalState state = m_checkpoints[checkpoint];
    for (std::size_t i = checkpoint * m_stride; i < index; ++i)
        applyRecord(state, program.record(i));
    return state;
}

std::string describeMove(const ModalState& before, const toolpath::Record& record)
{
    if (const auto* arc = std::get_if<toolpath::Arc>(&record); arc != nullptr && leavesPlane(before, *arc))
        return arc->clockwise ? "helix CW" : "helix CCW";
    return describeRecord(record);
}

}  // namespace camwb::document
