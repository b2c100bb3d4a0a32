#include "LinuxCncModel.h"

#include "base/NumberFormat.h"
#include "toolpath/KnownPosition.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <utility>

namespace camwb::external {

using namespace toolpath;

namespace {

// G73/G83 back off 0.010 inch between pecks; LinuxCNC computes it as 0.010 * 25.4 under G21.
const double kPeckBackOffMm = 0.010 * 25.4;

class Model {
public:
    explicit Model(bool fromPost) : m_fromPost(fromPost) {}
    Toolpath take();
    void add(const Record& record);

private:
    void rapid(const Vec3& to);
    void clRapid(const Rapid& r);
    void feedTo(const Vec3& to, double feed);
    Vec3 endOf(const Vec3& to, AxisMask axes) const;
    void spindle(double rpm, bool clockwise);
    void coolant(CoolantMode mode);
    void toolChange(const ToolChange& change);
    void arc(const Arc& arc);
    void cycle(const Cycle& cycle);
    void holeMoves(const Cycle& cycle, double x, double y, double clearZ);

    Toolpath m_out;
    Vec3 m_position;  // rs274 starts at the origin
    Spindle m_spindle{0, true};
    CoolantMode m_coolant = CoolantMode::Off;
    FeedMode m_feedMode = FeedMode::PerMinute;
    int m_workOffset = 1;
    bool m_fromPost = true;
    bool m_afterToolChange = false;
};

void Model::rapid(const Vec3& to)
{
    m_out.add(Rapid{to});
    m_position = to;
}

// A CL move that gives only some axes leaves the others where they are (G0 Z20 moves Z alone).
Vec3 Model::endOf(const Vec3& to, AxisMask axes) const
{
    KnownPosition at(m_position);
    at.moveTo(to, axes);
    return at.value();
}

// The post's first rapid after a tool change goes over in X/Y at the height the change left, then
// moves Z (unless the CL gives only one of them): two traverses in LinuxCNC. A traverse in X/Y
// alone right after a tool change leaves Z to the machine: G43 has just changed what the height
// the change left is in program coordinates, which the CL does not know, so it gives X/Y only.
void Model::clRapid(const Rapid& r)
{
    const Vec3 to = endOf(r.to, r.axes);
    const bool first = std::exchange(m_afterToolChange, false);
    const bool split = m_fromPost && r.axes.has(2) && (r.axes.has(0) || r.axes.has(1));
    const bool onlyXY = to.z == m_position.z && (!m_fromPost || to.x != m_position.x || to.y != m_position.y);
    if (first && (split || onlyXY)) {
        m_out.add(Rapid{{to.x, to.y, 0}, AxisMask{AxisMask::kX | AxisMask::kY}});
        m_position.x = to.x;
        m_position.y = to.y;
        if (!split)
            return;
    }
    rapid(to);
}

void Model::feedTo(const Vec3& to, double feed)
{
    if (m_feedMode == FeedMode::InverseTime)
        feed *= distance(m_position, to);  // LinuxCNC: the move takes 1/F minutes
    m_out.add(Linear{to, feed});
    m_position = to;
}

void Model::spindle(double rpm, bool clockwise)
{
    if (rpm <= 0) {
        if (m_spindle.rpm > 0)
            m_out.add(Spindle{0, true});
        m_spindle = {0, true};
        return;
    }
    if (rpm != m_spindle.rpm || clockwise != m_spindle.clockwise)
        m_out.add(Spindle{rpm, clockwise});
    m_spindle = {rpm, clockwise};
}

void Model::coolant(CoolantMode mode)
{
    if (mode == CoolantMode::ThroughTool || mode == m_coolant)
        return;  // through-tool coolant has no LinuxCNC code: the post warns and writes nothing
    if (mode != CoolantMode::Off && m_coolant != CoolantMode::Off)
        m_out.add(Coolant{CoolantMode::Off});  // M7 and M8 add up: M9 comes first
    m_out.add(Coolant{mode});
    m_coolant = mode;
}

// M6 stops the spindle; the post starts it again as the CL still has it turning.
void Model::toolChange(const ToolChange& change)
{
    const Spindle running = m_spindle;
    spindle(0, true);
    m_out.add(ToolChange{Tool{change.tool.number}});
    spindle(running.rpm, running.clockwise);
    m_afterToolChange = true;
}

void Model::arc(const Arc& cl)
{
    Arc arc = canonicalArc(cl);
    if (m_feedMode == FeedMode::InverseTime)
        arc.feedMmPerMin *= arcLengthMm(m_position, arc);
    m_out.add(arc);
    m_position = arc.to;
}

// The moves at one hole after the XY positioning (G-code reference, G73..G89; LinuxCNC 2.9's G83
// and G85 retract to R between pecks and before the rapid out).
void Model::holeMoves(const Cycle& c, double x, double y, double clearZ)
{
    const double r = written(c.retractZ);
    const double bottom = written(c.bottomZ);
    const double dwell = written(c.dwellSeconds > 0 ? c.dwellSeconds : 0);
    const double feed = c.feedMmPerMin;
    auto at = [&](double z) { return Vec3{x, y, z}; };
    switch (c.kind) {
    case CycleKind::Drill:
    case CycleKind::DrillDwell:
        feedTo(at(bottom), feed);
        if (c.kind == CycleKind::DrillDwell || dwell > 0)
            m_out.add(Dwell{dwell});
        rapid(at(clearZ));
        break;
    case CycleKind::ChipBreak:
    case CycleKind::Peck: {
        const double peck = written(c.peckMm);
        for (double depth = r - peck; depth > bottom; depth -= peck) {
            feedTo(at(depth), feed);
            if (c.kind == CycleKind::Peck)
                rapid(at(r));
            rapid(at(depth + kPeckBackOffMm));
        }
        feedTo(at(bottom), feed);
        rapid(at(clearZ));
        break;
    }
    case CycleKind::Tap: {
        const double rpm = m_spindle.rpm;
        feedTo(at(bottom), feed);
        spindle(0, true);
        spindle(rpm, false);
        m_out.add(Dwell{dwell});
        feedTo(at(clearZ), feed);
        spindle(0, true);
        spindle(rpm, true);
        break;
    }
    case CycleKind::Bore:
        feedTo(at(bottom), feed);
        if (dwell > 0) {  // G89
            m_out.add(Dwell{dwell});
            feedTo(at(clearZ), feed);
        } else {  // G85
            feedTo(at(r), feed);
            rapid(at(clearZ));
        }
        break;
    }
}

void Model::cycle(const Cycle& c)
{
    if (c.holes.empty())
        return;
    const double clearance = written(c.clearanceZ);
    const double r = written(c.retractZ);
    // G98 returns to the Z held before the cycle: the post stands at the clearance plane first.
    if (c.returnToClearance && written(m_position.z) != clearance)
        rapid({m_position.x, m_position.y, clearance});
    // Preliminary motion: up to R when below it; clear Z is the start Z (G98, if above R) or R (G99).
    if (written(m_position.z) < r)
        rapid({m_position.x, m_position.y, r});
    const double clearZ = c.returnToClearance ? std::max(clearance, r) : r;
    for (const Vec3& hole : c.holes) {
        const double x = written(hole.x), y = written(hole.y);
        rapid({x, y, m_position.z});
        if (written(m_position.z) != r)
            rapid({x, y, r});
        holeMoves(c, x, y, clearZ);
    }
}

void Model::add(const Record& record)
{
    std::visit(
        [this](const auto& r) {
            using T = std::decay_t<decltype(r)>;
            if constexpr (std::is_same_v<T, Rapid>) {
                clRapid(r);
            } else if constexpr (std::is_same_v<T, Linear>) {
                m_afterToolChange = false;
                feedTo(endOf(r.to, r.axes), r.feedMmPerMin);
            } else if constexpr (std::is_same_v<T, Arc>) {
                m_afterToolChange = false;
                arc(r);
            } else if constexpr (std::is_same_v<T, ToolChange>) {
                toolChange(r);
            } else if constexpr (std::is_same_v<T, Spindle>) {
                spindle(r.rpm, r.clockwise);
            } else if constexpr (std::is_same_v<T, Coolant>) {
                coolant(r.mode);
            } else if constexpr (std::is_same_v<T, FeedModeChange>) {
                if (r.mode != m_feedMode)
                    m_out.add(r);
                m_feedMode = r.mode;
            } else if constexpr (std::is_same_v<T, WorkOffset>) {
                if (r.index != m_workOffset)
                    m_out.add(r);
                m_workOffset = r.index;
            } else if constexpr (std::is_same_v<T, Dwell> || std::is_same_v<T, ProgramStop>) {
                m_out.add(r);
            } else if constexpr (std::is_same_v<T, Cycle>) {
                m_afterToolChange = false;
                cycle(r);
            }
            // Comments, sections, cutter compensation (tested with radius 0) and pass-through text
            // leave no trace in the motion; five-axis moves never reach this three-axis post.
        },
        record);
}

// M5 M9 at the end, then M2 resets the work offset to G54.
Toolpath Model::take()
{
    spindle(0, true);
    coolant(CoolantMode::Off);
    if (m_workOffset != 1)
        m_out.add(WorkOffset{1});
    return std::move(m_out);
}

}  // namespace

double written(double value) { return std::strtod(base::formatFixed(value, 3).c_str(), nullptr); }

Toolpath expectedMotion(const Toolpath& cl, bool fromPost)
{
    Model model(fromPost);
    for (const Record& record : cl.records())
        model.add(record);
    return model.take();
}

Arc canonicalArc(const Arc& arc)
{
    Arc result = arc;
    const Vec3& n = arc.normal;
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    const double along = az >= ax && az >= ay ? n.z : ay >= ax ? n.y : n.x;
    if (along < 0) {
        result.normal = n * -1.0;
        result.clockwise = !arc.clockwise;
    }
    return result;
}

double arcSweepDeg(const Vec3& start, const Arc& cl)
{
    const Arc arc = canonicalArc(cl);
    const Vec3 n = arc.normal * (1.0 / arc.normal.length());
    const Vec3 s = start - arc.center, e = arc.to - arc.center;
    const Vec3 u = s - n * s.dot(n), v = e - n * e.dot(n);
    double sweep = 2 * std::numbers::pi;
    if ((u - v).length() > 1e-9) {
        const double ccw = std::atan2(n.dot(u.cross(v)), u.dot(v));
        sweep = arc.clockwise ? -ccw : ccw;
        if (sweep <= 0)
            sweep += 2 * std::numbers::pi;
    }
    return (sweep + 2 * std::numbers::pi * std::max(0, arc.turns)) * 180 / std::numbers::pi;
}

double arcLengthMm(const Vec3& start, const Arc& cl)
{
    const Arc arc = canonicalArc(cl);
    const Vec3 n = arc.normal * (1.0 / arc.normal.length());
    const Vec3 s = start - arc.center;
    const double radius = (s - n * s.dot(n)).length();
    const double axial = (arc.to - start).dot(n);
    return std::hypot(radius * arcSweepDeg(start, arc) * std::numbers::pi / 180, axial);
}

}  // namespace camwb::external
