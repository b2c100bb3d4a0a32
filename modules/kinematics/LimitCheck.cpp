#include "kinematics/LimitCheck.h"

#include "kinematics/PoseSolver.h"

#include "base/NumberFormat.h"
#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/RecordNames.h"

#include <algorithm>
#include <cmath>

namespace camwb::kinematics {

using namespace toolpath;

namespace {

std::string num(double value) { return base::NumberFormat{3, true}.format(value); }

std::string toolName(int number) { return "tool T" + std::to_string(number); }

double component(const Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

constexpr const char* kAxisNames[3] = {"X", "Y", "Z"};

}  // namespace

LimitCheck::LimitCheck(const Machine& machine, MachineSink& next) :
    ForwardingSink(next),
    m_machine(machine),
    m_name(machine.name.empty() ? machine.id : machine.name),
    m_lathe(machine.axis("X") && machine.axis("Z") && !machine.axis("Y"))
{
}

void LimitCheck::setSource(const SourceRef& source)
{
    m_source = source;
    ForwardingSink::setSource(source);
}

void LimitCheck::nextRecord() { ++m_records; }

void LimitCheck::flag(const std::string& key, const std::string& message)
{
    const auto [it, inserted] = m_findingOfKey.emplace(key, m_findings.size());
    if (inserted)
        m_findings.push_back({m_source, m_records - 1, 0, message});
    ++m_findings[it->second].count;
}

void LimitCheck::reachMachine(const Vec3& p, AxisMask axes)
{
    for (int axis = 0; axis < 3; ++axis) {
        if (!axes.has(axis))  // a move that does not give this axis did not move it
            continue;
        // A machine with X and Z but no Y is a lathe: its tool works where Y is 0 (an arc in
        // G18 gives Y = 0 too), and a move elsewhere is one it cannot make. (Another axis a file
        // leaves out is not checked.)
        if (axis == 1 && m_lathe && std::abs(p.y) > 1e-9)
            flag("lathe Y",
                 "a move goes to Y" + num(p.y) + " but the " + m_name + " turns in X and Z only (a lathe, no Y axis)");
        const double v = component(p, axis);
        const bool first = !m_reached.has(axis);
        if (first || v < m_low[axis].value)
            m_low[axis] = {v, m_source, m_records - 1};
        if (first || v > m_high[axis].value)
            m_high[axis] = {v, m_source, m_records - 1};
    }
    m_reached.bits |= axes.bits;
}

void LimitCheck::cutting(double feed)
{
    if (m_noTool)
        flag("no tool", "a cutting move with no tool in the spindle (after T0)");
    if (!m_perMinute)  // per revolution or inverse time: the feed in mm/min is not known here
        return;
    if (m_machine.maxCuttingFeedMmPerMin > 0 && feed > m_machine.maxCuttingFeedMmPerMin)
        flag("feed", "feed " + num(feed) + " mm/min is above the " + m_name + "'s maximum cutting feed of " +
                         num(m_machine.maxCuttingFeedMmPerMin) + " mm/min");
    // A feed of 0 is no feed at all, which the interpreters and the post kernel report themselves.
    if (feed > 0 && feed < m_machine.minCuttingFeedMmPerMin)
        flag("feed min", "feed " + num(feed) + " mm/min is below the " + m_name + "'s minimum cutting feed of " +
                             num(m_machine.minCuttingFeedMmPerMin) + " mm/min");
}

void LimitCheck::rapid(const Rapid& r)
{
    nextRecord();
    reach(r.to, r.axes);
    m_position.moveTo(r);
    ForwardingSink::rapid(r);
}

void LimitCheck::linear(const Linear& r)
{
    nextRecord();
    reach(r.to, r.axes);
    m_position.moveTo(r);
    cutting(r.feedMmPerMin);
    ForwardingSink::linear(r);
}

void LimitCheck::arc(const Arc& r)
{
    nextRecord();
    if (const std::optional<Vec3> start = m_position.point()) {
        Vec3 min = *start, max = *start;
        extendByArc(min, max, *start, r);
        if (m_plane.tilted()) {  // the box's corners: the arc lies within them in any frame
            for (const Vec3& corner : base::boxCorners(min, max))
                reach(corner);
        } else {
            reach(min);
            reach(max);
        }
    }
    reach(r.to);
    m_position.set(r.to);
    cutting(r.feedMmPerMin);
    ForwardingSink::arc(r);
}

// A rotary position a move gives (NC read back, a post's solved pose) against the machine's axis.
void LimitCheck::rotary(const RotaryAxes& machine)
{
    const std::pair<unsigned char, const char*> axes[] = {
        {RotaryAxes::kA, "A"}, {RotaryAxes::kB, "B"}, {RotaryAxes::kC, "C"}};
    const double values[] = {machine.aDeg, machine.bDeg, machine.cDeg};
    for (int i = 0; i < 3; ++i) {
        if (!machine.has(axes[i].first))
            continue;
        const std::string name = axes[i].second;
        const Axis* axis = m_machine.axis(name);
        if (axis == nullptr || !axis->rotary)
            flag("rotary axis " + name, "a move turns " + name + " but the " + m_name + " has no rotary axis " + name);
        else if (values[i] < axis->min - 1e-9 || values[i] > axis->max + 1e-9)
            flag("rotary range " + name, name + num(values[i]) + " is outside the " + m_name + "'s " + name +
                                             " range " + num(axis->min) + " .. " + num(axis->max) + " degrees");
    }
}

// Where the machine's linear axes are for a five-axis move: through the chain when the move gives
// both of its rotary angles, else the tip (a machine without a chain moves the tip as it is).
Vec3 LimitCheck::linearAxes(const ToolAxisMove& r) const
{
    const KinematicChain& chain = m_machine.kinematics;
    if (!chain.fiveAxis())
        return r.tip;
    std::array<double, 2> deg{};
    for (int j = 0; j < 2; ++j) {
        const std::optional<double> angle = r.machine.of(chain.joints[j].axis);
        if (!angle)
            return r.tip;
        deg[j] = *angle;
    }
    return linearAxesFor(chain, r.tip, deg);
}

void LimitCheck::toolAxisMove(const ToolAxisMove& r)
{
    nextRecord();
    rotary(r.machine);
    reachMachine(linearAxes(r));
    m_position.set(r.tip);
    if (r.feedMmPerMin > 0)
        cutting(r.feedMmPerMin);
    ForwardingSink::toolAxisMove(r);
}

void LimitCheck::cycle(const Cycle& r)
{
    nextRecord();
    for (const Vec3& hole : r.holes) {
        reach({hole.x, hole.y, r.bottomZ});
        reach({hole.x, hole.y, std::max(cycleReturnZ(r), r.retractZ)});
    }
    if (!r.holes.empty()) {
        m_position.set({r.holes.back().x, r.holes.back().y, cycleReturnZ(r)});
        cutting(r.feedMmPerMin);
    }
    ForwardingSink::cycle(r);
}

void LimitCheck::feedMode(const FeedModeChange& r)
{
    nextRecord();
    m_perMinute = r.mode == FeedMode::PerMinute;
    ForwardingSink::feedMode(r);
}

void LimitCheck::toolChange(const ToolChange& r)
{
    nextRecord();
    const Tool& tool = r.tool;
    m_noTool = tool.number == 0;
    if (m_machine.toolStations > 0 && (tool.number < 0 || tool.number > m_machine.toolStations))
        flag("tool station " + std::to_string(tool.number), toolName(tool.number) + " has no station: the " + m_name +
                                                                " has stations 1.." +
                                                                std::to_string(m_machine.toolStations));
    if (m_machine.maxToolDiameterMm > 0 && tool.diameterMm > m_machine.maxToolDiameterMm)
        flag("tool diameter " + std::to_string(tool.number), toolName(tool.number) + " is " + num(tool.diameterMm) +
                                                                 " mm in diameter; the " + m_name + " takes at most " +
                                                                 num(m_machine.maxToolDiameterMm) + " mm");
    if (m_machine.maxToolLengthMm > 0 && tool.lengthMm > m_machine.maxToolLengthMm)
        flag("tool length " + std::to_string(tool.number), toolName(tool.number) + " is " + num(tool.lengthMm) +
                                                               " mm long; the " + m_name + " takes at most " +
                                                               num(m_machine.maxToolLengthMm) + " mm");
    ForwardingSink::toolChange(r);
}

void LimitCheck::spindle(const Spindle& r)
{
    nextRecord();
    if (r.rpm > 0 && m_machine.spindleMaxRpm > 0 && r.rpm > m_machine.spindleMaxRpm)
        flag("spindle max", "spindle speed " + num(r.rpm) + " rpm is above the " + m_name + "'s maximum of " +
                                num(m_machine.spindleMaxRpm) + " rpm");
    if (r.rpm > 0 && r.rpm < m_machine.spindleMinRpm)
        flag("spindle min", "spindle speed " + num(r.rpm) + " rpm is below the " + m_name + "'s minimum of " +
                                num(m_machine.spindleMinRpm) + " rpm");
    ForwardingSink::spindle(r);
}

void LimitCheck::coolant(const Coolant& r)
{
    nextRecord();
    if (r.mode != CoolantMode::Off && !m_machine.hasCoolant(toolpath::name(r.mode)))
        flag(std::string("coolant ") + toolpath::name(r.mode),
             std::string("coolant ") + toolpath::name(r.mode) + " is not available on the " + m_name);
    ForwardingSink::coolant(r);
}

void LimitCheck::workOffset(const WorkOffset& r)
{
    nextRecord();
    ForwardingSink::workOffset(r);
}

void LimitCheck::dwell(const Dwell& r)
{
    nextRecord();
    ForwardingSink::dwell(r);
}

void LimitCheck::cutterComp(const CutterComp& r)
{
    nextRecord();
    ForwardingSink::cutterComp(r);
}

void LimitCheck::comment(const Comment& r)
{
    nextRecord();
    ForwardingSink::comment(r);
}

void LimitCheck::sectionBegin(const SectionBegin& r)
{
    nextRecord();
    ForwardingSink::sectionBegin(r);
}

void LimitCheck::sectionEnd(const SectionEnd& r)
{
    nextRecord();
    ForwardingSink::sectionEnd(r);
}

void LimitCheck::programStop(const ProgramStop& r)
{
    nextRecord();
    ForwardingSink::programStop(r);
}

void LimitCheck::passThrough(const PassThrough& r)
{
    nextRecord();
    ForwardingSink::passThrough(r);
}

// Where the tool went is not known, so it reaches nothing; an arc from there counts by its end.
void LimitCheck::unknownAxes(const UnknownAxes& r)
{
    nextRecord();
    m_position.forget(r.axes);
    ForwardingSink::unknownAxes(r);
}

// A point in the current working plane's frame: in the machine's linear axes through the pose
// that tilts the tool along the plane's axis (the machine's preferred one: a post may take the
// other branch, whose spans differ), the workpiece frame where that is not known. A move that
// gives only some axes of a tilted frame says nothing certain about the machine's.
void LimitCheck::reach(const Vec3& p, AxisMask axes)
{
    if (!m_plane.tilted()) {
        reachMachine(p, axes);
        return;
    }
    if (!axes.all())
        return;
    const Vec3 w = m_plane.toWorkpiece(p);
    reachMachine(m_planePose ? linearAxesFor(m_machine.kinematics, w, m_planePose->rotaryDeg) : w);
}

void LimitCheck::workingPlane(const WorkingPlane& r)
{
    nextRecord();
    m_plane = r;
    m_planePose.reset();
    if (r.tilted()) {
        if (!m_machine.kinematics.fiveAxis()) {
            flag("plane without chain", "a tilted working plane (3+2), but the " + m_name +
                                            " has no five-axis chain in its machine file to tilt the tool");
        } else if (auto pose = PoseSolver(m_machine).solve({r.origin, r.zAxis}, nullptr); pose.ok()) {
            m_planePose = pose->pose;
        } else {
            flag("plane unreachable", "working plane with tool axis (" + num(r.zAxis.x) + ", " + num(r.zAxis.y) + ", " +
                                          num(r.zAxis.z) + "): " + pose.error().message);
        }
    }
    ForwardingSink::workingPlane(r);
}

std::vector<LimitCheck::Finding> LimitCheck::spanFindings() const
{
    std::vector<Finding> out;
    for (int axis = 0; axis < 3; ++axis) {
        const Axis* travel = m_machine.axis(kAxisNames[axis]);
        if (!m_reached.has(axis) || !travel || travel->rotary || travel->endless || travel->max <= travel->min)
            continue;
        const Reach& low = m_low[axis];
        const Reach& high = m_high[axis];
        const double span = high.value - low.value;
        if (span <= travel->max - travel->min + 1e-6)
            continue;
        // Blame the record that made the span too long: the later of the two extremes.
        const Reach& at = high.record > low.record ? high : low;
        out.push_back({at.source, at.record, 1,
                       std::string("the program spans ") + num(span) + " mm in " + kAxisNames[axis] + " (" +
                           num(low.value) + " to " + num(high.value) + "); the " + m_name + " travels " +
                           num(travel->max - travel->min) + " mm"});
    }
    return out;
}

std::vector<LimitCheck::Finding> LimitCheck::findings() const
{
    std::vector<Finding> out = m_findings;
    for (Finding& span : spanFindings())
        out.push_back(std::move(span));
    return out;
}

std::vector<base::Diagnostic> LimitCheck::ncDiagnostics(const std::vector<std::string>& files) const
{
    std::vector<base::Diagnostic> out;
    for (const Finding& f : findings()) {
        const bool known = f.source.file >= 0 && f.source.file < static_cast<int>(files.size());
        std::string message = f.message;
        if (f.count > 1)
            message += " (" + std::to_string(f.count) + " times in all)";
        out.push_back(base::warningDiagnostic(std::move(message), known ? files[f.source.file] : std::string(),
                                              std::max(f.source.line, 0)));
    }
    return out;
}

std::vector<base::Diagnostic> LimitCheck::clDiagnostics() const
{
    std::vector<base::Diagnostic> out;
    for (const Finding& f : findings()) {
        std::string message = f.message + " (CL record " + std::to_string(f.record);
        if (f.count > 1)
            message += "; " + std::to_string(f.count) + " records in all";
        out.push_back(base::warningDiagnostic(message + ")"));
    }
    return out;
}

}  // namespace camwb::kinematics
