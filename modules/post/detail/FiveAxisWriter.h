// Private: writes the steps of a FiveAxisPlan through the post, the kernel's five-axis path. Each
// step becomes a block of the post's rapid5D/linear5D templates (in C++, no script call) or an
// onLinear5D call; machine coordinates are linearised in joint space and their feed converted as
// post.fiveAxis says; onFiveAxisBegin/onFiveAxisEnd frame each five-axis section.
#pragma once

#include "base/Diagnostic.h"
#include "post/FiveAxisPlan.h"

#include <cstddef>
#include <string>
#include <vector>

namespace camwb::post {

class ScriptRun;

class FiveAxisWriter {
public:
    FiveAxisWriter(ScriptRun& run, FiveAxisPlan plan) : m_run(run), m_plan(std::move(plan)) {}

    // Whether the plan has steps for the record being played.
    bool owns(long long record) const
    {
        return m_next < m_plan.steps.size() && static_cast<long long>(m_plan.steps[m_next].record) == record;
    }
    // Writes the record's steps. True when they ended a five-axis section (onFiveAxisEnd ran: the
    // machine stands where the post left it, which the kernel does not know).
    bool writeRecord(bool compensationOn);
    // Warnings for what the five-axis output changed: axes moved onto the pole, feeds capped.
    void report(std::vector<base::Diagnostic>& messages) const;

private:
    bool chooseModes();  // the section's output and feed (post.fiveAxis, asked per section)
    void writeStep(const FiveAxisStep& step);
    void writePose(const FiveAxisStep& step, const kinematics::MachinePose& pose, const kinematics::ToolPose& tool,
                   double feed);
    double feedFor(const FiveAxisStep& step, const kinematics::MachinePose& from, const kinematics::MachinePose& to,
                   double tipLength);

    ScriptRun& m_run;
    FiveAxisPlan m_plan;
    std::size_t m_next = 0;
    const FiveAxisStep* m_last = nullptr;  // the step written last in this section
    toolpath::Vec3 m_written;              // the linear axes the last complete five-axis block wrote
    bool m_writtenKnown = false;
    bool m_inSection = false;
    bool m_machineCoordinates = false;  // of the section being written
    FiveAxisFeed m_feed = FiveAxisFeed::Tip;
    int m_capped = 0;
    std::size_t m_firstCapped = 0;
};

}  // namespace camwb::post
