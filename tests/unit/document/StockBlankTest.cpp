// The job's stock as a solid: a blank from a mesh or STEP file (format version 9, its path
// relative to the job file, a clear error when it cannot be read, its bounds as the stock's
// min/max), and a cylinder simulated as a cylinder rather than as its bounding box.
#include "document/StockBlank.h"
#include "base/AtomicFile.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "document/Simulate.h"
#include "occ/ExamplePart.h"
#include "occ/Model.h"
#include "sim/HeightField.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>

using namespace camwb;
using document::Job;
using document::Stock;
namespace fs = std::filesystem;

namespace {

const std::string kExamples = std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/";

fs::path scratch(const char* name)
{
    const fs::path dir = fs::temp_directory_path() / "camwb-stock-blank-test" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

Job blankJob(const fs::path& dir)
{
    Job job;
    job.name = "Blank";
    job.modelPath = (dir / "part.step").string();
    job.stock.shape = Stock::Shape::Blank;
    job.stock.blankPath = (dir / "blanks" / "cast.step").string();
    job.stock.min = {-40, -40, 0};
    job.stock.max = {40, 40, 40};
    return job;
}

}  // namespace

TEST(StockBlank, RoundTripsAsVersion9WithItsPathRelativeToTheJob)
{
    const fs::path dir = scratch("roundtrip");
    const Job job = blankJob(dir);
    const std::string path = (dir / "job.camwb").string();
    ASSERT_TRUE(document::saveJob(job, path).ok());
    const std::string text = document::serializeJob(document::parseJob(base::readTextFile(path).value(), path).value());
    EXPECT_NE(text.find("\"version\": 9"), std::string::npos) << text;
    EXPECT_NE(text.find("\"shape\": \"blank\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"blank\": \"blanks/cast.step\""), std::string::npos) << "relative in the file: " << text;
    auto back = document::loadJob(path);
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_EQ(back->stock, job.stock);  // absolute again in memory
    EXPECT_EQ(back->stock.blankPath, job.stock.blankPath);

    // Without a blank the job keeps its older version: a box or cylinder is version 3 or 6 still.
    Job box = job;
    box.stock.shape = Stock::Shape::Box;
    box.stock.blankPath.clear();
    EXPECT_EQ(document::serializeJob(box).find("\"version\": 9"), std::string::npos);
    EXPECT_EQ(document::serializeJob(box).find("\"blank\""), std::string::npos);
}

TEST(StockBlank, FileErrorsNameTheField)
{
    const fs::path dir = scratch("errors");
    const std::string text = document::serializeJob(blankJob(dir));
    const std::string withoutFile = std::regex_replace(text, std::regex(R"(,\s*"blank": "[^"]*")"), "");
    ASSERT_NE(withoutFile, text);
    auto noFile = document::parseJob(withoutFile, "cast.camwb");
    ASSERT_FALSE(noFile.ok());
    EXPECT_NE(noFile.error().toString().find("job.stock: missing \"blank\""), std::string::npos)
        << noFile.error().toString();

    std::string unknown = text;
    unknown.replace(unknown.find("\"blank\","), 7, "\"casting\"");
    auto badShape = document::parseJob(unknown, "cast.camwb");
    ASSERT_FALSE(badShape.ok());
    EXPECT_NE(badShape.error().toString().find("stock.shape"), std::string::npos) << badShape.error().toString();

    // A file newer than this build understands is refused, one it understands is read.
    std::string newer = text;
    newer.replace(newer.find("\"version\": 9"), 12, "\"version\": 10");
    EXPECT_FALSE(document::parseJob(newer, "cast.camwb").ok());
}

TEST(StockBlank, MissingOrUnreadableBlankNamesTheJobFileAndTheField)
{
    const fs::path dir = scratch("missing");
    const Job job = blankJob(dir);
    const std::string jobPath = (dir / "job.camwb").string();
    auto missing = document::loadStockBlank(job, jobPath);
    ASSERT_FALSE(missing.ok());
    const std::string message = missing.error().toString();
    EXPECT_EQ(missing.error().file, jobPath);
    EXPECT_NE(message.find("stock.blank"), std::string::npos) << message;
    EXPECT_NE(message.find("cast.step"), std::string::npos) << message;

    fs::create_directories(dir / "blanks");
    ASSERT_TRUE(base::writeFileAtomically(job.stock.blankPath, "ISO-10303-21;\nnot a step file\n").ok());
    auto unreadable = document::loadStockBlank(job, jobPath);
    ASSERT_FALSE(unreadable.ok());
    EXPECT_EQ(unreadable.error().file, jobPath);
    EXPECT_NE(unreadable.error().toString().find("stock.blank"), std::string::npos) << unreadable.error().toString();
}

// The five-axis example's blank: its bounds are the stock's min/max, in work coordinates.
TEST(StockBlank, TheBlankResolvesTheStockBoxInWorkCoordinates)
{
    auto job = document::loadJob(kExamples + "example-five-axis.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    ASSERT_EQ(job->stock.shape, Stock::Shape::Blank);
    job->origin = {0, 0, 40};  // the cap's top as Z0
    job->stock.min = job->stock.max = {};
    auto blank = document::loadStockBlank(job.value(), "example-five-axis.camwb");
    ASSERT_TRUE(blank.ok()) << blank.error().toString();
    document::resolveStockBlank(job->stock, blank.value());
    EXPECT_NEAR(job->stock.min.x, -40, 1e-3);
    EXPECT_NEAR(job->stock.max.y, 40, 1e-3);
    EXPECT_NEAR(job->stock.min.z, -40, 1e-3);
    EXPECT_NEAR(job->stock.max.z, 0, 1e-2);  // the cap's top, meshed
    // What the simulator cuts is the blank, not its box: less material than the box holds.
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok()) << model.error().toString();
    const sim::StockSpec spec = document::jobStockSpec(job.value(), model.value(), blank.value(), 0.5);
    EXPECT_FALSE(spec.box);
    const double boxVolume = 80.0 * 80 * 40;
    const double volume = sim::makeStock(spec, false).value()->volumeMm3();
    EXPECT_LT(volume, 0.9 * boxVolume);
    EXPECT_NEAR(volume, blank->volumeMm3(), 0.02 * blank->volumeMm3());
}

// The blank the generator makes is the committed one, byte for byte.
TEST(StockBlank, TheCommittedFiveAxisBlankIsWhatTheGeneratorWrites)
{
    const fs::path dir = scratch("generator");
    const std::string again = (dir / "example-five-axis-blank.step").string();
    ASSERT_TRUE(occ::writeFiveAxisExampleBlank(again).ok());
    const auto written = base::readTextFile(again),
               committed = base::readTextFile(kExamples + "example-five-axis-blank.step");
    ASSERT_TRUE(written.ok() && committed.ok());
    EXPECT_TRUE(written.value() == committed.value())
        << "resources/examples/example-five-axis-blank.step is not what the generator writes; regenerate it with "
           "camwb-make-example resources/examples/example-five-axis-blank.step five-axis-blank";
}

// A cylinder stock goes to the simulator as a cylinder: the corners of its box are air.
TEST(StockBlank, CylinderIsSimulatedAsACylinder)
{
    Job job;
    job.stock.shape = Stock::Shape::Cylinder;
    job.stock.min = {-10, -10, 0};
    job.stock.max = {10, 10, 30};
    const sim::StockSpec spec = document::jobStockSpec(job, occ::Model(), {}, 0.2);
    ASSERT_FALSE(spec.box);
    ASSERT_FALSE(spec.blank.empty());
    const double cylinder = std::numbers::pi * 10 * 10 * 30;
    for (const bool tilts : {false, true}) {
        const std::unique_ptr<sim::Stock> stock = sim::makeStock(spec, tilts).value();
        EXPECT_NEAR(stock->volumeMm3(), cylinder, 0.01 * cylinder) << (tilts ? "tri-dexel" : "height field");
    }
    const std::unique_ptr<sim::Stock> stock = sim::makeStock(spec, false).value();
    const auto* field = dynamic_cast<const sim::HeightField*>(stock.get());
    ASSERT_NE(field, nullptr);
    const int nx = field->columnsX(), ny = field->columnsY();
    for (const auto& [i, j] : {std::pair{0, 0}, {nx - 1, 0}, {0, ny - 1}, {nx - 1, ny - 1}})
        EXPECT_FALSE(field->top(i, j) > 0) << "corner column " << i << "," << j << " holds material";
    EXPECT_NEAR(field->top(nx / 2, ny / 2), 30, 1e-4) << "the centre is material to the top";
    // A box stays a box.
    job.stock.shape = Stock::Shape::Box;
    EXPECT_TRUE(document::jobStockSpec(job, occ::Model(), {}, 0.2).box);
}

// The five-axis example's drilling from its blank: a D6 drill in the model's D6 holes, its tip on
// their flat floors, on faces tilted 30 degrees. It touches the part and goes no deeper, so no
// gouge (the tri-dexel rays that run along a tilted floor once read the part's length as depth).
TEST(StockBlank, TheFiveAxisExamplesDrillingFromItsBlankGougesNothing)
{
    auto job = document::loadJob(kExamples + "example-five-axis.camwb");
    ASSERT_TRUE(job.ok()) << job.error().toString();
    for (std::size_t i = 1; i < job->operations.size(); ++i)
        job->operations[i].enabled = false;  // the four holes only
    auto model = document::loadJobModel(job.value());
    ASSERT_TRUE(model.ok()) << model.error().toString();
    auto blank = document::loadStockBlank(job.value(), "example-five-axis.camwb");
    ASSERT_TRUE(blank.ok()) << blank.error().toString();
    auto program = document::computeProgram(job.value(), model.value());
    ASSERT_TRUE(program.ok()) << program.error().toString();
    auto machine = document::jobMachine(job.value());
    ASSERT_TRUE(machine.ok() && machine.value()) << "the example names its machine";
    sim::StockSpec spec = document::jobStockSpec(job.value(), model.value(), blank.value(), 0.2);
    spec.design = document::designMesh(model.value());
    sim::SimulationSetup setup;
    setup.machine = &*machine.value();
    setup.stockSpec = &spec;
    const sim::SimulationResult result = sim::simulate(program.value(), setup);
    ASSERT_TRUE(result.cut && result.tilts);
    EXPECT_GT(result.removedMm3, 4 * 3.14159 * 9 * 5);  // four holes D6, at least 5 mm at full diameter
    for (const sim::Check& check : result.checks)
        EXPECT_NE(check.kind, sim::CheckKind::Gouge) << check.valueMm << " mm at record " << check.record;
}
