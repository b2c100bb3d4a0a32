#include "document/JobFile.h"
#include "base/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace camwb;
using document::Job;
namespace fs = std::filesystem;

namespace {

Job sampleJob()
{
    Job job;
    job.name = "Sample";
    job.modelPath = "/parts/block.step";
    job.stock = {{-1, -2, 0}, {91, 62, 15.5}};
    job.workOffset = 2;
    job.postId = "sinumerik828d-emco";
    ops::ToolController tc;
    tc.tool = {3, "Flat D6", "flat", 6.0, 0.0, 15.0, 40.0, 2};
    tc.spindleRpm = 4000;
    tc.cuttingFeedMmPerMin = 450;
    tc.plungeFeedMmPerMin = 120;
    job.tools.push_back(tc);
    document::Operation op;
    op.toolNumber = 3;
    op.profile.name = "Outer";
    op.profile.faceIndex = 7;
    op.profile.finalDepthZ = 10.25;
    op.profile.safeZ = 17;
    op.profile.clearanceZ = 25;
    op.profile.climb = false;
    job.operations.push_back(op);
    return job;
}

std::string validText() { return document::serializeJob(sampleJob()); }

base::Error parseError(const std::string& text)
{
    auto job = document::parseJob(text, "job.camwb");
    EXPECT_FALSE(job.ok());
    return job.ok() ? base::Error{} : job.error();
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    return pos == std::string::npos ? text : text.replace(pos, from.size(), to);
}

}  // namespace

TEST(JobFile, SerializeParseRoundTripKeepsEveryField)
{
    const std::string text = validText();
    auto job = document::parseJob(text, "job.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    EXPECT_EQ(document::serializeJob(job.value()), text);
    EXPECT_EQ(job->name, "Sample");
    EXPECT_EQ(job->workOffset, 2);
    ASSERT_EQ(job->operations.size(), 1u);
    EXPECT_DOUBLE_EQ(job->operations[0].profile.finalDepthZ, 10.25);
    EXPECT_FALSE(job->operations[0].profile.climb);
    EXPECT_EQ(job->tools[0].tool.name, "Flat D6");
}

TEST(JobFile, FileIsVersionedJson)
{
    const std::string text = validText();
    EXPECT_NE(text.find("\"format\": \"camwb-job\""), std::string::npos);
    EXPECT_NE(text.find("\"version\": 1"), std::string::npos);
}

TEST(JobFile, MalformedJsonNamesLineAndColumn)
{
    const base::Error e = parseError("{\n  \"format\": \"camwb-job\",\n  \"version\": 1 2\n}\n");
    EXPECT_EQ(e.file, "job.camwb");
    EXPECT_EQ(e.line, 3);
    EXPECT_GT(e.column, 0);
    EXPECT_NE(e.message.find("malformed JSON"), std::string::npos);
}

TEST(JobFile, NewerVersionIsRefusedWithAReason)
{
    const base::Error e = parseError(replaced(validText(), "\"version\": 1", "\"version\": 99"));
    EXPECT_NE(e.message.find("newer"), std::string::npos) << e.message;
}

TEST(JobFile, MissingOrWrongFieldsAreNamed)
{
    EXPECT_NE(parseError(replaced(validText(), "\"finalDepth\"", "\"finalDepht\"")).message.find("finalDepth"),
              std::string::npos);
    EXPECT_NE(
        parseError(replaced(validText(), "\"workOffset\": 2", "\"workOffset\": \"G55\"")).message.find("workOffset"),
        std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"type\": \"profile\"", "\"type\": \"knurl\"")).message.find("knurl"),
              std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"tool\": 3", "\"tool\": 4")).message.find("no tool number 4"),
              std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"conventional\"", "\"sideways\"")).message.find("direction"),
              std::string::npos);
    EXPECT_NE(parseError("[1, 2]").message.find("expected an object"), std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "camwb-job", "other")).message.find("not a CAM Workbench job"),
              std::string::npos);
}

TEST(JobFile, ModelPathIsRelativeOnDiskAndAbsoluteInMemory)
{
    const fs::path dir = fs::temp_directory_path() / "camwb-jobfile-test";
    fs::create_directories(dir / "jobs");
    Job job = sampleJob();
    job.modelPath = (dir / "parts" / "block.step").string();
    const std::string jobPath = (dir / "jobs" / "a.camwb").string();
    ASSERT_TRUE(document::saveJob(job, jobPath));

    auto raw = document::parseJob(base::readTextFile(jobPath).value(), jobPath);
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(raw->modelPath, "../parts/block.step");

    auto loaded = document::loadJob(jobPath);
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(loaded->modelPath, job.modelPath);
    fs::remove_all(dir);
}

TEST(JobFile, MissingFileIsAnErrorNamingIt)
{
    auto job = document::loadJob("/nonexistent/x.camwb");
    ASSERT_FALSE(job.ok());
    EXPECT_EQ(job.error().file, "/nonexistent/x.camwb");
}

TEST(JobFile, MachineAndPostPropertiesMakeVersionTwo)
{
    Job job = sampleJob();
    job.machineId = "emco-concept-mill-105";
    job.postProperties = {{"drillingCalls", "perHole"}, {"sequenceStep", "5"}};
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
    EXPECT_NE(text.find("\"machine\": \"emco-concept-mill-105\""), std::string::npos);
    auto read = document::parseJob(text, "job.camwb");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(read->machineId, job.machineId);
    EXPECT_EQ(read->postProperties, job.postProperties);
    EXPECT_EQ(document::serializeJob(read.value()), text);

    // Written by hand: numbers and booleans are kept as the text the post's declaration will read.
    auto typed = document::parseJob(
        replaced(validText(), "\"post\": \"sinumerik828d-emco\"",
                 "\"post\": \"sinumerik828d-emco\", \"postProperties\": {\"sequenceStep\": 5, \"flag\": true}"),
        "job.camwb");
    ASSERT_TRUE(typed.ok()) << typed.error().toString();
    EXPECT_EQ(typed->postProperties.at("sequenceStep"), "5");
    EXPECT_EQ(typed->postProperties.at("flag"), "true");
    EXPECT_NE(parseError(replaced(validText(), "\"post\": \"sinumerik828d-emco\"",
                                  "\"post\": \"sinumerik828d-emco\", \"postProperties\": {\"a\": [1]}"))
                  .message.find("postProperties.a: expected a string, number or bool"),
              std::string::npos);
}
