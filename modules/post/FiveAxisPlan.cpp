#include "post/FiveAxisPlan.h"

#include "base/NumberFormat.h"
#include "toolpath/ArcGeometry.h"
#include "toolpath/CycleExpansion.h"
#include "toolpath/KnownPosition.h"
#include "toolpath/RecordNames.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace camwb::post {

using kinematics::MachinePose;
using kinematics::ToolPose;
using toolpath::AxisMask;
using toolpath::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

double angleDeg(const Vec3& a, const Vec3& b) { return a.angleTo(b) * 180.0 / kPi; }

// One tool pose of a five-axis section before the plan: where it came from and how it moves.
struct SectionPose {
    std::size_t record;
    ToolPose tool;
    double feed;
    int feedKind;
};

std::string recordError(const toolpath::Toolpath& toolpath, std::size_t record, const std::string& message)
{
    return "CL record " + std::to_string(record) + " " + toolpath::recordName(toolpath.record(record)) + ": " + message;
}

// The record ranges [begin, end) of the sections that hold a ToolAxisMove.
std::vector<std::pair<std::size_t, std::size_t>> fiveAxisRanges(const toolpath::Toolpath& toolpath)
{
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    std::size_t begin = 0;
    bool five = false;
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        const toolpath::Record& record = toolpath.record(i);
        // A section runs from its SectionBegin to its SectionEnd; what lies outside sections is
        // a region of its own (a CL without sections is one).
        const bool opens = std::holds_alternative<toolpath::SectionBegin>(record);
        const bool closes = std::holds_alternative<toolpath::SectionEnd>(record);
        if (opens) {
            if (five)
                ranges.emplace_back(begin, i);
            begin = i;
            five = false;
        }
        if (const auto* move = std::get_if<toolpath::ToolAxisMove>(&record))
            five = five || !alongZ(move->axis);
        if (closes) {
            if (five)
                ranges.emplace_back(begin, i + 1);
            begin = i + 1;
            five = false;
        }
    }
    if (five)
        ranges.emplace_back(begin, toolpath.size());
    return ranges;
}

double rotaryDistance(const MachinePose& a, const MachinePose& b)
{
    return std::abs(a.rotaryDeg[0] - b.rotaryDeg[0]) + std::abs(a.rotaryDeg[1] - b.rotaryDeg[1]);
}

// The joint whose angle the pole leaves free: the table joint nearest the workpiece, else the
// first head joint.
int poleJoint(const kinematics::KinematicChain& chain)
{
    int joint = 0;
    for (int j = 0; j < static_cast<int>(chain.joints.size()); ++j)
        if (chain.joints[j].onTable)
            joint = j;
    return joint;
}

class SectionPlanner {
public:
    SectionPlanner(const toolpath::Toolpath& toolpath, const kinematics::Machine& machine,
                   const FiveAxisOptions& options, FiveAxisPlan& plan) :
        m_toolpath(toolpath),
        m_machine(machine),
        m_options(options),
        m_plan(plan)
    {
    }

    base::Status plan(const std::vector<SectionPose>& poses, double toolLengthMm);

private:
    base::Status explainFailure(const kinematics::PoseSolver& solver, const std::vector<ToolPose>& tools,
                                const std::vector<SectionPose>& poses, const MachinePose& home,
                                const base::Error& error) const;
    void keepPoleInCone(const kinematics::PoseSolver& solver, FiveAxisStep& step, const MachinePose& previous);
    void turnOnPole(const FiveAxisStep& pole, const FiveAxisStep& next, double toolLengthMm);
    FiveAxisStep step(const SectionPose& pose, StepKind kind) const
    {
        FiveAxisStep s;
        s.record = pose.record;
        s.section = static_cast<int>(m_plan.sections.size());
        s.kind = kind;
        s.tool = pose.tool;
        s.linearAxes = AxisMask{AxisMask::kAll};
        return s;
    }
    // A rapid of a reconfiguration or section start: `tip` with `rotary`, linear axes solved.
    FiveAxisStep rapidAt(const SectionPose& pose, StepKind kind, const Vec3& tip, const Vec3& axis,
                         const std::array<double, 2>& rotary, double toolLengthMm) const
    {
        FiveAxisStep s = step(pose, kind);
        s.tool = {tip, axis};
        s.pose.rotaryDeg = rotary;
        s.pose.linear = kinematics::linearAxesFor(m_machine.kinematics, tip, rotary, toolLengthMm);
        s.reconfigure = kind != StepKind::Position;
        return s;
    }

    const toolpath::Toolpath& m_toolpath;
    const kinematics::Machine& m_machine;
    const FiveAxisOptions& m_options;
    FiveAxisPlan& m_plan;
    MachinePose m_home;  // where the rotaries stand before the next section
};

base::Status SectionPlanner::explainFailure(const kinematics::PoseSolver& solver, const std::vector<ToolPose>& tools,
                                            const std::vector<SectionPose>& poses, const MachinePose& home,
                                            const base::Error& error) const
{
    // Name the record: the first pose no solution within the limits reaches ...
    const MachinePose* previous = &home;
    std::vector<kinematics::PoseCandidate> last;
    for (std::size_t i = 0; i < tools.size(); ++i) {
        std::vector<kinematics::PoseCandidate> candidates = solver.candidates(tools[i], previous);
        if (candidates.empty()) {
            auto solved = solver.solve(tools[i], previous);
            return base::makeError(recordError(m_toolpath, poses[i].record,
                                               "no machine pose within the limits reaches tool axis (" +
                                                   base::NumberFormat{6, true}.format(tools[i].axis.x) + ", " +
                                                   base::NumberFormat{6, true}.format(tools[i].axis.y) + ", " +
                                                   base::NumberFormat{6, true}.format(tools[i].axis.z) + ")" +
                                                   (solved ? "" : ": " + solved.error().message)));
        }
        last = std::move(candidates);
        previous = &last.front().pose;
    }
    // ... or the first that needs a reconfiguration the options refuse.
    kinematics::BranchPlanOptions allow;
    allow.reconfigureStepDeg = m_options.reconfigureStepDeg;
    if (auto planned = kinematics::planBranches(solver, tools, &home, allow)) {
        for (std::size_t i = 0; i < planned.value().size(); ++i)
            if (planned.value()[i].reconfigure)
                return base::makeError(recordError(m_toolpath, poses[i].record,
                                                   "the rotary axes must be reconfigured here (a flip or rewind that "
                                                   "no branch of the operation avoids) and the post refuses to "
                                                   "retract and turn"));
    }
    return base::makeError(recordError(m_toolpath, poses.front().record, error.message));
}

void SectionPlanner::keepPoleInCone(const kinematics::PoseSolver& solver, FiveAxisStep& step,
                                    const MachinePose& previous)
{
    const Vec3 direction = m_machine.kinematics.joints[poleJoint(m_machine.kinematics)].direction.normalized();
    for (const double sign : {1.0, -1.0}) {
        const Vec3 pole = direction * sign;
        const double off = angleDeg(step.tool.axis, pole);
        if (off > m_options.poleConeDeg)
            continue;
        std::vector<kinematics::PoseCandidate> candidates = solver.candidates({step.tool.tip, pole}, &previous);
        if (candidates.empty())
            return;
        const auto nearest = std::min_element(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
            return rotaryDistance(a.pose, previous) < rotaryDistance(b.pose, previous);
        });
        step.pose = nearest->pose;
        step.pose.linear =
            kinematics::linearAxesFor(m_machine.kinematics, step.tool.tip, step.pose.rotaryDeg, solver.toolLengthMm());
        step.pole = true;
        step.axisDeviationDeg = off;
        if (off > 0 && m_plan.poleAdjusted++ == 0)
            m_plan.firstPoleAdjusted = step.record;
        m_plan.maxAxisDeviationDeg = std::max(m_plan.maxAxisDeviationDeg, off);
        return;
    }
}

// Leaving the pole, the free angle must reach the next pose's: turned there, on the spot, while
// the tool axis lies on the free joint's direction, so the turn does not tilt the tool. Turned
// during the next move, it would swing the tool axis off the CL's (a B that may only be negative
// goes through the pole with C half a turn on: the axis would spiral, degrees off the CL).
void SectionPlanner::turnOnPole(const FiveAxisStep& pole, const FiveAxisStep& next, double toolLengthMm)
{
    const auto free = static_cast<std::size_t>(poleJoint(m_machine.kinematics));
    const double target = next.pose.rotaryDeg[free];
    if (std::abs(target - pole.pose.rotaryDeg[free]) < 1e-9)
        return;
    FiveAxisStep turn = pole;
    turn.record = next.record;
    turn.feedMmPerMin = next.feedMmPerMin;
    turn.feedKind = next.feedKind;
    turn.reconfigure = false;
    turn.pose.rotaryDeg[free] = target;
    turn.pose.linear =
        kinematics::linearAxesFor(m_machine.kinematics, turn.tool.tip, turn.pose.rotaryDeg, toolLengthMm);
    m_plan.steps.push_back(turn);
}

base::Status SectionPlanner::plan(const std::vector<SectionPose>& poses, double toolLengthMm)
{
    if (poses.empty())
        return {};
    const kinematics::PoseSolver solver(m_machine, toolLengthMm);
    std::vector<ToolPose> tools;
    tools.reserve(poses.size());
    for (const SectionPose& pose : poses)
        tools.push_back(pose.tool);
    const MachinePose home = m_home;
    kinematics::BranchPlanOptions options;
    options.reconfigureStepDeg = m_options.reconfigureStepDeg;
    options.allowReconfigure = m_options.retractToReconfigure;
    // Within the cone C may swing however the tool axis turns: the post keeps it there.
    options.poleConeDeg = std::max(options.poleConeDeg, m_options.poleConeDeg);
    auto planned = kinematics::planBranches(solver, tools, &home, options);
    if (!planned)
        return explainFailure(solver, tools, poses, home, planned.error());

    FiveAxisSection section;
    section.firstRecord = poses.front().record;
    section.lastRecord = poses.back().record;
    section.firstStep = m_plan.steps.size();
    section.toolLengthMm = toolLengthMm;
    const double retract = m_options.retractMm;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const kinematics::PlannedPose& chosen = planned.value()[i];
        FiveAxisStep move = step(poses[i], StepKind::Move);
        move.pose = chosen.candidate.pose;
        move.pole = chosen.candidate.pole >= 0;
        move.feedMmPerMin = poses[i].feed;
        move.feedKind = poses[i].feedKind;
        const FiveAxisStep* previous = i > 0 ? &m_plan.steps.back() : nullptr;
        if (m_options.poleConeDeg > 0 && !move.pole)
            keepPoleInCone(solver, move, previous ? previous->pose : home);
        if (chosen.candidate.pole >= 0 && previous) {
            // On the pole the free angle stays where the last block left it (the cone may have
            // kept it where the plan did not).
            const auto free = static_cast<std::size_t>(chosen.candidate.pole);
            move.pose.rotaryDeg[free] = previous->pose.rotaryDeg[free];
            move.pose.linear =
                kinematics::linearAxesFor(m_machine.kinematics, move.tool.tip, move.pose.rotaryDeg, toolLengthMm);
        }
        if (previous && previous->pole && !move.pole && !chosen.reconfigure)
            turnOnPole(FiveAxisStep(*previous), move, toolLengthMm);
        if (!previous) {
            // The post turns the rotaries to the first pose (onFiveAxisBegin); then a first rapid
            // goes over in X/Y before it moves down, as after a tool change.
            if (move.feedMmPerMin <= 0) {
                FiveAxisStep position = move;
                position.kind = StepKind::Position;
                position.linearAxes = AxisMask{static_cast<unsigned char>(AxisMask::kX | AxisMask::kY)};
                m_plan.steps.push_back(position);
            }
        } else if (chosen.reconfigure) {
            const FiveAxisStep from = *previous;
            const Vec3 away = from.tool.tip + from.tool.axis * retract;
            m_plan.steps.push_back(
                rapidAt(poses[i], StepKind::Retract, away, from.tool.axis, from.pose.rotaryDeg, toolLengthMm));
            m_plan.steps.push_back(
                rapidAt(poses[i], StepKind::Turn, away, from.tool.axis, move.pose.rotaryDeg, toolLengthMm));
            m_plan.steps.push_back(rapidAt(poses[i], StepKind::Approach, move.tool.tip + move.tool.axis * retract,
                                           move.tool.axis, move.pose.rotaryDeg, toolLengthMm));
            move.reconfigure = true;
            ++section.reconfigurations;
        }
        m_plan.steps.push_back(move);
    }
    section.endStep = m_plan.steps.size();
    // After the section the post turns the rotaries home: each to the whole turn nearest where it
    // stands (a tilt to 0), or to 0 where that turn lies beyond the axis' limits.
    for (int j = 0; j < 2; ++j) {
        const double stands = m_plan.steps.back().pose.rotaryDeg[static_cast<std::size_t>(j)];
        m_home.rotaryDeg[static_cast<std::size_t>(j)] = 360 * std::round(stands / 360);
    }
    if (solver.outsideLimits(m_home))
        m_home = MachinePose{};
    section.home = m_home.rotaryDeg;
    m_plan.sections.push_back(section);
    return {};
}

}  // namespace

base::Result<FiveAxisPlan> planFiveAxis(const toolpath::Toolpath& toolpath, const kinematics::Machine& machine,
                                        const FiveAxisOptions& options, double arcToleranceMm)
{
    FiveAxisPlan plan;
    if (!machine.kinematics.fiveAxis())
        return plan;
    const auto ranges = fiveAxisRanges(toolpath);
    if (ranges.empty())
        return plan;
    SectionPlanner planner(toolpath, machine, options, plan);
    toolpath::KnownPosition position;
    double toolLength = 0;
    std::size_t next = 0;  // the next range
    std::vector<SectionPose> poses;
    const Vec3 up{0, 0, 1};
    for (std::size_t i = 0; i < toolpath.size() && next < ranges.size(); ++i) {
        const toolpath::Record& record = toolpath.record(i);
        const bool inside = i >= ranges[next].first;
        auto known = [&]() -> base::Status {
            if (inside && !position.complete())
                return base::makeError(recordError(toolpath, i,
                                                   "a five-axis operation needs X, Y and Z known before this move "
                                                   "(since the start or the last tool change)"));
            return {};
        };
        if (const auto* tool = std::get_if<toolpath::ToolChange>(&record)) {
            toolLength = tool->tool.lengthMm;
            position.forget();
        } else if (const auto* unknown = std::get_if<toolpath::UnknownAxes>(&record)) {
            position.forget(unknown->axes);
        } else if (const auto* rapid = std::get_if<toolpath::Rapid>(&record)) {
            position.moveTo(*rapid);
            if (auto status = known(); !status)
                return status.error();
            if (inside)
                poses.push_back({i, {position.value(), up}, 0, 0});
        } else if (const auto* linear = std::get_if<toolpath::Linear>(&record)) {
            position.moveTo(*linear);
            if (auto status = known(); !status)
                return status.error();
            if (inside)
                poses.push_back({i, {position.value(), up}, linear->feedMmPerMin, static_cast<int>(linear->feedKind)});
        } else if (const auto* arc = std::get_if<toolpath::Arc>(&record)) {
            if (inside) {
                if (auto status = known(); !status)
                    return status.error();
                if (plan.arcsLinearised++ == 0)
                    plan.firstArcLinearised = i;
                for (const Vec3& point : toolpath::linearizeArc(position.value(), *arc, arcToleranceMm))
                    poses.push_back({i, {point, up}, arc->feedMmPerMin, static_cast<int>(arc->feedKind)});
            }
            position.set(arc->to);
        } else if (const auto* move = std::get_if<toolpath::ToolAxisMove>(&record)) {
            position.set(move->tip);
            if (inside)
                poses.push_back({i, {move->tip, move->axis.normalized()}, move->feedMmPerMin, 0});
        } else if (const auto* cycle = std::get_if<toolpath::Cycle>(&record)) {
            if (inside)
                return base::makeError(recordError(toolpath, i,
                                                   "a canned cycle in a five-axis operation: the post writes cycles "
                                                   "in the working plane only"));
            if (!cycle->holes.empty())
                position.set({cycle->holes.back().x, cycle->holes.back().y, toolpath::cycleReturnZ(*cycle)});
        }
        if (i + 1 == ranges[next].second) {
            if (auto status = planner.plan(poses, toolLength); !status)
                return status.error();
            poses.clear();
            ++next;
        }
    }
    return plan;
}

namespace {

MachinePose lerp(const MachinePose& a, const MachinePose& b, double t)
{
    MachinePose p;
    p.linear = a.linear + (b.linear - a.linear) * t;
    for (int j = 0; j < 2; ++j)
        p.rotaryDeg[j] = a.rotaryDeg[j] + (b.rotaryDeg[j] - a.rotaryDeg[j]) * t;
    return p;
}

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double length2 = ab.dot(ab);
    const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + ab * t)).length();
}

bool rotariesStill(const MachinePose& a, const MachinePose& b)
{
    return std::abs(a.rotaryDeg[0] - b.rotaryDeg[0]) < 1e-12 && std::abs(a.rotaryDeg[1] - b.rotaryDeg[1]) < 1e-12;
}

void subdivide(const kinematics::KinematicChain& chain, const MachinePose& from, const MachinePose& to,
               const Vec3& tipFrom, const Vec3& tipTo, double tolerance, double toolLength, int depth,
               std::vector<MachinePose>& out)
{
    if (depth >= 20 || jointMoveTipDeviation(chain, from, to, tipFrom, tipTo, toolLength) <= tolerance) {
        out.push_back(to);
        return;
    }
    MachinePose middle = lerp(from, to, 0.5);
    const Vec3 tipMiddle = (tipFrom + tipTo) * 0.5;
    middle.linear = kinematics::linearAxesFor(chain, tipMiddle, middle.rotaryDeg, toolLength);
    subdivide(chain, from, middle, tipFrom, tipMiddle, tolerance, toolLength, depth + 1, out);
    subdivide(chain, middle, to, tipMiddle, tipTo, tolerance, toolLength, depth + 1, out);
}

}  // namespace

double jointMoveTipDeviation(const kinematics::KinematicChain& chain, const MachinePose& from, const MachinePose& to,
                             const Vec3& tipFrom, const Vec3& tipTo, double toolLengthMm)
{
    if (rotariesStill(from, to))
        return 0;  // only linear axes move: the tip goes straight
    double worst = 0;
    for (const double t : {0.25, 0.5, 0.75}) {
        const Vec3 tip = kinematics::forwardKinematics(chain, lerp(from, to, t), toolLengthMm).tip;
        worst = std::max(worst, segmentDistance(tip, tipFrom, tipTo));
    }
    return worst;
}

std::vector<MachinePose> lineariseJointMove(const kinematics::KinematicChain& chain, const MachinePose& from,
                                            const MachinePose& to, const Vec3& tipFrom, const Vec3& tipTo,
                                            double toleranceMm, double toolLengthMm)
{
    std::vector<MachinePose> poses;
    subdivide(chain, from, to, tipFrom, tipTo, toleranceMm, toolLengthMm, 0, poses);
    return poses;
}

namespace {

// The length of a block in machine space, mm and degrees together.
double axesLength(const MachinePose& from, const MachinePose& to)
{
    const Vec3 d = to.linear - from.linear;
    const double b = to.rotaryDeg[0] - from.rotaryDeg[0], c = to.rotaryDeg[1] - from.rotaryDeg[1];
    return std::sqrt(d.dot(d) + b * b + c * c);
}

}  // namespace

double inverseTimeFeed(const MachinePose& from, const MachinePose& to, double tipLengthMm, double tipFeed,
                       double maxFeed, bool* capped)
{
    const double rotary = std::hypot(to.rotaryDeg[0] - from.rotaryDeg[0], to.rotaryDeg[1] - from.rotaryDeg[1]);
    const double length = tipLengthMm > 1e-9 ? tipLengthMm : rotary;
    const double inverse = length > 1e-12 ? tipFeed / length : 0;
    const double axes = axesLength(from, to);
    const bool over = maxFeed > 0 && axes > 1e-12 && inverse * axes > maxFeed;
    if (capped)
        *capped = over;
    return over ? maxFeed / axes : inverse;
}

double combinedFeed(const MachinePose& from, const MachinePose& to, double tipLengthMm, double tipFeed, double maxFeed,
                    bool* capped)
{
    const double axes = axesLength(from, to);
    double feed = tipLengthMm > 1e-9 ? tipFeed * axes / tipLengthMm : tipFeed;
    const bool over = maxFeed > 0 && feed > maxFeed;
    if (capped)
        *capped = over;
    return over ? maxFeed : feed;
}

}  // namespace camwb::post
