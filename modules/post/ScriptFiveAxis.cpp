// The five-axis path of a post run: FiveAxisWriter writes a FiveAxisPlan's steps (templates or
// onLinear5D), and the script services that report what five-axis blocks wrote.
#include "post/detail/FiveAxisWriter.h"
#include "post/detail/ScriptRun.h"

#include <cmath>

namespace camwb::post {

using kinematics::MachinePose;
using kinematics::ToolPose;
using toolpath::Vec3;

namespace {

constexpr const char* kAxisNames[6] = {"x", "y", "z", "a", "b", "c"};

int rotaryIndex(const std::string& axis) { return axis == "A" ? 0 : axis == "B" ? 1 : 2; }

const char* kindName(StepKind kind)
{
    switch (kind) {
    case StepKind::Move:
        return "move";
    case StepKind::Retract:
        return "retract";
    case StepKind::Turn:
        return "turn";
    case StepKind::Approach:
        return "approach";
    case StepKind::Position:
        return "position";
    }
    return "move";
}

}  // namespace

void ScriptKernel::noteMachineAxes(const std::array<double, 6>& values, unsigned mask)
{
    for (int axis = 0; axis < 6; ++axis) {
        if (!(mask & (1u << axis)))
            continue;
        const double v = values[axis];
        const bool first = !(m_axesSeen & (1u << axis));
        m_axisMin[axis] = first ? v : std::min(m_axisMin[axis], v);
        m_axisMax[axis] = first ? v : std::max(m_axisMax[axis], v);
        m_axisLast[axis] = v;
    }
    m_axesSeen |= mask;
}

QJSValue ScriptKernel::getFiveAxisTravel()
{
    if (m_axesSeen == 0)
        return QJSValue(QJSValue::NullValue);
    QJSValue travel = m_engine->newObject();
    for (int axis = 0; axis < 6; ++axis) {
        if (!(m_axesSeen & (1u << axis)))
            continue;
        QJSValue range = m_engine->newObject();
        range.setProperty("min", m_axisMin[axis]);
        range.setProperty("max", m_axisMax[axis]);
        travel.setProperty(kAxisNames[axis], range);
    }
    return travel;
}

QJSValue ScriptKernel::getMachinePose()
{
    if (m_axesSeen == 0)
        return QJSValue(QJSValue::NullValue);
    QJSValue pose = m_engine->newObject();
    for (int axis = 0; axis < 6; ++axis)
        if (m_axesSeen & (1u << axis))
            pose.setProperty(kAxisNames[axis], m_axisLast[axis]);
    return pose;
}

bool FiveAxisWriter::writeRecord(bool compensationOn)
{
    const std::vector<FiveAxisStep>& steps = m_plan.steps;
    const std::size_t record = steps[m_next].record;
    if (compensationOn) {
        m_run.fail("cutter compensation is on in a five-axis move: five-axis moves are written without it");
        return false;
    }
    while (m_next < steps.size() && steps[m_next].record == record && !m_run.m_failure) {
        const FiveAxisStep& step = steps[m_next];
        if (!m_inSection) {
            m_inSection = true;
            m_last = nullptr;
            if (!chooseModes())
                return false;
            const FiveAxisSection& section = m_plan.sections[static_cast<std::size_t>(step.section)];
            QJSValue info = m_run.m_engine.newObject();
            info.setProperty("output", m_machineCoordinates ? "machine" : "tip");
            info.setProperty("reconfigurations", section.reconfigurations);
            info.setProperty("firstRecord", static_cast<double>(section.firstRecord));
            info.setProperty("lastRecord", static_cast<double>(section.lastRecord));
            // The rotaries of the first pose: the post turns them before its first move.
            const kinematics::KinematicChain& chain = m_run.m_machine->kinematics;
            for (std::size_t j = 0; j < chain.joints.size() && j < 2; ++j)
                info.setProperty(kAxisNames[3 + rotaryIndex(chain.joints[j].axis)], step.pose.rotaryDeg[j]);
            if (m_run.has(Handler::FiveAxisBegin) && !m_run.call(Handler::FiveAxisBegin, {info}))
                return false;
        }
        writeStep(step);
        m_last = &step;
        ++m_next;
    }
    if (m_run.m_failure || (m_next < steps.size() && steps[m_next].section == m_last->section))
        return false;
    m_inSection = false;
    if (m_run.has(Handler::FiveAxisEnd)) {
        const FiveAxisSection& section = m_plan.sections[static_cast<std::size_t>(m_last->section)];
        const kinematics::KinematicChain& chain = m_run.m_machine->kinematics;
        QJSValue home = m_run.m_engine.newObject();
        for (std::size_t j = 0; j < chain.joints.size() && j < 2; ++j)
            home.setProperty(kAxisNames[3 + rotaryIndex(chain.joints[j].axis)], section.home[j]);
        m_run.call(Handler::FiveAxisEnd, {m_run.m_kernel->getMachinePose(), home});
    }
    return true;
}

bool FiveAxisWriter::chooseModes()
{
    const FiveAxisDeclaration& declared = m_run.m_fiveAxis;
    m_machineCoordinates = declared.machineCoordinates;
    m_feed = declared.feed;
    if (declared.chooseOutput.isCallable()) {
        const std::optional<std::string> output = m_run.answer(declared.chooseOutput, "post.fiveAxis.output()");
        if (!output)
            return false;
        if (*output != "tip" && *output != "machine") {
            m_run.fail("post.fiveAxis.output() answered \"" + *output + "\": tip or machine");
            return false;
        }
        m_machineCoordinates = *output == "machine";
    }
    if (declared.chooseFeed.isCallable()) {
        const std::optional<std::string> feed = m_run.answer(declared.chooseFeed, "post.fiveAxis.feed()");
        if (!feed)
            return false;
        if (*feed != "tip" && *feed != "combined" && *feed != "inverse") {
            m_run.fail("post.fiveAxis.feed() answered \"" + *feed + "\": tip, combined or inverse");
            return false;
        }
        m_feed = *feed == "combined"  ? FiveAxisFeed::Combined
                 : *feed == "inverse" ? FiveAxisFeed::InverseTime
                                      : FiveAxisFeed::Tip;
    }
    return true;
}

double FiveAxisWriter::feedFor(const FiveAxisStep& step, const MachinePose& from, const MachinePose& to,
                               double tipLength)
{
    // The combined feed is what a control without TCPM reads of machine coordinates.
    const FiveAxisFeed mode = m_feed == FiveAxisFeed::Combined && !m_machineCoordinates ? FiveAxisFeed::Tip : m_feed;
    if (mode == FiveAxisFeed::Tip || step.feedMmPerMin <= 0)
        return step.feedMmPerMin;
    bool capped = false;
    const double max = m_run.m_machine->maxCuttingFeedMmPerMin;
    const double feed = mode == FiveAxisFeed::Combined
                            ? combinedFeed(from, to, tipLength, step.feedMmPerMin, max, &capped)
                            : inverseTimeFeed(from, to, tipLength, step.feedMmPerMin, max, &capped);
    if (capped && m_capped++ == 0)
        m_firstCapped = step.record;
    return feed;
}

void FiveAxisWriter::writeStep(const FiveAxisStep& step)
{
    const bool machine = m_machineCoordinates;
    if (!(step.feedMmPerMin > 0) || !m_last) {
        if (step.feedMmPerMin > 0 && m_feed == FiveAxisFeed::InverseTime) {
            m_run.fail("an inverse-time feed for the first move of a five-axis operation, whose start is not known");
            return;
        }
        writePose(step, step.pose, step.tool, step.feedMmPerMin);
        return;
    }
    if (!machine || step.kind != StepKind::Move) {
        writePose(step, step.pose, step.tool,
                  feedFor(step, m_last->pose, step.pose, distance(m_last->tool.tip, step.tool.tip)));
        return;
    }
    // Without TCPM the control moves every axis linearly between blocks: pieces in joint space
    // keep the tip within the tolerance of the CL's straight line.
    const kinematics::KinematicChain& chain = m_run.m_machine->kinematics;
    const double toolLength = m_plan.sections[static_cast<std::size_t>(step.section)].toolLengthMm;
    const std::vector<MachinePose> pieces = lineariseJointMove(
        chain, m_last->pose, step.pose, m_last->tool.tip, step.tool.tip, m_run.m_capabilities.toleranceMm, toolLength);
    MachinePose from = m_last->pose;
    Vec3 tipFrom = m_last->tool.tip;
    for (std::size_t k = 0; k < pieces.size() && !m_run.m_failure; ++k) {
        const ToolPose tool =
            k + 1 == pieces.size() ? step.tool : kinematics::forwardKinematics(chain, pieces[k], toolLength);
        writePose(step, pieces[k], tool, feedFor(step, from, pieces[k], distance(tipFrom, tool.tip)));
        from = pieces[k];
        tipFrom = tool.tip;
    }
}

void FiveAxisWriter::writePose(const FiveAxisStep& step, const MachinePose& pose, const ToolPose& tool, double feed)
{
    ScriptKernel& kernel = *m_run.m_kernel;
    const kinematics::KinematicChain& chain = m_run.m_machine->kinematics;
    const Vec3 linear = m_machineCoordinates ? pose.linear : tool.tip;
    std::array<double, 6> axes{linear.x, linear.y, linear.z, 0, 0, 0};
    unsigned mask = step.linearAxes.bits;
    for (std::size_t j = 0; j < chain.joints.size() && j < 2; ++j) {
        const int index = rotaryIndex(chain.joints[j].axis);
        axes[3 + index] = pose.rotaryDeg[j];
        mask |= 8u << index;
    }
    if (m_run.has(Handler::Linear5D)) {
        QJSEngine& engine = m_run.m_engine;
        QJSValue machine = engine.newObject();
        for (int axis = 0; axis < 6; ++axis)
            if (mask & (1u << axis))
                machine.setProperty(kAxisNames[axis], axes[axis]);
        machine.setProperty("pole", step.pole);
        machine.setProperty("reconfigure", step.reconfigure);
        machine.setProperty("kind", kindName(step.kind));
        m_run.call(Handler::Linear5D,
                   {tool.tip.x, tool.tip.y, tool.tip.z, tool.axis.x, tool.axis.y, tool.axis.z, feed, machine});
    } else {
        BlockTemplates& templates = m_run.m_templates;
        std::optional<BlockTemplate>& block = feed > 0 ? templates.linear5D : templates.rapid5D;
        if (!block) {
            m_run.fail("post " + m_run.m_postId + " drives 5 axes but has neither onLinear5D nor post.blocks." +
                       (feed > 0 ? "linear5D" : "rapid5D"));
            return;
        }
        MoveValues move;
        move.end = linear;
        move.start = m_writtenKnown ? m_written : linear;
        move.known = step.linearAxes;
        move.feed = feed;
        move.feedKind = step.feedKind;
        move.motion = feed > 0 ? 1 : 0;
        move.rotaryDeg = {axes[3], axes[4], axes[5]};
        move.toolAxis = tool.axis;
        templates.writeBeforeMove(kernel.writer());
        BlockTemplate::Issues issues;
        if (block->write(move, kernel.writer(), issues))
            templates.finishMove(block->axisBits(), move.start, move.end, kernel.writer());
        if (!issues.beyondMax.empty()) {
            m_run.fail(issues.beyondMax);
            return;
        }
    }
    if (step.linearAxes.all()) {
        m_written = linear;
        m_writtenKnown = true;
        kernel.setPosition(tool.tip);
    }
    kernel.noteMachineAxes(axes, mask);
}

void FiveAxisWriter::report(std::vector<base::Diagnostic>& messages) const
{
    const std::string& file = m_run.m_postFile;
    if (m_plan.poleAdjusted > 0)
        messages.push_back(base::warningDiagnostic(
            counted(m_plan.poleAdjusted, "tool axis", "tool axes") + " within the pole cone written on the pole to " +
                "keep C, at most " + base::NumberFormat{6, true}.format(m_plan.maxAxisDeviationDeg) +
                " deg from the CL's (first: CL record " + std::to_string(m_plan.firstPoleAdjusted) + ")",
            file));
    if (m_plan.arcsLinearised > 0)
        messages.push_back(base::warningDiagnostic(
            counted(m_plan.arcsLinearised, "arc", "arcs") + " in a five-axis operation: written as lines within " +
                base::NumberFormat{6, true}.format(m_run.m_capabilities.toleranceMm) + " mm (first: CL record " +
                std::to_string(m_plan.firstArcLinearised) + ")",
            file));
    if (m_capped > 0)
        messages.push_back(base::warningDiagnostic(
            counted(m_capped, "five-axis block", "five-axis blocks") + " would need a feed above the machine's " +
                base::NumberFormat{0, true}.format(m_run.m_machine->maxCuttingFeedMmPerMin) +
                " mm/min: F capped there, the tip goes slower than the CL says (first: CL record " +
                std::to_string(m_firstCapped) + ")",
            file));
}

}  // namespace camwb::post
