// The lathe job: the groove operation in the job file (job format 8, R names as aliases), a job
// without a model computed by the pipeline (the op's own spindle start), --set's parameter
// overrides and the turning setup the simulator checks the program on.
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "document/OperationParameters.h"
#include "document/SetupSheet.h"
#include "document/TurningSetup.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"
#include "sim/TurningCheck.h"

#include <gtest/gtest.h>

#include <string>

using namespace camwb;

namespace {

const std::string kGrooveJob = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/groove-kod1.camwb";

document::Job grooveJob()
{
    auto job = document::loadJob(kGrooveJob);
    EXPECT_TRUE(job.ok()) << job.error().toString();
    return job.ok() ? job.value() : document::Job{};
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

base::Result<toolpath::Toolpath> computeWithoutModel(const document::Job& job)
{
    auto model = document::loadJobModel(job);
    if (!model)
        return model.error();
    EXPECT_TRUE(model->empty());
    return document::computeProgram(job, model.value());
}

}  // namespace

TEST(GrooveJob, ExampleIsALatheJobWithTheThesisValues)
{
    const document::Job job = grooveJob();
    ASSERT_EQ(job.operations.size(), 1u);
    const document::Operation& op = job.operations[0];
    EXPECT_EQ(op.kind(), document::OperationKind::Groove);
    EXPECT_FALSE(document::isSurfaceKind(op.kind()));
    EXPECT_TRUE(document::isTurningKind(op.kind()));
    EXPECT_STREQ(document::kindName(op.kind()), "groove");
    EXPECT_STREQ(document::kindLabel(op.kind()), "groove roughing");
    EXPECT_TRUE(job.modelPath.empty());
    EXPECT_FALSE(document::jobNeedsModel(job));
    const auto& p = std::get<ops::GrooveParams>(op.params);
    EXPECT_DOUBLE_EQ(p.groove.r2, 21.801);
    EXPECT_DOUBLE_EQ(p.groove.r3, 170);
    EXPECT_DOUBLE_EQ(p.groove.r6, 4.09);
    EXPECT_DOUBLE_EQ(p.surfaceSpeedMPerMin, 300);
    EXPECT_DOUBLE_EQ(p.maxRpm, 3000);
    EXPECT_DOUBLE_EQ(p.feedMmPerRev, 0.2);
    ASSERT_NE(job.tool(5), nullptr);
    EXPECT_EQ(job.tool(5)->tool.kind, "groove");
    EXPECT_DOUBLE_EQ(job.tool(5)->tool.diameterMm, 3);
    EXPECT_EQ(job.postId, "sinumerik840d-turn");
    EXPECT_EQ(job.machineId, "skoda-sr2000-840d");
}

TEST(GrooveJob, FileRoundTripIsVersionEightAndReadsTheRNames)
{
    const document::Job job = grooveJob();
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"version\": 8"), std::string::npos);
    EXPECT_NE(text.find("\"type\": \"groove\""), std::string::npos);
    EXPECT_NE(text.find("\"rightFlankAngle\": 6.71"), std::string::npos);
    EXPECT_EQ(text.find("\"R5\""), std::string::npos) << "R names are read, never written";
    auto back = document::parseJob(text, "lathe.camwb");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_EQ(document::serializeJob(back.value()), text);

    // The thesis' names in the file: R3 is the depth, R10 the step factor, R30 the safety.
    std::string withR = replaced(text, "\"depth\": 170.0", "\"R3\": 150.5");
    withR = replaced(withR, "\"stepFactor\": 0.8", "\"R10\": 0.6");
    withR = replaced(withR, "\"safety\": 1.0", "\"R30\": 2.0");
    auto aliased = document::parseJob(withR, "lathe.camwb");
    ASSERT_TRUE(aliased.ok()) << aliased.error().toString();
    const auto& p = std::get<ops::GrooveParams>(aliased->operations[0].params);
    EXPECT_DOUBLE_EQ(p.groove.r3, 150.5);
    EXPECT_DOUBLE_EQ(p.stepFactor, 0.6);
    EXPECT_DOUBLE_EQ(p.safetyMm, 2);
    EXPECT_NE(document::serializeJob(aliased.value()).find("\"depth\": 150.5"), std::string::npos);

    // Both names of one parameter, R9 (the tool's width) and a wrong type are errors naming it.
    auto both = document::parseJob(replaced(text, "\"depth\": 170.0", "\"depth\": 170.0, \"R3\": 160"), "l.camwb");
    ASSERT_FALSE(both.ok());
    EXPECT_NE(both.error().message.find("params.R3: the same parameter as \"depth\""), std::string::npos)
        << both.error().message;
    auto r9 = document::parseJob(replaced(text, "\"depth\": 170.0", "\"R9\": 3"), "l.camwb");
    ASSERT_FALSE(r9.ok());
    EXPECT_NE(r9.error().message.find("params.R9: unknown parameter"), std::string::npos) << r9.error().message;
    auto wrong = document::parseJob(replaced(text, "\"coolant\": true", "\"coolant\": 1"), "l.camwb");
    ASSERT_FALSE(wrong.ok());
    EXPECT_NE(wrong.error().message.find("params.coolant"), std::string::npos) << wrong.error().message;
    auto wrongR = document::parseJob(replaced(text, "\"depth\": 170.0", "\"R3\": \"deep\""), "l.camwb");
    ASSERT_FALSE(wrongR.ok());
    EXPECT_NE(wrongR.error().message.find("params.R3: expected a number"), std::string::npos) << wrongR.error().message;

    // Version 8 may leave the model out; version 7 may not, nor know the groove.
    auto noModel = document::parseJob(replaced(text, "\"model\": \"\",", ""), "l.camwb");
    ASSERT_TRUE(noModel.ok()) << noModel.error().toString();
    EXPECT_TRUE(noModel->modelPath.empty());
    auto seven = document::parseJob(
        replaced(replaced(text, "\"version\": 8", "\"version\": 7"), "\"model\": \"\",", ""), "l.camwb");
    ASSERT_FALSE(seven.ok());
    EXPECT_NE(seven.error().message.find("model"), std::string::npos) << seven.error().message;
}

TEST(GrooveJob, ComputesWithoutAModelAndStartsItsOwnSpindle)
{
    auto program = computeWithoutModel(grooveJob());
    ASSERT_TRUE(program.ok()) << program.error().toString();
    std::size_t toolChanges = 0, moves = 0;
    std::vector<toolpath::Spindle> spindles;
    for (std::size_t i = 0; i < program->size(); ++i) {
        const toolpath::Record& r = program->record(i);
        toolChanges += std::holds_alternative<toolpath::ToolChange>(r) ? 1 : 0;
        moves += std::holds_alternative<toolpath::Rapid>(r) || std::holds_alternative<toolpath::Linear>(r) ? 1 : 0;
        if (const auto* s = std::get_if<toolpath::Spindle>(&r))
            spindles.push_back(*s);
    }
    EXPECT_EQ(toolChanges, 1u);
    // Only the operation's G96 start: no milling start at the tool controller's rpm (0 here).
    ASSERT_EQ(spindles.size(), 1u);
    EXPECT_DOUBLE_EQ(spindles[0].surfaceSpeedMPerMin, 300);
    EXPECT_DOUBLE_EQ(spindles[0].rpm, 3000);
    EXPECT_EQ(moves, 575u);  // the first retract and the reference's 574 moves
}

TEST(GrooveJob, AMillingOperationInALatheJobNeedsAModel)
{
    document::Job job = grooveJob();
    document::Operation contour;
    contour.toolNumber = 5;
    contour.params = ops::ContourParams{};
    contour.geometry.faces = {1};
    job.operations.push_back(contour);
    EXPECT_TRUE(document::jobNeedsModel(job));
    auto model = document::loadJobModel(job);
    ASSERT_FALSE(model.ok());
    EXPECT_EQ(model.error().message, "the job has no model (its milling operations need one)");
    auto program = document::computeProgram(job, occ::Model());
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().message.find("contour \"Contour\": needs a model and the job has none"),
              std::string::npos)
        << program.error().message;
}

TEST(GrooveJob, SetParameterByNameRNameOrNumber)
{
    document::Job job = grooveJob();
    auto byName = document::findOperation(job, "Groove");
    ASSERT_TRUE(byName.ok());
    EXPECT_EQ(byName.value(), 0);
    auto byNumber = document::findOperation(job, "1");
    ASSERT_TRUE(byNumber.ok());
    EXPECT_EQ(byNumber.value(), 0);
    auto missing = document::findOperation(job, "2");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message, "no operation \"2\" in the job (operations: 1 \"Groove\")");

    ASSERT_TRUE(document::setOperationParameter(job, 0, "R3", "160"));
    ASSERT_TRUE(document::setOperationParameter(job, 0, "infeed", "1.5"));
    ASSERT_TRUE(document::setOperationParameter(job, 0, "coolant", "false"));
    ASSERT_TRUE(document::setOperationParameter(job, 0, "R9", "4"));
    const auto& p = std::get<ops::GrooveParams>(job.operations[0].params);
    EXPECT_DOUBLE_EQ(p.groove.r3, 160);
    EXPECT_DOUBLE_EQ(p.infeedMm, 1.5);
    EXPECT_FALSE(p.coolant);
    EXPECT_DOUBLE_EQ(job.tool(5)->tool.diameterMm, 4);  // R9: the insert width is the tool's
    EXPECT_DOUBLE_EQ(p.groove.r4, 45) << "the others keep their values";

    const base::Status unknown = document::setOperationParameter(job, 0, "width", "3");
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().message.find("no parameter \"width\" (parameters: startX, startZ,"), std::string::npos)
        << unknown.error().message;
    EXPECT_NE(unknown.error().message.find("R30, R9)"), std::string::npos) << unknown.error().message;
    const base::Status text = document::setOperationParameter(job, 0, "R2", "steep");
    ASSERT_FALSE(text);
    EXPECT_NE(text.error().message.find("groove roughing \"Groove\": params.R2: expected a number (got \"steep\")"),
              std::string::npos)
        << text.error().message;
    // Ranges are the operation's: it says what is wrong when computed.
    ASSERT_TRUE(document::setOperationParameter(job, 0, "R11", "0"));
    auto program = computeWithoutModel(job);
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().message.find("R11"), std::string::npos) << program.error().message;
}

TEST(GrooveJob, TurningSetupIsTheGroovesShaftAndOffsetContour)
{
    document::Job job = grooveJob();
    for (const char* depth : {"170", "160"}) {
        ASSERT_TRUE(document::setOperationParameter(job, 0, "R3", depth));
        const std::optional<document::TurningSetup> setup = document::turningSetup(job);
        ASSERT_TRUE(setup);
        EXPECT_DOUBLE_EQ(setup->insert.widthMm, 3);
        EXPECT_FALSE(setup->stock.empty());
        EXPECT_FALSE(setup->design.empty());
        auto program = computeWithoutModel(job);
        ASSERT_TRUE(program.ok()) << program.error().toString();
        sim::TurningOptions options;
        options.insert = setup->insert;
        const sim::TurningReport report =
            sim::checkTurning(sim::inTurningPlane(program.value()), setup->stock, setup->design, options);
        EXPECT_EQ(report.rapidsInStock, 0u) << "R3 = " << depth;
        EXPECT_EQ(report.gouges, 0u) << "R3 = " << depth << ": " << report.maxGougeMm << " mm";
        EXPECT_GT(report.removedMm2, 1000) << "R3 = " << depth;
    }
    // A job without a groove has no turning setup.
    job.operations[0].enabled = false;
    EXPECT_FALSE(document::turningSetup(job));
}

TEST(GrooveJob, SetupSheetSimulatesTheTurningWithoutAModel)
{
    document::Job job = grooveJob();
    job.postId = "sinumerik828d-emco";  // a post this test can rely on; the sheet only reads its name
    job.machineId.clear();
    auto model = document::loadJobModel(job);
    ASSERT_TRUE(model.ok()) << model.error().toString();
    auto program = document::computeProgram(job, model.value());
    ASSERT_TRUE(program.ok()) << program.error().toString();
    document::SheetOptions options;
    options.machine = kinematics::defaultLimitsMachine();
    options.postDirs = post::defaultPostDirs();
    auto sheet = document::collectSetupSheet(job, kGrooveJob, model.value(), program.value(), options);
    ASSERT_TRUE(sheet.ok()) << sheet.error().toString();
    const document::SheetVerification& v = sheet->verification;
    EXPECT_TRUE(v.run);
    EXPECT_TRUE(v.turning);
    EXPECT_EQ(v.rapidsInStock, 0);
    EXPECT_EQ(v.gouges, 0);
    // The moves are built although the program never gives Y (the turning plane).
    EXPECT_GT(sheet->feedLengthMm, 4000);
    ASSERT_EQ(sheet->operations.size(), 1u);
    EXPECT_GT(sheet->operations[0].seconds, 0);
    EXPECT_NEAR(sheet->operations[0].seconds, sheet->cycleSeconds, 1e-6);
    ASSERT_EQ(sheet->tools.size(), 1u);
    EXPECT_FALSE(sheet->tools[0].stickOutMm) << "a lathe insert has no stick-out along a spindle axis";
}
