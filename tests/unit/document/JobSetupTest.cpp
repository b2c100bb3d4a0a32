// The job setup fields of format version 6: the stock's shape and "from model" rule, the work
// origin (the model and so the NC moved by -origin) and the default NC output path.
#include "document/JobSetup.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "post/PostRegistry.h"

#include "ExampleJob.h"

#include <gtest/gtest.h>

#include <regex>

using namespace camwb;
using document::Job;
using document::Stock;
using document::test::example;

namespace {

// The posted NC of `job` on `model` (the job's post, machine and properties).
std::string postedNc(const Job& job, const occ::Model& model)
{
    auto program = document::computeProgram(job, model);
    EXPECT_TRUE(program) << program.error().toString();
    auto processor = document::loadJobPost(job, post::defaultPostDirs());
    EXPECT_TRUE(processor) << processor.error().toString();
    post::PostContext context;
    context.outputName = "SETUP";
    auto options = document::jobRunOptions(job, processor.value(), context, kinematics::defaultMachineDirs());
    EXPECT_TRUE(options) << options.error().toString();
    auto out = processor.value().run(program.value(), options.value());
    EXPECT_TRUE(out) << out.error().toString();
    return out ? out->text : std::string();
}

// Every value of the address `letter` (X, Z) in the program, in order.
std::vector<double> words(const std::string& nc, char letter)
{
    std::vector<double> values;
    const std::regex word(std::string(R"((?:^|\s))") + letter + R"((-?[0-9]*\.?[0-9]+)(?=\s|$))");
    for (std::sregex_iterator it(nc.begin(), nc.end(), word), end; it != end; ++it)
        values.push_back(std::stod((*it)[1].str()));
    return values;
}

}  // namespace

TEST(JobSetup, SetupFieldsRoundTripAsVersion6)
{
    Job job = example().job;
    EXPECT_EQ(document::serializeJob(job).find("\"version\": 6"), std::string::npos) << "no v6 field used";
    job.stock.shape = Stock::Shape::Cylinder;
    job.stock.fromModel = document::StockFromModel{{1, 2, 0}, {3, 4, 2.5}};
    job.origin = {10, -5, 16};
    job.outputName = "PART1";
    job.outputFolder = "nc";
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"version\": 6"), std::string::npos);
    auto reread = document::parseJob(text, "setup.camwb");
    ASSERT_TRUE(reread) << reread.error().toString();
    EXPECT_EQ(reread->stock, job.stock);
    EXPECT_EQ(reread->origin, job.origin);
    EXPECT_EQ(reread->outputName, "PART1");
    EXPECT_EQ(reread->outputFolder, "nc");
    EXPECT_EQ(document::serializeJob(reread.value()), text);

    // Each field alone makes the file version 6.
    Job origin = example().job;
    origin.origin = {0, 0, 1};
    EXPECT_NE(document::serializeJob(origin).find("\"version\": 6"), std::string::npos);
}

TEST(JobSetup, BadStockShapeIsNamed)
{
    Job job = example().job;
    job.stock.shape = Stock::Shape::Cylinder;
    std::string text = document::serializeJob(job);
    text.replace(text.find("\"cylinder\""), 10, "\"sphere\"");
    auto parsed = document::parseJob(text, "bad.camwb");
    ASSERT_FALSE(parsed);
    EXPECT_NE(parsed.error().message.find("stock.shape"), std::string::npos) << parsed.error().message;
}

TEST(JobSetup, StockFromModelFollowsTheBoundsAndCylinderIsSquare)
{
    Stock stock;
    stock.min = {-100, -100, -100};  // stale: replaced by the resolution
    stock.fromModel = document::StockFromModel{{2, 2, 0}, {2, 2, 1}};
    stock.resolve({0, 0, 0}, {90, 60, 15});
    EXPECT_EQ(stock.min, (base::Vec3{-2, -2, 0}));
    EXPECT_EQ(stock.max, (base::Vec3{92, 62, 16}));

    stock.shape = Stock::Shape::Cylinder;
    stock.resolve({0, 0, 0}, {90, 60, 15});
    EXPECT_DOUBLE_EQ(stock.max.x - stock.min.x, 94);
    EXPECT_DOUBLE_EQ(stock.max.y - stock.min.y, 94);
    EXPECT_DOUBLE_EQ((stock.min.y + stock.max.y) / 2, 30);

    Stock fixed;  // no rule: left as given
    fixed.min = {1, 1, 1};
    fixed.resolve({0, 0, 0}, {9, 9, 9});
    EXPECT_EQ(fixed.min, (base::Vec3{1, 1, 1}));
}

TEST(JobSetup, ResolveFromTheLoadedModelUsesWorkCoordinates)
{
    Job job = example().job;
    job.origin = {0, 0, 15};  // top of the block
    job.stock.fromModel = document::StockFromModel{{2, 2, 0}, {2, 2, 1}};
    auto model = document::loadJobModel(job);
    ASSERT_TRUE(model) << model.error().toString();
    document::resolveJobStock(job, model.value());
    EXPECT_NEAR(job.stock.max.z, example().model.boundsMax().z - 15 + 1, 1e-6);
    EXPECT_NEAR(job.stock.min.x, example().model.boundsMin().x - 2, 1e-6);
}

// Moving the origin translates the model without renumbering its faces and edges.
TEST(JobSetup, OriginKeepsFaceAndEdgeIndices)
{
    const occ::Model& raw = example().model;
    Job job = example().job;
    job.origin = {10, -3, 7};
    auto moved = document::loadJobModel(job);
    ASSERT_TRUE(moved) << moved.error().toString();
    ASSERT_EQ(moved->faceCount(), raw.faceCount());
    ASSERT_EQ(moved->edgeCount(), raw.edgeCount());
    for (int i = 1; i <= raw.edgeCount(); ++i) {
        const occ::EdgeInfo a = raw.edge(i), b = moved->edge(i);
        EXPECT_EQ(a.curve, b.curve) << "edge " << i;
        EXPECT_NEAR(b.start.x, a.start.x - 10, 1e-9) << "edge " << i;
        EXPECT_NEAR(b.start.y, a.start.y + 3, 1e-9) << "edge " << i;
        EXPECT_NEAR(b.start.z, a.start.z - 7, 1e-9) << "edge " << i;
    }
    for (int i = 1; i <= raw.faceCount(); ++i) {
        EXPECT_EQ(moved->face(i).planar, raw.face(i).planar) << "face " << i;
        EXPECT_NEAR(moved->face(i).areaMm2, raw.face(i).areaMm2, 1e-6) << "face " << i;
    }
}

// The origin is the program zero: the posted NC's X and Z words move by -origin (moveOrigin keeps
// the stock and the height overrides where they are on the part). The pocket is left out: its
// finishing pass picks where it enters the rings from the coordinates, so a shifted pocket may
// start its wall and island rings in another order (a path as good, not the same).
TEST(JobSetup, OriginShiftsThePostedProgram)
{
    Job job = example().job;
    std::erase_if(job.operations,
                  [](const document::Operation& op) { return op.kind() == document::OperationKind::Pocket; });
    ASSERT_EQ(job.operations.size(), 3u);
    const std::string before = postedNc(job, example().model);
    Job shifted = job;
    document::moveOrigin(shifted, {10, 0, 5});
    EXPECT_EQ(shifted.stock.min.x, job.stock.min.x - 10);
    EXPECT_EQ(shifted.operations[0].heights.clearanceZ, *job.operations[0].heights.clearanceZ - 5);
    auto model = document::loadJobModel(shifted);
    ASSERT_TRUE(model) << model.error().toString();
    const std::string after = postedNc(shifted, model.value());
    for (const auto& [letter, shift] : {std::pair{'X', 10.0}, std::pair{'Z', 5.0}}) {
        const std::vector<double> was = words(before, letter), is = words(after, letter);
        ASSERT_GT(was.size(), 10u);
        ASSERT_EQ(is.size(), was.size()) << letter;
        for (std::size_t i = 0; i < was.size(); ++i)
            EXPECT_NEAR(is[i], was[i] - shift, 1e-3) << letter << " word " << i;
    }
}

TEST(JobSetup, OutputPathIsRelativeToTheJobFile)
{
    Job job;
    EXPECT_EQ(document::jobOutputPath(job, "/jobs/a.camwb", "mpf"), "");
    job.outputName = "PART1";
    EXPECT_EQ(document::jobOutputPath(job, "/jobs/a.camwb", "mpf"), "/jobs/PART1.mpf");
    job.outputFolder = "../nc";
    job.outputName = "part.h";
    EXPECT_EQ(document::jobOutputPath(job, "/jobs/a.camwb", "mpf"), "/nc/part.h");
    job.outputFolder = "/abs/out";
    EXPECT_EQ(document::jobOutputPath(job, "/jobs/a.camwb", "mpf"), "/abs/out/part.h");
}

TEST(JobSetup, StockAnchorsAndMachineTravels)
{
    Stock stock;
    stock.min = {-2, -2, 0};
    stock.max = {92, 62, 16};
    EXPECT_EQ(document::stockAnchor(stock, document::StockAnchor::TopFrontLeft), (base::Vec3{-2, -2, 16}));
    EXPECT_EQ(document::stockAnchor(stock, document::StockAnchor::TopCentre), (base::Vec3{45, 30, 16}));
    EXPECT_EQ(document::stockAnchor(stock, document::StockAnchor::BottomCentre), (base::Vec3{45, 30, 0}));

    kinematics::Machine machine;
    machine.axes = {{"X", false, 0, 100}, {"Y", false, 0, 50}, {"Z", false, -200, 0}, {"C", true, -1e9, 1e9}};
    const std::vector<std::string> shortfalls = document::travelShortfalls(machine, stock);
    ASSERT_EQ(shortfalls.size(), 1u);
    EXPECT_EQ(shortfalls[0], "Y: stock 64 mm, travel 50 mm");
    stock.max.y = 40;
    EXPECT_TRUE(document::travelShortfalls(machine, stock).empty());
}
