// The five-axis example job's swarf operation along the drafted boss: simultaneous moves with the
// tool's side on the cone all round it (the axis leaning every way), gouge-checked against the
// model; a tip forced into the inclined face is a gouge named by face and place; a face that is not
// ruled and a working plane are refused; the parameters' round trip through the job file.
#include "FiveAxisExample.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "document/OperationGeometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace camwb;
using toolpath::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSwarf = 2;  // the operation's index in the job

using document::test::fiveAxis;
using document::test::withBoxStock;

std::vector<toolpath::ToolAxisMove> moves(const toolpath::Toolpath& tp)
{
    std::vector<toolpath::ToolAxisMove> out;
    for (const toolpath::Record& r : tp.records())
        if (const auto* m = std::get_if<toolpath::ToolAxisMove>(&r))
            out.push_back(*m);
    return out;
}

std::string computeError(const document::Job& job)
{
    auto r = document::computeOperation(job, kSwarf, fiveAxis().model);
    return r.ok() ? std::string("ok") : r.error().message;
}

}  // namespace

TEST(FiveAxisSwarf, TheToolsSideFollowsTheConeAllRound)
{
    const document::Operation& op = fiveAxis().job.operations[kSwarf];
    ASSERT_EQ(op.kind(), document::OperationKind::Swarf);
    auto result = document::computeOperation(fiveAxis().job, kSwarf, fiveAxis().model);
    ASSERT_TRUE(result.ok()) << result.error().toString();
    const auto* begin = std::get_if<toolpath::SectionBegin>(&result->toolpath.record(0));
    ASSERT_NE(begin, nullptr);
    EXPECT_EQ(begin->strategy, "swarf");
    // The boss: axis along the +X face's normal through the face 14 mm along +Y, R5.5 at the face,
    // 15 degrees draft. The tool axis lies on the cone's rulings, 3 mm (the radius) off the cone.
    const Vec3 n{0.5, 0, std::sqrt(3.0) / 2};
    const Vec3 centre{40 - 7.5 / std::tan(kPi / 6), 14, 27.5};
    double minAzimuth = 1e9, maxAzimuth = -1e9, minTilt = 1e9, maxTilt = -1e9;
    int cuts = 0;
    for (const toolpath::ToolAxisMove& m : moves(result->toolpath)) {
        if (m.feedMmPerMin != 500)
            continue;
        ++cuts;
        EXPECT_NEAR(std::acos(m.axis.dot(n)) * 180 / kPi, 15, 1e-6);
        const Vec3 d = m.tip - centre;
        EXPECT_NEAR(d.dot(n), 3 * std::sin(15 * kPi / 180), 1e-6);  // the tip lifted by the normal's tilt
        // Out from the boss' axis: its radius at the face plus the tool's radius along the normal.
        EXPECT_NEAR((d - n * d.dot(n)).length(), 5.5 + 3 * std::cos(15 * kPi / 180), 1e-6);
        const double azimuth = std::atan2(m.axis.y, m.axis.x);
        minAzimuth = std::min(minAzimuth, azimuth);
        minTilt = std::min(minTilt, std::acos(m.axis.z));
        maxTilt = std::max(maxTilt, std::acos(m.axis.z));
        maxAzimuth = std::max(maxAzimuth, azimuth);
    }
    EXPECT_GT(cuts, 50);
    // The axis swings 31.2 degrees either side of +X (C turns: asin(sin 15 / sin 30)) and tilts
    // between 15 and 45 degrees from Z (B).
    const double swing = std::asin(std::sin(15 * kPi / 180) / std::sin(30 * kPi / 180));
    EXPECT_NEAR(minAzimuth, -swing, 1e-3);
    EXPECT_NEAR(maxAzimuth, swing, 1e-3);
    EXPECT_NEAR(minTilt * 180 / kPi, 15, 0.05);
    EXPECT_NEAR(maxTilt * 180 / kPi, 45, 0.05);
}

TEST(FiveAxisSwarf, ATipForcedIntoTheFaceBelowIsAGougeNamedByFaceAndPlace)
{
    document::Job job = fiveAxis().job;
    std::get<ops::SwarfParams>(job.operations[kSwarf].params).axialOffsetMm = -0.5;
    const std::string message = computeError(job);
    // The +X inclined face (the largest face with that normal).
    int inclined = 0;
    double area = 0;
    for (int i = 1; i <= fiveAxis().model.faceCount(); ++i) {
        const occ::FaceInfo f = fiveAxis().model.face(i);
        if (f.planar && distance(f.normal, Vec3{0.5, 0, std::sqrt(3.0) / 2}) < 1e-9 && f.areaMm2 > area) {
            inclined = i;
            area = f.areaMm2;
        }
    }
    EXPECT_EQ(message.rfind("swarf \"Drafted boss, tool side on its cone\": the tool gouges face " +
                                std::to_string(inclined) + " by more than 0.01 mm at (",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("on the move to ("), std::string::npos) << message;
    // Within the tolerance the same offset passes.
    std::get<ops::SwarfParams>(job.operations[kSwarf].params).axialOffsetMm = -0.005;
    EXPECT_EQ(computeError(job), "ok");
    // Swarf along the +X inclined face itself, the tool lying on it up the slope: it runs into the
    // drafted boss standing on that face (face 1, its cone, is the first it meets).
    job = fiveAxis().job;
    job.operations[kSwarf].geometry.faces = {inclined};
    for (ops::ToolController& tc : job.tools)
        tc.tool.fluteLengthMm = 32;  // the face is 30 mm up the slope
    const std::string boss = computeError(job);
    EXPECT_EQ(boss.rfind(
                  "swarf \"Drafted boss, tool side on its cone\": the tool gouges face 1 by more than 0.01 mm at (", 0),
              0u)
        << boss;
}

TEST(FiveAxisSwarf, AFaceThatIsNotRuledOrAPlaneIsRefused)
{
    document::Job job = fiveAxis().job;
    int sphere = 0;
    for (int i = 1; i <= fiveAxis().model.faceCount() && sphere == 0; ++i) {
        auto face = fiveAxis().model.swarfFace(i);
        if (!face.ok() && face.error().message.find("sphere") != std::string::npos)
            sphere = i;
    }
    ASSERT_GT(sphere, 0);
    job.operations[kSwarf].geometry.faces = {sphere};
    EXPECT_EQ(computeError(job), "swarf \"Drafted boss, tool side on its cone\": face " + std::to_string(sphere) +
                                     " is a sphere, not a ruled developable surface: swarf milling follows planes, "
                                     "cylinders, cones and linear extrusions");
    job.operations[kSwarf].geometry.faces = {1, 2};
    EXPECT_EQ(computeError(job),
              "swarf \"Drafted boss, tool side on its cone\": follows one ruled face: select exactly one face (2 "
              "selected)");
    job = fiveAxis().job;
    job.operations[kSwarf].plane = {document::WorkingPlaneSpec::Mode::Angles, 0, 0, 30, 0};
    EXPECT_NE(computeError(job).find("takes no working plane"), std::string::npos);
}

TEST(FiveAxisSwarf, ParametersRoundTripThroughTheJobFile)
{
    document::Job job = withBoxStock(fiveAxis().job);  // the version the swarf operation needs
    ops::SwarfParams& p = std::get<ops::SwarfParams>(job.operations[kSwarf].params);
    p.climb = false;
    p.axialOffsetMm = 0.25;
    p.radialStockMm = 0.1;
    p.radialPasses = 3;
    p.radialStepoverMm = 0.4;
    p.chordToleranceMm = 0.002;
    p.angleToleranceDeg = 0.5;
    p.gougeToleranceMm = 0.02;
    job.operations[kSwarf].geometry.edges = {7};
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"type\": \"swarf\""), std::string::npos);
    EXPECT_NE(text.find("\"version\": 5"), std::string::npos);
    auto back = document::parseJob(text, "swarf.camwb");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    const ops::SwarfParams& q = std::get<ops::SwarfParams>(back->operations[kSwarf].params);
    EXPECT_EQ(q.climb, false);
    EXPECT_EQ(q.axialOffsetMm, 0.25);
    EXPECT_EQ(q.radialStockMm, 0.1);
    EXPECT_EQ(q.radialPasses, 3);
    EXPECT_EQ(q.radialStepoverMm, 0.4);
    EXPECT_EQ(q.chordToleranceMm, 0.002);
    EXPECT_EQ(q.angleToleranceDeg, 0.5);
    EXPECT_EQ(q.gougeToleranceMm, 0.02);
    EXPECT_EQ(back->operations[kSwarf].geometry.edges, std::vector<int>{7});
    EXPECT_EQ(document::serializeJob(back.value()), text);
    // A wrong value names its place.
    std::string bad = text;
    bad.replace(bad.find("\"radialPasses\": 3"), 17, "\"radialPasses\": \"x\"");
    auto refused = document::parseJob(bad, "bad.camwb");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().toString().find("operations[2].params.radialPasses"), std::string::npos)
        << refused.error().toString();
}
