#include "document/JobPipeline.h"
#include "document/JobFile.h"
#include "post/PostRegistry.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace camwb;

namespace {

const std::string kExampleJob = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/example-block.camwb";

template <class T> std::size_t countOf(const toolpath::Toolpath& tp)
{
    std::size_t n = 0;
    for (const auto& r : tp.records())
        n += std::holds_alternative<T>(r) ? 1 : 0;
    return n;
}

}  // namespace

TEST(JobPipeline, ExampleJobComputesWithToolChangeAfterSectionBegin)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok()) << job.error().toString();
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok()) << model.error().toString();
    auto program = document::computeProgram(job.value(), model.value());
    ASSERT_TRUE(program.ok()) << program.error().toString();

    const toolpath::Toolpath& tp = program.value();
    ASSERT_GE(tp.size(), 6u);
    EXPECT_TRUE(std::holds_alternative<toolpath::WorkOffset>(tp.record(0)));
    EXPECT_TRUE(std::holds_alternative<toolpath::SectionBegin>(tp.record(1)));
    ASSERT_TRUE(std::holds_alternative<toolpath::ToolChange>(tp.record(2)));
    EXPECT_EQ(std::get<toolpath::ToolChange>(tp.record(2)).tool.number, job->operations[0].toolNumber);
    EXPECT_TRUE(std::holds_alternative<toolpath::Spindle>(tp.record(3)));
    EXPECT_EQ(tp.source(2).operationIndex, 0);
    EXPECT_GT(countOf<toolpath::Arc>(tp), 0u) << "the rounded corners must stay arcs";
}

TEST(JobPipeline, SameToolTwiceChangesOnceAnotherToolChangesAgain)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok());
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok());

    document::Job twice = job.value();
    twice.operations = {job->operations[0], job->operations[0]};
    auto same = document::computeProgram(twice, model.value());
    ASSERT_TRUE(same.ok());
    EXPECT_EQ(countOf<toolpath::ToolChange>(same.value()), 1u);
    EXPECT_EQ(countOf<toolpath::SectionBegin>(same.value()), 2u);

    ops::ToolController other = twice.tools[0];
    other.tool.number = 7;
    other.tool.diameterMm = 6;
    twice.tools.push_back(other);
    twice.operations[1].toolNumber = 7;
    auto changed = document::computeProgram(twice, model.value());
    ASSERT_TRUE(changed.ok());
    EXPECT_EQ(countOf<toolpath::ToolChange>(changed.value()), 2u);
}

TEST(JobPipeline, ErrorsNameTheOperation)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok());
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok());
    document::Job bad = job.value();
    bad.operations[0].geometry.faces = {9999};
    auto program = document::computeProgram(bad, model.value());
    ASSERT_FALSE(program.ok());
    EXPECT_NE(
        program.error().message.find("contour \"" + bad.operations[0].name() + "\": face 9999 is not in the model"),
        std::string::npos)
        << program.error().message;
}

TEST(JobPipeline, MissingModelAndUnknownPostAreErrors)
{
    document::Job job;
    EXPECT_FALSE(document::loadJobModel(job).ok());
    job.modelPath = "/nonexistent/part.step";
    auto model = document::loadJobModel(job);
    ASSERT_FALSE(model.ok());
    EXPECT_EQ(model.error().file, "/nonexistent/part.step");
    job.postId = "no-such-post";
    auto post = document::loadJobPost(job, post::defaultPostDirs());
    ASSERT_FALSE(post.ok());
    EXPECT_NE(post.error().toString().find("no-such-post"), std::string::npos);
}

TEST(JobPipeline, RunOptionsCarryTheJobsMachineAndProperties)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok()) << job.error().toString();
    auto post = document::loadJobPost(job.value(), post::defaultPostDirs());
    ASSERT_TRUE(post.ok()) << post.error().toString();
    const std::vector<std::string> machines = kinematics::defaultMachineDirs();

    // No machine in the job: the post's default one.
    auto defaults = document::jobRunOptions(job.value(), post.value(), {}, machines);
    ASSERT_TRUE(defaults.ok()) << defaults.error().toString();
    ASSERT_TRUE(defaults->machine.has_value());
    EXPECT_EQ(defaults->machine->id, "emco-concept-mill-105");
    EXPECT_TRUE(defaults->properties.empty());

    document::Job custom = job.value();
    custom.postProperties = {{"drillingCalls", "perHole"}};
    custom.machineId = "no-such-mill";
    auto missing = document::jobRunOptions(custom, post.value(), {}, machines);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("machine 'no-such-mill' not found"), std::string::npos);
    custom.machineId.clear();
    auto options = document::jobRunOptions(custom, post.value(), {}, machines);
    ASSERT_TRUE(options.ok());
    EXPECT_EQ(options->properties, custom.postProperties);
}

TEST(JobPipeline, WarningsAndCountsOfEachOperationAreReported)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok());
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok());
    document::Job j = job.value();
    // The D5 drill in the D10 through hole: drilled, but the hole comes out undersize.
    document::Operation& drill = j.operations.back();
    ASSERT_EQ(drill.kind(), document::OperationKind::Drill);
    drill.geometry.holes = {21};
    document::ProgramReport report;
    auto program = document::computeProgram(j, model.value(), {}, &report);
    ASSERT_TRUE(program.ok()) << program.error().toString();
    ASSERT_EQ(report.counts.size(), j.operations.size());
    EXPECT_EQ(report.counts.back().cycles, 1);
    EXPECT_GT(report.counts[0].arcs, 0) << "the contour's corners stay arcs";
    EXPECT_GT(report.counts[2].helices, 0);
    ASSERT_EQ(report.warnings.size(), 1u);
    const std::string& warning = report.warnings[0].message;
    EXPECT_EQ(report.warnings[0].severity, base::Severity::Warning);
    EXPECT_EQ(warning.rfind("drilling \"" + drill.name() + "\": ", 0), 0u) << warning;
    EXPECT_NE(warning.find("undersize"), std::string::npos) << warning;
}

TEST(JobPipeline, EveryOperationThatCannotBeMadeIsNamedWhenAsked)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok());
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok());
    document::Job j = job.value();
    ASSERT_GE(j.operations.size(), 3u);
    j.operations[0].toolNumber = 98;
    j.operations[2].toolNumber = 99;

    document::ProgramReport first;  // by default the first failure ends the run
    auto stopped = document::computeProgram(j, model.value(), {}, &first);
    ASSERT_FALSE(stopped.ok());
    ASSERT_EQ(first.failures.size(), 1u);
    EXPECT_EQ(first.failures[0].operation, 0);

    document::ProgramReport all;
    all.allFailures = true;
    auto program = document::computeProgram(j, model.value(), {}, &all);
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().message.find("no tool number 98"), std::string::npos) << program.error().message;
    ASSERT_EQ(all.failures.size(), 2u);
    EXPECT_EQ(all.failures[0].operation, 0);
    EXPECT_EQ(all.failures[1].operation, 2);
    EXPECT_NE(all.failures[1].message.find("no tool number 99"), std::string::npos) << all.failures[1].message;
    EXPECT_EQ(all.counts.size(), j.operations.size());
}

TEST(JobPipeline, DisabledOperationIsNeitherComputedNorPosted)
{
    auto job = document::loadJob(kExampleJob);
    ASSERT_TRUE(job.ok());
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok());
    document::Job j = job.value();
    // The pocket (T2) off: the helix after it (T2 too) must now change to T2 itself.
    ASSERT_GE(j.operations.size(), 3u);
    ASSERT_EQ(j.operations[1].toolNumber, j.operations[2].toolNumber);
    ASSERT_NE(j.operations[0].toolNumber, j.operations[1].toolNumber);
    j.operations[1].enabled = false;
    j.operations[1].toolNumber = 99;  // not even its tool is looked at
    document::ProgramReport report;
    auto program = document::computeProgram(j, model.value(), {}, &report);
    ASSERT_TRUE(program.ok()) << program.error().toString();
    ASSERT_EQ(report.counts.size(), j.operations.size());
    EXPECT_EQ(report.counts[1].lines + report.counts[1].arcs + report.counts[1].rapids, 0u);

    std::vector<int> sectionOps, toolChanges;
    for (std::size_t r = 0; r < program->size(); ++r) {
        const toolpath::Record& record = program->record(r);
        EXPECT_NE(program->source(r).operationIndex, 1);
        if (const auto* begin = std::get_if<toolpath::SectionBegin>(&record)) {
            EXPECT_NE(begin->operationName, j.operations[1].name());
            sectionOps.push_back(program->source(r).operationIndex);
        }
        if (const auto* change = std::get_if<toolpath::ToolChange>(&record))
            toolChanges.push_back(change->tool.number);
    }
    ASSERT_GE(sectionOps.size(), 3u);
    EXPECT_EQ(sectionOps[0], 0);
    EXPECT_EQ(sectionOps[1], 2) << "the operations after it keep their job indices";
    ASSERT_GE(toolChanges.size(), 2u);
    EXPECT_EQ(toolChanges[1], j.operations[2].toolNumber);

    // Posted: no line of the NC comes from it, and its name is nowhere in the program.
    auto post = document::loadJobPost(j, post::defaultPostDirs());
    ASSERT_TRUE(post.ok()) << post.error().toString();
    auto options = document::jobRunOptions(j, post.value(), {}, kinematics::defaultMachineDirs());
    ASSERT_TRUE(options.ok()) << options.error().toString();
    auto nc = post->run(program.value(), options.value());
    ASSERT_TRUE(nc.ok()) << nc.error().toString();
    EXPECT_EQ(nc->text.find(j.operations[1].name()), std::string::npos);
    EXPECT_NE(nc->text.find(j.operations[2].name()), std::string::npos);
    EXPECT_EQ(std::count(nc->lineOperation.begin(), nc->lineOperation.end(), 1), 0);
    EXPECT_GT(std::count(nc->lineOperation.begin(), nc->lineOperation.end(), 2), 0);
}
