// The five-axis example job (3+2): drilling square to four inclined faces, one plane per hole
// direction, and a contour round a boss on an inclined face in that face's plane; the working
// planes in the job file; the errors of a plane that cannot be.
#include "FiveAxisExample.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "document/OperationGeometry.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace camwb;
using toolpath::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

using document::test::fiveAxis;
using document::test::withBoxStock;

Vec3 sideNormal(int quarter)
{
    const double a = quarter * kPi / 2;
    return {0.5 * std::cos(a), 0.5 * std::sin(a), std::sqrt(3.0) / 2};
}

// An operation's own post property: the swarf pass in machine coordinates (tcpm off) while the
// job posts with M128; it rides on the CL section, survives the job file, and a value the post
// does not take per operation, or a bad one, fails naming the record.
TEST(FiveAxisJob, AnOperationSetsItsOwnTcpm)
{
    document::Job job = fiveAxis().job;
    auto swarf = std::find_if(job.operations.begin(), job.operations.end(), [](const document::Operation& op) {
        return op.kind() == document::OperationKind::Swarf;
    });
    ASSERT_NE(swarf, job.operations.end());
    post::PostContext context;
    context.outputName = "FIVE";  // the Klartext program's name
    auto post = [&](const document::Job& j) -> base::Result<std::string> {
        auto program = document::computeProgram(j, fiveAxis().model);
        if (!program)
            return program.error();
        auto processor = document::loadJobPost(j, post::defaultPostDirs());
        if (!processor)
            return processor.error();
        auto options = document::jobRunOptions(j, processor.value(), context, kinematics::defaultMachineDirs());
        if (!options)
            return options.error();
        auto out = processor.value().run(program.value(), options.value());
        if (!out)
            return out.error();
        return out.value().text;
    };
    auto asJob = post(job);
    ASSERT_TRUE(asJob) << asJob.error().toString();
    EXPECT_NE(asJob.value().find("L M128"), std::string::npos);

    swarf->postProperties["tcpm"] = "off";
    auto reread = document::parseJob(document::serializeJob(job), "five.camwb");
    ASSERT_TRUE(reread) << reread.error().toString();
    EXPECT_EQ(reread.value().operations[static_cast<std::size_t>(swarf - job.operations.begin())].postProperties,
              swarf->postProperties);
    EXPECT_NE(document::serializeJob(withBoxStock(job)).find("\"version\": 5"), std::string::npos);
    auto own = post(reread.value());
    ASSERT_TRUE(own) << own.error().toString();
    EXPECT_EQ(own.value().find("M128"), std::string::npos);  // the only five-axis operation is off
    EXPECT_NE(own.value().find("PLANE SPATIAL"), std::string::npos);

    swarf->postProperties = {{"tcpm", "sometimes"}};
    auto bad = post(job);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("tcpm"), std::string::npos) << bad.error().toString();
    EXPECT_NE(bad.error().message.find("CL record"), std::string::npos) << bad.error().toString();
    swarf->postProperties = {{"units", "inch"}};
    bad = post(job);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("applies to the whole program"), std::string::npos) << bad.error().toString();
}

}  // namespace

TEST(FiveAxisJob, DrillingTurnsToEachHolesAxis)
{
    auto result = document::computeOperation(fiveAxis().job, 0, fiveAxis().model);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const toolpath::Toolpath& tp = result->toolpath;
    ASSERT_TRUE(std::holds_alternative<toolpath::SectionBegin>(tp.record(0)));
    ASSERT_TRUE(std::holds_alternative<toolpath::SectionEnd>(tp.record(tp.size() - 1)));
    toolpath::WorkingPlane plane;
    std::vector<Vec3> tops;
    int tilted = 0;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        EXPECT_EQ(tp.source(i).operationIndex, 0);
        EXPECT_EQ(tp.source(i).recordIndex, static_cast<int>(i));
        if (const auto* p = std::get_if<toolpath::WorkingPlane>(&tp.record(i))) {
            plane = *p;
            tilted += p->tilted() ? 1 : 0;
        } else if (const auto* c = std::get_if<toolpath::Cycle>(&tp.record(i))) {
            ASSERT_TRUE(plane.tilted());
            ASSERT_EQ(c->holes.size(), 1u);
            EXPECT_NEAR(c->topZ - c->bottomZ, 8, 1e-6);
            EXPECT_NEAR(c->retractZ, 40, 1e-9);  // the job's safe height, in the plane's frame
            tops.push_back(plane.toWorkpiece({c->holes[0].x, c->holes[0].y, c->topZ}));
            // The plane's tool axis is the hole's face's normal.
            bool onAFace = false;
            for (int q = 0; q < 4; ++q)
                onAFace = onAFace || distance(plane.zAxis, sideNormal(q)) < 1e-9;
            EXPECT_TRUE(onAFace);
        }
    }
    EXPECT_EQ(tilted, 4);
    EXPECT_FALSE(plane.tilted());  // reset before the section ends
    ASSERT_EQ(tops.size(), 4u);
    const double r = 40 - 7.5 / std::tan(kPi / 6);
    for (const Vec3& top : tops) {
        EXPECT_NEAR(top.z, 27.5, 1e-6);
        const double sideways = std::abs(std::abs(top.x) - r) < 1e-6 ? std::abs(top.y) : std::abs(top.x);
        EXPECT_NEAR(std::hypot(top.x, top.y), std::hypot(r, sideways), 1e-6);
    }
}

TEST(FiveAxisJob, ContourRoundTheBossStaysOnTheInclinedFace)
{
    auto result = document::computeOperation(fiveAxis().job, 1, fiveAxis().model);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const toolpath::Toolpath& tp = result->toolpath;
    ASSERT_GE(tp.size(), 4u);
    const auto* plane = std::get_if<toolpath::WorkingPlane>(&tp.record(1));
    ASSERT_NE(plane, nullptr);
    EXPECT_NEAR(distance(plane->zAxis, sideNormal(2)), 0, 1e-12);
    // In the plane's frame the inclined face is at 20 + 10 sqrt 3: nothing cuts below it, and the
    // last pass is on it.
    const double face = 20 + 10 * std::sqrt(3.0);
    double lowest = 1e9;
    int moves = 0;
    for (const toolpath::Record& record : tp.records()) {
        if (const auto* l = std::get_if<toolpath::Linear>(&record)) {
            lowest = std::min(lowest, l->to.z);
            ++moves;
        } else if (const auto* a = std::get_if<toolpath::Arc>(&record)) {
            lowest = std::min(lowest, a->to.z);
            EXPECT_NEAR(std::abs(a->normal.z), 1, 1e-12);  // arcs in the plane's own XY
        }
    }
    EXPECT_GT(moves, 4);
    EXPECT_NEAR(lowest, 37.3205, 1e-9);
    EXPECT_GT(lowest, face - 1e-4);
    EXPECT_FALSE(std::get<toolpath::WorkingPlane>(tp.record(tp.size() - 2)).tilted());
}

TEST(FiveAxisJob, TheProgramChangesToolsBeforeItTilts)
{
    auto program = document::computeProgram(fiveAxis().job, fiveAxis().model);
    ASSERT_TRUE(program.ok()) << program.error().toString();
    const toolpath::Toolpath& tp = program.value();
    // WorkOffset, SectionBegin, ToolChange, Spindle, then the first plane.
    ASSERT_GE(tp.size(), 5u);
    EXPECT_TRUE(std::holds_alternative<toolpath::ToolChange>(tp.record(2)));
    EXPECT_TRUE(std::holds_alternative<toolpath::Spindle>(tp.record(3)));
    EXPECT_TRUE(std::holds_alternative<toolpath::WorkingPlane>(tp.record(4)));
}

TEST(FiveAxisJob, WorkingPlanesInTheJobFile)
{
    const document::Job job = withBoxStock(fiveAxis().job);
    ASSERT_EQ(job.operations.size(), 3u);
    EXPECT_EQ(job.operations[0].plane.mode, document::WorkingPlaneSpec::Mode::Flat);
    EXPECT_EQ(job.operations[1].plane.mode, document::WorkingPlaneSpec::Mode::Face);
    EXPECT_EQ(job.operations[1].plane.face, 26);
    EXPECT_NE(document::serializeJob(job).find("\"version\": 5"), std::string::npos);  // the swarf operation
    document::Job planes = job;
    planes.operations.resize(2);
    const std::string text = document::serializeJob(planes);
    EXPECT_NE(text.find("\"version\": 4"), std::string::npos);
    auto again = document::parseJob(text, "again.camwb");
    ASSERT_TRUE(again.ok()) << again.error().toString();
    EXPECT_EQ(again->operations[1].plane, job.operations[1].plane);
    // Angles, and a job with no plane is written as version 3 (older readers keep reading it).
    document::Job angles = job;
    angles.operations[1].plane = {document::WorkingPlaneSpec::Mode::Angles, 0, 12.5, -30, 90};
    auto back = document::parseJob(document::serializeJob(angles), "a.camwb");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->operations[1].plane, angles.operations[1].plane);
    document::Job flat = planes;
    flat.operations[1].plane = {};
    EXPECT_NE(document::serializeJob(flat).find("\"version\": 3"), std::string::npos);
    // A plane along a face that is not planar, or a face and angles both.
    std::string bad = text;
    bad.replace(bad.find("\"face\": 26"), 10, "\"face\": 26, \"a\": 1");
    auto refused = document::parseJob(bad, "bad.camwb");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("workingPlane: a face or the angles a, b, c, not both"), std::string::npos)
        << refused.error().message;
}

TEST(FiveAxisJob, APlaneThatCannotBeIsAnError)
{
    document::Job job = fiveAxis().job;
    job.operations[1].plane.face = 8;  // a hole's cylinder
    auto cylinder = document::computeOperation(job, 1, fiveAxis().model);
    ASSERT_FALSE(cylinder.ok());
    EXPECT_EQ(cylinder.error().message, "contour \"Boss on the inclined face\": working plane: face 8 is not planar");
    job.operations[1].plane.face = 999;
    auto missing = document::computeOperation(job, 1, fiveAxis().model);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().message,
              "contour \"Boss on the inclined face\": working plane: no face 999 in the model");
}
