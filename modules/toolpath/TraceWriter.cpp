#include "toolpath/TraceWriter.h"

#include "base/NumberFormat.h"
#include "toolpath/RecordNames.h"
#include "toolpath/Toolpath.h"

namespace camwb::toolpath {

namespace {

std::string num(double v) { return base::formatFixed(v, 4); }
std::string point(const Vec3& p) { return num(p.x) + ' ' + num(p.y) + ' ' + num(p.z); }
// Unit vectors (tool axes, plane axes) to 9 decimals: at 4, a 100 mm reach would move by up to
// 0.01 mm and the axis by 1e-4 rad, beyond what five-axis output keeps.
std::string unitVector(const Vec3& v)
{
    return base::formatFixed(v.x, 9) + ' ' + base::formatFixed(v.y, 9) + ' ' + base::formatFixed(v.z, 9);
}

// The target of a straight move: three numbers when it gives every axis, else only the axes it
// gives, each named ("z 20.0000"): the trace never shows a coordinate the move did not give.
std::string target(const Vec3& p, AxisMask axes)
{
    if (axes.all())
        return point(p);
    std::string out;
    const double values[3] = {p.x, p.y, p.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (axes.has(axis))
            out += (out.empty() ? "" : " ") + std::string(1, static_cast<char>('x' + axis)) + ' ' + num(values[axis]);
    }
    return out;
}

// A text in quotes, with '"' and '\\' escaped, so that any name or comment reads back unchanged.
std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    return out + '"';
}

// " plunge" after a move's feed when it has a kind; nothing when unspecified, so that traces
// written before kinds existed read and write unchanged.
std::string kindSuffix(FeedKind kind)
{
    return kind == FeedKind::Unspecified ? std::string() : ' ' + std::string(name(kind));
}

}  // namespace

void TraceWriter::rapid(const Rapid& r) { m_out += "rapid " + target(r.to, r.axes) + '\n'; }

void TraceWriter::linear(const Linear& r)
{
    m_out += "linear " + target(r.to, r.axes) + " f " + num(r.feedMmPerMin) + kindSuffix(r.feedKind) + '\n';
}

void TraceWriter::arc(const Arc& r)
{
    m_out += std::string("arc ") + (r.clockwise ? "cw " : "ccw ") + point(r.to) + " c " + point(r.center) + " n " +
             point(r.normal) + " turns " + std::to_string(r.turns) + " f " + num(r.feedMmPerMin) +
             kindSuffix(r.feedKind) + '\n';
}

void TraceWriter::toolChange(const ToolChange& r)
{
    const Tool& t = r.tool;
    m_out += "tool " + std::to_string(t.number) + " " + t.kind + " d " + num(t.diameterMm) + " r " +
             num(t.cornerRadiusMm) + " flute " + num(t.fluteLengthMm) + " len " + num(t.lengthMm) + " " +
             quoted(t.name) + (t.flutes != Tool{}.flutes ? " flutes " + std::to_string(t.flutes) : "") +
             (t.pointAngleDeg > 0 ? " angle " + num(t.pointAngleDeg) : "") +
             (t.holder.empty() ? "" : " holder " + quoted(t.holder)) + "\n";
}

void TraceWriter::spindle(const Spindle& r)
{
    m_out += "spindle " + num(r.rpm) + (r.clockwise ? " cw" : " ccw");
    if (r.surfaceSpeedMPerMin > 0)
        m_out += " css " + num(r.surfaceSpeedMPerMin);
    m_out += '\n';
}

void TraceWriter::coolant(const Coolant& r) { m_out += std::string("coolant ") + name(r.mode) + '\n'; }
void TraceWriter::feedMode(const FeedModeChange& r) { m_out += std::string("feedmode ") + name(r.mode) + '\n'; }
void TraceWriter::workOffset(const WorkOffset& r) { m_out += "workoffset " + std::to_string(r.index) + '\n'; }
void TraceWriter::dwell(const Dwell& r) { m_out += "dwell " + num(r.seconds) + '\n'; }

void TraceWriter::cycle(const Cycle& r)
{
    m_out += std::string("cycle ") + name(r.kind) + " clear " + num(r.clearanceZ) + " retract " + num(r.retractZ) +
             " top " + num(r.topZ) + " bottom " + num(r.bottomZ) + " peck " + num(r.peckMm) + " dwell " +
             num(r.dwellSeconds) + " f " + num(r.feedMmPerMin) +
             (r.returnToClearance ? " return clear" : " return retract") + " holes " + std::to_string(r.holes.size()) +
             '\n';
    for (const Vec3& hole : r.holes)
        m_out += "  hole " + point(hole) + '\n';
}

void TraceWriter::toolAxisMove(const ToolAxisMove& r)
{
    m_out += "move5 " + point(r.tip) + " axis " + unitVector(r.axis) + " f " + num(r.feedMmPerMin);
    // The machine's rotary positions where the source knows them (NC read back through a machine).
    if (r.machine.has(RotaryAxes::kA))
        m_out += " a " + num(r.machine.aDeg);
    if (r.machine.has(RotaryAxes::kB))
        m_out += " b " + num(r.machine.bDeg);
    if (r.machine.has(RotaryAxes::kC))
        m_out += " c " + num(r.machine.cDeg);
    if (r.jointInterpolated)
        m_out += " joint";
    m_out += '\n';
}

void TraceWriter::cutterComp(const CutterComp& r) { m_out += std::string("comp ") + name(r.side) + '\n'; }
void TraceWriter::comment(const Comment& r) { m_out += "comment " + quoted(r.text) + "\n"; }

void TraceWriter::sectionBegin(const SectionBegin& r)
{
    // An empty strategy is "-", so that the line keeps its fields.
    m_out += "section " + quoted(r.operationName) + " " + (r.strategy.empty() ? "-" : r.strategy) + " tool " +
             std::to_string(r.toolNumber) + " cut " + num(r.feeds.cuttingMmPerMin) + " plunge " +
             num(r.feeds.plungeMmPerMin);
    // The other feeds only when the section has them, so that older traces stay as they were.
    if (r.feeds.entryMmPerMin > 0)
        m_out += " entry " + num(r.feeds.entryMmPerMin);
    if (r.feeds.exitMmPerMin > 0)
        m_out += " exit " + num(r.feeds.exitMmPerMin);
    if (r.feeds.finishingMmPerMin > 0)
        m_out += " finish " + num(r.feeds.finishingMmPerMin);
    for (const auto& [name, value] : r.postProperties)
        m_out += " set " + name + " " + quoted(value);
    for (const auto& [name, value] : r.strategyParameters)
        m_out += " param " + name + " " + num(value);
    m_out += '\n';
}

void TraceWriter::sectionEnd(const SectionEnd&) { m_out += "endsection\n"; }
void TraceWriter::programStop(const ProgramStop& r) { m_out += r.optional ? "stop optional\n" : "stop\n"; }
void TraceWriter::passThrough(const PassThrough& r) { m_out += "passthrough " + quoted(r.text) + "\n"; }

void TraceWriter::workingPlane(const WorkingPlane& r)
{
    m_out += "plane " + point(r.origin) + " x " + unitVector(r.xAxis) + " z " + unitVector(r.zAxis) + '\n';
}

void TraceWriter::unknownAxes(const UnknownAxes& r) { m_out += "unknown " + axisNames(r.axes) + '\n'; }

std::string traceOf(const Toolpath& toolpath)
{
    std::string out;
    TraceWriter writer(out);
    play(toolpath, writer);
    return out;
}

}  // namespace camwb::toolpath
