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
    ops::ContourParams contour;
    contour.name = "Outer";
    contour.climb = false;
    contour.side = ops::ContourSide::Inside;
    contour.tabCount = 3;
    op.params = contour;
    op.geometry.faces = {7};
    op.heights.finalZ = 10.25;
    op.heights.safeZ = 17;
    op.heights.clearanceZ = 25;
    job.operations.push_back(op);

    document::Operation pocket;
    pocket.toolNumber = 3;
    ops::PocketParams p;
    p.name = "Pocket";
    p.pattern = ops::PocketPattern::ZigZag;
    p.zigZagAngleDeg = 30;
    p.entry = ops::EntryKind::Ramp;
    p.finishWalls = true;
    pocket.params = p;
    pocket.geometry.faces = {4, 9};
    job.operations.push_back(pocket);

    document::Operation helix;
    helix.toolNumber = 3;
    ops::HelixParams h;
    h.name = "Bore";
    h.pitchMm = 0.75;
    helix.params = h;
    helix.geometry.holes = {12};
    job.operations.push_back(helix);

    document::Operation drill;
    drill.toolNumber = 3;
    ops::DrillParams d;
    d.name = "Holes";
    d.cycle = toolpath::CycleKind::ChipBreak;
    d.peckMm = 2;
    drill.params = d;
    drill.geometry.holes = {13, 14};
    drill.heights.startZ = 15;
    job.operations.push_back(drill);
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
    ASSERT_EQ(job->operations.size(), 4u);
    const document::Operation& contour = job->operations[0];
    EXPECT_EQ(contour.kind(), document::OperationKind::Contour);
    EXPECT_DOUBLE_EQ(*contour.heights.finalZ, 10.25);
    EXPECT_FALSE(contour.heights.startZ.has_value()) << "only overridden heights are stored";
    EXPECT_FALSE(std::get<ops::ContourParams>(contour.params).climb);
    EXPECT_EQ(std::get<ops::ContourParams>(contour.params).side, ops::ContourSide::Inside);
    EXPECT_EQ(std::get<ops::ContourParams>(contour.params).tabCount, 3);
    EXPECT_EQ(job->operations[1].geometry.faces, (std::vector<int>{4, 9}));
    EXPECT_EQ(std::get<ops::PocketParams>(job->operations[1].params).pattern, ops::PocketPattern::ZigZag);
    EXPECT_EQ(std::get<ops::PocketParams>(job->operations[1].params).entry, ops::EntryKind::Ramp);
    EXPECT_DOUBLE_EQ(std::get<ops::HelixParams>(job->operations[2].params).pitchMm, 0.75);
    EXPECT_EQ(std::get<ops::DrillParams>(job->operations[3].params).cycle, toolpath::CycleKind::ChipBreak);
    EXPECT_EQ(job->operations[3].geometry.holes, (std::vector<int>{13, 14}));
    EXPECT_EQ(job->operations[3].name(), "Holes");
    EXPECT_EQ(job->tools[0].tool.name, "Flat D6");
}

TEST(JobFile, FileIsVersionedJson)
{
    const std::string text = validText();
    EXPECT_NE(text.find("\"format\": \"camwb-job\""), std::string::npos);
    EXPECT_NE(text.find("\"version\": 3"), std::string::npos);
}

TEST(JobFile, VersionOneProfileIsReadAsAnOutsideContourWithItsHeights)
{
    const std::string legacy = R"({"format": "camwb-job", "version": 1, "name": "Old", "model": "m.step",
        "stock": {"min": [0, 0, 0], "max": [10, 10, 5]}, "workOffset": 1, "post": "linuxcnc",
        "tools": [{"number": 1, "name": "D10", "kind": "flat", "diameter": 10, "cornerRadius": 0,
                   "fluteLength": 22, "length": 50, "flutes": 3, "spindleRpm": 3000, "cuttingFeed": 600,
                   "plungeFeed": 150}],
        "operations": [{"type": "profile", "name": "Outer profile", "tool": 1, "face": 2, "finalDepth": 10.0,
                        "safeHeight": 17.0, "clearanceHeight": 25.0, "direction": "conventional"}]})";
    auto job = document::parseJob(legacy, "old.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    const document::Operation& op = job->operations[0];
    EXPECT_EQ(op.kind(), document::OperationKind::Contour);
    EXPECT_EQ(op.name(), "Outer profile");
    EXPECT_EQ(op.geometry.faces, std::vector<int>{2});
    EXPECT_EQ(*op.heights.finalZ, 10.0);
    EXPECT_EQ(*op.heights.safeZ, 17.0);
    EXPECT_EQ(*op.heights.clearanceZ, 25.0);
    EXPECT_FALSE(op.heights.startZ.has_value());
    EXPECT_EQ(std::get<ops::ContourParams>(op.params).side, ops::ContourSide::Outside);
    EXPECT_FALSE(std::get<ops::ContourParams>(op.params).climb);
}

TEST(JobFile, ParametersMayBeLeftOutButNotMisspelled)
{
    auto job = document::parseJob(replaced(validText(), "\"pitch\": 0.75,", ""), "job.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    EXPECT_DOUBLE_EQ(std::get<ops::HelixParams>(job->operations[2].params).pitchMm, ops::HelixParams{}.pitchMm);
    EXPECT_NE(
        parseError(replaced(validText(), "\"pitch\": 0.75", "\"pich\": 0.75")).message.find("params.pich: unknown"),
        std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"pattern\": \"zigzag\"", "\"pattern\": \"spiral\""))
                  .message.find("expected one of \"offset\", \"zigzag\", got \"spiral\""),
              std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"holes\": [\n          12", "\"holes\": [\n          0"))
                  .message.find("holes"),
              std::string::npos);
}

// A stock whose max is not above its min on an axis would be taken for "no stock" by the post
// and the simulator (the model's box in its place): the file is refused, saying which axis. So
// is a stock beyond any machine's reach. All zero is a job without stock (a lathe job's).
TEST(JobFile, AStockThatIsNoBoxIsRefusedNamingTheAxis)
{
    Job job = sampleJob();
    job.stock.max.y = -5;
    base::Error error = parseError(document::serializeJob(job));
    EXPECT_EQ(error.message, "job.stock: the stock's max y (-5) is not above its min y (-2)") << error.message;
    job = sampleJob();
    job.stock.min.z = job.stock.max.z;
    EXPECT_NE(parseError(document::serializeJob(job)).message.find("max z (15.5) is not above its min z (15.5)"),
              std::string::npos);
    job = sampleJob();
    job.stock.max.x = 2e5;
    EXPECT_NE(parseError(document::serializeJob(job)).message.find("job.stock: the stock reaches more than 100 m"),
              std::string::npos);
    job = sampleJob();
    job.stock = {};
    EXPECT_TRUE(document::parseJob(document::serializeJob(job), "job.camwb").ok());
}

TEST(JobFile, ToolExtrasAreOptional)
{
    Job job = sampleJob();
    job.tools[0].rampFeedMmPerMin = 200;
    job.tools[0].tool.pointAngleDeg = 118;
    job.tools[0].tool.centreCutting = false;
    job.tools[0].tool.holder = "SK40 ER32";
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"holder\": \"SK40 ER32\""), std::string::npos) << text;
    auto read = document::parseJob(text, "job.camwb");
    ASSERT_TRUE(read.ok()) << read.error().toString();
    EXPECT_EQ(read->tools[0].rampFeedMmPerMin, 200);
    EXPECT_EQ(read->tools[0].tool.pointAngleDeg, 118);
    EXPECT_FALSE(read->tools[0].tool.centreCutting);
    EXPECT_EQ(read->tools[0].tool.holder, "SK40 ER32");
    // Left out when there is none, and a file without one reads as none.
    EXPECT_EQ(validText().find("rampFeed"), std::string::npos);
    EXPECT_EQ(validText().find("holder"), std::string::npos);
    auto plain = document::parseJob(validText(), "job.camwb");
    ASSERT_TRUE(plain.ok()) << plain.error().toString();
    EXPECT_EQ(plain->tools[0].tool.holder, "");
    const auto notText = document::parseJob(replaced(text, "\"SK40 ER32\"", "40"), "job.camwb");
    ASSERT_FALSE(notText.ok());
    EXPECT_NE(notText.error().message.find("holder"), std::string::npos) << notText.error().message;
}

TEST(JobFile, DisabledOperationIsKeptAndNeedsVersionSix)
{
    auto job = document::parseJob(validText(), "job.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    EXPECT_TRUE(job->operations[1].enabled);
    EXPECT_EQ(document::serializeJob(job.value()).find("\"enabled\""), std::string::npos) << "written only when off";
    job->operations[1].enabled = false;
    const std::string text = document::serializeJob(job.value());
    EXPECT_NE(text.find("\"version\": 6"), std::string::npos);
    EXPECT_NE(text.find("\"enabled\": false"), std::string::npos);
    auto back = document::parseJob(text, "job.camwb");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_FALSE(back->operations[1].enabled);
    EXPECT_TRUE(back->operations[0].enabled);
    EXPECT_EQ(document::serializeJob(back.value()), text);
    const base::Error e = parseError(replaced(text, "\"enabled\": false", "\"enabled\": \"no\""));
    EXPECT_NE(e.message.find("enabled"), std::string::npos) << e.message;
}

TEST(JobFile, SurfaceOperationsRoundTripAndNeedVersionSeven)
{
    auto job = document::parseJob(validText(), "job.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    EXPECT_EQ(document::serializeJob(job.value()).find("\"version\": 7"), std::string::npos);
    ops::Pocket3dParams rough;
    rough.name = "Rough";
    rough.pattern = ops::PocketPattern::ZigZag;
    rough.stepDownMm = 1.5;
    rough.sideStockMm = 0.4;
    rough.bottomStockMm = 0.1;
    rough.restMachining = true;
    ops::WaterlineParams walls;
    walls.name = "Walls";
    walls.scallopMm = 0.005;
    walls.minSlopeDeg = 40;
    ops::ParallelParams floor;
    floor.name = "Floor";
    floor.angleDeg = 45;
    floor.maxSlopeDeg = 42;
    floor.zigZag = false;
    for (const document::OperationParams& params :
         {document::OperationParams{rough}, document::OperationParams{walls}, document::OperationParams{floor}}) {
        document::Operation op;
        op.params = params;
        op.toolNumber = job->operations.front().toolNumber;
        op.geometry.faces = {3, 4};
        job->operations.push_back(op);
    }
    const std::string text = document::serializeJob(job.value());
    EXPECT_NE(text.find("\"version\": 7"), std::string::npos);
    for (const char* type : {"\"pocket3d\"", "\"waterline\"", "\"parallel\""})
        EXPECT_NE(text.find(type), std::string::npos) << type;
    auto back = document::parseJob(text, "job.camwb");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    ASSERT_EQ(back->operations.size(), job->operations.size());
    const auto& r = std::get<ops::Pocket3dParams>(back->operations.end()[-3].params);
    EXPECT_EQ(r.name, "Rough");
    EXPECT_EQ(r.pattern, ops::PocketPattern::ZigZag);
    EXPECT_DOUBLE_EQ(r.sideStockMm, 0.4);
    EXPECT_DOUBLE_EQ(r.bottomStockMm, 0.1);
    EXPECT_TRUE(r.restMachining);
    EXPECT_DOUBLE_EQ(std::get<ops::WaterlineParams>(back->operations.end()[-2].params).minSlopeDeg, 40);
    EXPECT_FALSE(std::get<ops::ParallelParams>(back->operations.back().params).zigZag);
    EXPECT_EQ(back->operations.back().geometry.faces, (std::vector<int>{3, 4}));
    EXPECT_EQ(document::serializeJob(back.value()), text);
    const base::Error e = parseError(replaced(text, "\"minSlope\"", "\"minSlop\""));
    EXPECT_NE(e.message.find("minSlop"), std::string::npos) << e.message;
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
    const base::Error e = parseError(replaced(validText(), "\"version\": 3", "\"version\": 99"));
    EXPECT_NE(e.message.find("newer"), std::string::npos) << e.message;
}

TEST(JobFile, MissingOrWrongFieldsAreNamed)
{
    EXPECT_NE(
        parseError(replaced(validText(), "\"final\": 10.25", "\"final\": \"deep\"")).message.find("heights.final"),
        std::string::npos);
    EXPECT_NE(
        parseError(replaced(validText(), "\"workOffset\": 2", "\"workOffset\": \"G55\"")).message.find("workOffset"),
        std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"type\": \"contour\"", "\"type\": \"knurl\"")).message.find("knurl"),
              std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"tool\": 3", "\"tool\": 4")).message.find("no tool number 4"),
              std::string::npos);
    EXPECT_NE(parseError(replaced(validText(), "\"side\": \"inside\"", "\"side\": \"sideways\"")).message.find("side"),
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

TEST(JobFile, MachineAndPostPropertiesAreKept)
{
    Job job = sampleJob();
    job.machineId = "emco-concept-mill-105";
    job.postProperties = {{"drillingCalls", "perHole"}, {"sequenceStep", "5"}};
    const std::string text = document::serializeJob(job);
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
