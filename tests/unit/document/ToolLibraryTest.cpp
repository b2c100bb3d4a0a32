// The tool library: its file (round trip, errors naming file and field), the shipped default
// library, the FreeCAD and Fusion 360 importers on sample files, adding tools to a job, the job's
// material and tools' cutting data in the job file, and the feeds and speeds computed from them.
#include "document/ToolLibrary.h"
#include "document/CuttingData.h"
#include "document/JobFile.h"
#include "document/ToolLibraryImport.h"

#include "base/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

using namespace camwb;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/tools";
const std::string kDefault = std::string(CAMWB_TEST_DATA_DIR) + "/resources/tools/default.camwb-tools.json";

ops::ToolController endMill()
{
    ops::ToolController tc;
    tc.tool = {1, "Flat D10", "flat", 10.0, 0.0, 22.0, 50.0, 3};
    tc.tool.holder = "SK40 ER32";
    tc.cuttingData = {{"aluminium", 250, 0.06, 0.3, 0.5}, {"steel", 100, 0.04, 0, 0}};
    return tc;
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

const ops::ToolController* byNumber(const document::ToolLibrary& library, int number)
{
    for (const auto& tc : library.tools)
        if (tc.tool.number == number)
            return &tc;
    return nullptr;
}

}  // namespace

TEST(ToolLibrary, SerializeParseRoundTripKeepsEveryField)
{
    document::ToolLibrary library{"Shop", {endMill()}};
    library.tools[0].spindleRpm = 8000;
    const std::string text = document::serializeToolLibrary(library);
    EXPECT_NE(text.find("\"format\": \"camwb-tools\""), std::string::npos);
    auto back = document::parseToolLibrary(text, "shop.json");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_EQ(back->name, "Shop");
    ASSERT_EQ(back->tools.size(), 1u);
    EXPECT_EQ(back->tools[0].tool.holder, "SK40 ER32");
    EXPECT_EQ(back->tools[0].cuttingData, library.tools[0].cuttingData);
    EXPECT_DOUBLE_EQ(back->tools[0].spindleRpm, 8000);
    EXPECT_EQ(document::serializeToolLibrary(back.value()), text);
}

TEST(ToolLibrary, ErrorsNameTheFileAndTheField)
{
    const std::string text = document::serializeToolLibrary({"Shop", {endMill()}});
    auto bad = document::parseToolLibrary(replaced(text, "\"fz\": 0.06", "\"fz\": \"fast\""), "shop.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().file, "shop.json");
    EXPECT_NE(bad.error().message.find("library.tools[0].cuttingData[0].fz"), std::string::npos) << bad.error().message;
    // An integer beyond int's range is refused, not wrapped round to some other count.
    auto many = document::parseToolLibrary(replaced(text, "\"flutes\": 3", "\"flutes\": 4294967299"), "shop.json");
    ASSERT_FALSE(many.ok());
    EXPECT_NE(many.error().message.find("library.tools[0].flutes: 4294967299 is out of range"), std::string::npos)
        << many.error().message;
    auto newer = document::parseToolLibrary(replaced(text, "\"version\": 1", "\"version\": 7"), "shop.json");
    ASSERT_FALSE(newer.ok());
    EXPECT_NE(newer.error().message.find("newer"), std::string::npos);
}

TEST(ToolLibrary, CorruptFileGivesLineAndLeavesTheFileAlone)
{
    const std::string path = kData + "/corrupt.camwb-tools.json";
    const std::string before = base::readTextFile(path).value();
    auto library = document::loadToolLibrary(path);
    ASSERT_FALSE(library.ok());
    EXPECT_EQ(library.error().file, path);
    EXPECT_GT(library.error().line, 0) << library.error().toString();
    EXPECT_EQ(base::readTextFile(path).value(), before);
}

TEST(ToolLibrary, SaveIsAtomicAndReadsBack)
{
    const fs::path dir = fs::temp_directory_path() / "camwb-toollib-test";
    fs::create_directories(dir);
    const std::string path = (dir / "tools.camwb-tools.json").string();
    ASSERT_TRUE(document::saveToolLibrary({"Mine", {endMill()}}, path).ok());
    auto back = document::loadToolLibrary(path);
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_EQ(back->tools[0].tool.name, "Flat D10");
    fs::remove_all(dir);
}

TEST(ToolLibrary, DefaultLibraryHasTheExampleJobsToolsWithCuttingData)
{
    auto library = document::loadToolLibrary(kDefault);
    ASSERT_TRUE(library.ok()) << library.error().toString();
    for (const std::string example : {"example-block.camwb", "example-five-axis.camwb"}) {
        auto job = document::loadJob(std::string(CAMWB_TEST_DATA_DIR) + "/resources/examples/" + example);
        ASSERT_TRUE(job.ok()) << job.error().toString();
        for (const ops::ToolController& tc : job->tools) {
            const auto same = std::find_if(library->tools.begin(), library->tools.end(), [&](const auto& lib) {
                return lib.tool.name == tc.tool.name && lib.tool.diameterMm == tc.tool.diameterMm &&
                       lib.tool.flutes == tc.tool.flutes && lib.tool.kind == tc.tool.kind;
            });
            EXPECT_NE(same, library->tools.end()) << example << ": " << tc.tool.name;
        }
    }
    for (const ops::ToolController& tc : library->tools) {
        EXPECT_TRUE(document::cuttingDataFor(tc, "Aluminium")) << tc.tool.name;
        EXPECT_TRUE(document::cuttingDataFor(tc, "steel")) << tc.tool.name;
    }
}

TEST(ToolLibraryImport, FreeCadLibraryResolvesBitsAndReadsUnits)
{
    auto imported = document::importToolLibrary(kData + "/freecad/Library/shop.fctl");
    ASSERT_TRUE(imported.ok()) << imported.error().toString();
    const document::ToolLibrary& library = imported->library;
    ASSERT_EQ(library.tools.size(), 4u) << "the probe is left out";
    ASSERT_EQ(imported->notes.size(), 1u);
    EXPECT_NE(imported->notes[0].find("Probe"), std::string::npos) << imported->notes[0];

    const ops::ToolController* mill = byNumber(library, 1);
    ASSERT_TRUE(mill);
    EXPECT_EQ(mill->tool.kind, "flat");
    EXPECT_DOUBLE_EQ(mill->tool.diameterMm, 6);
    EXPECT_DOUBLE_EQ(mill->tool.fluteLengthMm, 18);
    EXPECT_DOUBLE_EQ(mill->tool.lengthMm, 50);
    EXPECT_EQ(mill->tool.flutes, 3) << "Flutes from \"attribute\"";

    const ops::ToolController* drill = byNumber(library, 2);
    ASSERT_TRUE(drill) << "a bare file name is looked for in ../Bit";
    EXPECT_EQ(drill->tool.kind, "drill");
    EXPECT_DOUBLE_EQ(drill->tool.pointAngleDeg, 118);

    const ops::ToolController* bull = byNumber(library, 3);
    ASSERT_TRUE(bull);
    EXPECT_EQ(bull->tool.kind, "bull");
    EXPECT_DOUBLE_EQ(bull->tool.cornerRadiusMm, 1.5) << "D/2 - FlatRadius";

    const ops::ToolController* ball = byNumber(library, 4);
    ASSERT_TRUE(ball);
    EXPECT_DOUBLE_EQ(ball->tool.diameterMm, 0.3125 * 25.4) << "inches converted";
    EXPECT_DOUBLE_EQ(ball->tool.cornerRadiusMm, ball->tool.diameterMm / 2);
    EXPECT_EQ(ball->tool.flutes, 2) << "Flutes given as text";
}

TEST(ToolLibraryImport, FreeCadErrorsNameTheBitFileAndField)
{
    const std::string lib = kData + "/freecad/Library/bad-bit.fctl";
    auto bad = document::importToolLibrary(lib);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().file, lib);
    EXPECT_NE(bad.error().message.find("library.tools[1]"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("bad_diameter.fctb"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("Diameter"), std::string::npos) << bad.error().message;

    // from_chars reads "inf" and "nan" as numbers: a length of "inf mm" is no quantity either.
    const fs::path dir = fs::temp_directory_path() / "camwb_tool_import_inf";
    fs::create_directories(dir / "Bit");
    fs::create_directories(dir / "Library");
    std::ofstream(dir / "Bit" / "endless.fctb") << R"({"version": 2, "name": "Endless", "shape": "endmill.fcstd",
        "parameter": {"Diameter": "6 mm", "Length": "inf mm"}, "attribute": {}})";
    std::ofstream(dir / "Library" / "endless.fctl") << R"({"tools": [{"nr": 1, "path": "../Bit/endless.fctb"}]})";
    auto endless = document::importToolLibrary((dir / "Library" / "endless.fctl").string());
    ASSERT_FALSE(endless.ok());
    EXPECT_NE(endless.error().message.find("Length: expected a quantity such as \"6.00 mm\", got \"inf mm\""),
              std::string::npos)
        << endless.error().message;

    // A flute count is a whole number: 1e30 would not fit an int (converting it is undefined).
    for (const char* flutes : {"1e30", "2.5", "-1"}) {
        std::ofstream(dir / "Bit" / "endless.fctb") << R"({"version": 2, "name": "Many", "shape": "endmill.fcstd",
            "parameter": {"Diameter": "6 mm", "Flutes": ")"
                                                    << flutes << R"("}, "attribute": {}})";
        auto many = document::importToolLibrary((dir / "Library" / "endless.fctl").string());
        ASSERT_FALSE(many.ok()) << flutes;
        EXPECT_NE(many.error().message.find("Flutes: expected a whole number from 0 to 2147483647"), std::string::npos)
            << many.error().message;
    }
    fs::remove_all(dir);

    auto missing = document::importToolLibrary(kData + "/freecad/Library/missing-bit.fctl");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("no_such_bit.fctb"), std::string::npos) << missing.error().message;
}

TEST(ToolLibraryImport, FusionLibraryKeepsGeometryNumbersAndCuttingData)
{
    auto imported = document::importToolLibrary(kData + "/fusion/shop.json");
    ASSERT_TRUE(imported.ok()) << imported.error().toString();
    const document::ToolLibrary& library = imported->library;
    ASSERT_EQ(library.tools.size(), 3u) << "the probe is left out";
    EXPECT_EQ(imported->notes.size(), 1u);

    const ops::ToolController* mill = byNumber(library, 11);
    ASSERT_TRUE(mill) << "the post-process number is the tool number";
    EXPECT_EQ(mill->tool.name, "10mm 3FL flat");
    EXPECT_EQ(mill->tool.kind, "flat");
    EXPECT_DOUBLE_EQ(mill->tool.diameterMm, 10);
    EXPECT_EQ(mill->tool.flutes, 3);
    EXPECT_DOUBLE_EQ(mill->tool.fluteLengthMm, 22);
    EXPECT_DOUBLE_EQ(mill->tool.lengthMm, 72);
    EXPECT_EQ(mill->tool.holder, "BT30 ER32 70");
    ASSERT_EQ(mill->cuttingData.size(), 2u);
    EXPECT_EQ(mill->cuttingData[0].material, "aluminum");
    EXPECT_DOUBLE_EQ(mill->cuttingData[0].vcMPerMin, 250);
    EXPECT_DOUBLE_EQ(mill->cuttingData[0].fzMm, 0.06);
    EXPECT_NEAR(mill->cuttingData[0].plungeFraction, 430.0 / 1432.0, 1e-12);
    EXPECT_DOUBLE_EQ(mill->spindleRpm, 7958) << "the first preset's speeds are the tool's";
    EXPECT_DOUBLE_EQ(mill->cuttingFeedMmPerMin, 1432);

    const ops::ToolController* drill = byNumber(library, 12);
    ASSERT_TRUE(drill);
    EXPECT_DOUBLE_EQ(drill->tool.pointAngleDeg, 118);
    ASSERT_EQ(drill->cuttingData.size(), 1u);
    EXPECT_NEAR(drill->cuttingData[0].vcMPerMin, 2800 * std::numbers::pi * 6.8 / 1000, 1e-9) << "vc from n";
    EXPECT_NEAR(drill->cuttingData[0].fzMm, 300.0 / (2800 * 2), 1e-12) << "fz from v_f";

    const ops::ToolController* ball = byNumber(library, 13);
    ASSERT_TRUE(ball);
    EXPECT_DOUBLE_EQ(ball->tool.diameterMm, 6.35) << "inches converted";
    EXPECT_DOUBLE_EQ(ball->tool.cornerRadiusMm, 3.175);
    EXPECT_NEAR(ball->cuttingData[0].vcMPerMin, 785 * 0.3048, 1e-9) << "ft/min converted";
    EXPECT_NEAR(ball->cuttingData[0].fzMm, 0.002 * 25.4, 1e-12);
    EXPECT_DOUBLE_EQ(ball->cuttingFeedMmPerMin, 48 * 25.4);
}

TEST(ToolLibraryImport, FusionErrorsNameTheFileAndField)
{
    const std::string path = kData + "/fusion/bad-diameter.json";
    auto bad = document::importToolLibrary(path);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().file, path);
    EXPECT_NE(bad.error().message.find("library.data[1].geometry.DC"), std::string::npos) << bad.error().message;

    const fs::path many = fs::temp_directory_path() / "camwb_fusion_flutes.json";
    std::ofstream(many) << R"({"data": [{"type": "flat end mill", "unit": "millimeters",
        "geometry": {"DC": 10, "NOF": 1e30}, "post-process": {"number": 1}}], "version": 12})";
    auto flutes = document::importToolLibrary(many.string());
    fs::remove(many);
    ASSERT_FALSE(flutes.ok());
    EXPECT_NE(flutes.error().message.find("library.data[0].geometry.NOF: expected a whole number"), std::string::npos)
        << flutes.error().message;
}

// Fusion 360 exports its libraries as .tools: a zip holding tools.json. The JSON inside is read.
TEST(ToolLibraryImport, FusionToolsArchiveReadsTheJsonInside)
{
    auto zipped = document::importToolLibrary(kData + "/fusion/shop.tools");
    ASSERT_TRUE(zipped.ok()) << zipped.error().toString();
    auto plain = document::importToolLibrary(kData + "/fusion/shop.json");
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(document::serializeToolLibrary(zipped->library), document::serializeToolLibrary(plain->library));
    EXPECT_EQ(zipped->notes, plain->notes);
    ASSERT_EQ(zipped->library.tools.size(), 3u);
    EXPECT_EQ(byNumber(zipped->library, 11)->tool.holder, "BT30 ER32 70");
}

TEST(ToolLibraryImport, DamagedToolsArchiveIsAnErrorNamingTheFile)
{
    // One byte of the JSON changed after zipping (stored, so it still parses): only the
    // entry's checksum tells, and the import must not take the changed holder name.
    const std::string damaged = kData + "/fusion/damaged.tools";
    auto bad = document::importToolLibrary(damaged);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().file, damaged);
    EXPECT_NE(bad.error().message.find("'tools.json' in the zip archive is damaged (its checksum does not match)"),
              std::string::npos)
        << bad.error().message;

    auto none = document::importToolLibrary(kData + "/fusion/no-json.tools");
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("holds no .json file"), std::string::npos) << none.error().message;

    // Cut off half-way (a download that stopped): the zip's directory at its end is missing.
    const fs::path dir = fs::temp_directory_path() / ("camwb-tools-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto whole = base::readTextFile(kData + "/fusion/shop.tools");
    ASSERT_TRUE(whole.ok());
    const std::string cut = (dir / "cut.tools").string();
    ASSERT_TRUE(base::writeFileAtomically(cut, whole->substr(0, whole->size() / 2)));
    auto truncated = document::importToolLibrary(cut);
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().file, cut);
    EXPECT_NE(truncated.error().message.find("not a zip archive that can be read"), std::string::npos)
        << truncated.error().message;
    fs::remove_all(dir);
}

TEST(ToolLibraryImport, ImportedToolsExportToOurFormat)
{
    auto imported = document::importToolLibrary(kData + "/fusion/shop.json");
    ASSERT_TRUE(imported.ok());
    auto back = document::parseToolLibrary(document::serializeToolLibrary(imported->library), "x.json");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    ASSERT_EQ(back->tools.size(), imported->library.tools.size());
    EXPECT_EQ(back->tools[0].cuttingData, imported->library.tools[0].cuttingData);
}

TEST(ToolLibrary, AddingToAJobTakesTheNextFreeNumberAndSaysSo)
{
    document::Job job;
    job.tools.push_back(endMill());
    ops::ToolController other = endMill();
    other.tool.name = "Other";
    const auto notes = document::addToolsToJob(job, {other});
    ASSERT_EQ(job.tools.size(), 2u);
    EXPECT_EQ(job.tools[1].tool.number, 2);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("added as T2"), std::string::npos) << notes[0];
    EXPECT_EQ(job.tools[1].cuttingData, other.cuttingData) << "copied with its cutting data";
}

TEST(ToolLibrary, JobKeepsMaterialAndCuttingDataAsVersionSix)
{
    document::Job job;
    job.name = "J";
    job.tools.push_back(endMill());
    job.tools[0].spindleRpm = 1000;
    const std::string without = [&] {
        document::Job plain = job;
        plain.tools[0].cuttingData.clear();
        return document::serializeJob(plain);
    }();
    EXPECT_EQ(without.find("\"version\": 6"), std::string::npos) << "older files stay older";
    job.material = "aluminium";
    const std::string text = document::serializeJob(job);
    EXPECT_NE(text.find("\"version\": 6"), std::string::npos);
    EXPECT_NE(text.find("\"material\": \"aluminium\""), std::string::npos);
    auto back = document::parseJob(text, "j.camwb");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    EXPECT_EQ(back->material, "aluminium");
    EXPECT_EQ(back->tools[0].cuttingData, job.tools[0].cuttingData);
}

TEST(CuttingData, SpindleSpeedAndFeedsFromVcAndFz)
{
    const ops::ToolController tc = endMill();
    auto feeds = document::feedsFor(tc, "ALUMINIUM", nullptr);
    ASSERT_TRUE(feeds.ok()) << feeds.error().toString();
    // n = 250·1000/(π·10) = 7957.7 → 7958; vf = 0.06·3·7958 = 1432.4 → 1432.
    EXPECT_DOUBLE_EQ(feeds->spindleRpm, 7958);
    EXPECT_DOUBLE_EQ(feeds->cuttingFeedMmPerMin, 1432);
    EXPECT_DOUBLE_EQ(feeds->plungeFeedMmPerMin, std::round(1432 * 0.3));
    EXPECT_DOUBLE_EQ(feeds->rampFeedMmPerMin, 716);
    EXPECT_TRUE(feeds->notes.empty());

    auto steel = document::feedsFor(tc, "steel", nullptr);
    ASSERT_TRUE(steel.ok());
    EXPECT_DOUBLE_EQ(steel->spindleRpm, 3183);
    EXPECT_DOUBLE_EQ(steel->plungeFeedMmPerMin, std::round(steel->cuttingFeedMmPerMin * 0.5)) << "default half";
    EXPECT_DOUBLE_EQ(steel->rampFeedMmPerMin, 0) << "none given: the cutting feed";
}

TEST(CuttingData, MachineSpindleMaximumClampsSpeedAndFeedAndSaysSo)
{
    kinematics::Machine machine;
    machine.spindleMaxRpm = 5000;
    auto feeds = document::feedsFor(endMill(), "aluminium", &machine);
    ASSERT_TRUE(feeds.ok());
    EXPECT_DOUBLE_EQ(feeds->spindleRpm, 5000);
    EXPECT_DOUBLE_EQ(feeds->cuttingFeedMmPerMin, 900) << "fz kept: 0.06 · 3 · 5000";
    ASSERT_EQ(feeds->notes.size(), 1u);
    EXPECT_NE(feeds->notes[0].find("7958 rpm is above the machine's spindle maximum"), std::string::npos)
        << feeds->notes[0];
}

TEST(CuttingData, MissingMaterialOrDataIsAnError)
{
    auto none = document::feedsFor(endMill(), "", nullptr);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("no stock material"), std::string::npos);
    auto titanium = document::feedsFor(endMill(), "titanium", nullptr);
    ASSERT_FALSE(titanium.ok());
    EXPECT_NE(titanium.error().message.find("it has: aluminium, steel"), std::string::npos) << titanium.error().message;
    ops::ToolController flat = endMill();
    flat.tool.diameterMm = 0;
    EXPECT_FALSE(document::feedsFor(flat, "steel", nullptr).ok());
}

TEST(CuttingData, JobFeedsSkipToolsWithoutDataAndFailWhole)
{
    document::Job job;
    job.material = "aluminium";
    job.tools.push_back(endMill());
    ops::ToolController plain;
    plain.tool = {2, "Plain D6", "flat", 6.0, 0.0, 15.0, 40.0, 2};
    plain.spindleRpm = 1234;
    job.tools.push_back(plain);

    document::Job one = job;
    auto refused = document::computeJobFeeds(one, 2, nullptr);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("T2"), std::string::npos) << refused.error().message;
    EXPECT_EQ(document::serializeJob(one), document::serializeJob(job)) << "unchanged on error";

    auto notes = document::computeJobFeeds(job, 0, nullptr);
    ASSERT_TRUE(notes.ok()) << notes.error().toString();
    EXPECT_DOUBLE_EQ(job.tools[0].spindleRpm, 7958);
    EXPECT_DOUBLE_EQ(job.tools[1].spindleRpm, 1234);
    ASSERT_EQ(notes->size(), 1u);
    EXPECT_NE(notes->front().find("left as it was"), std::string::npos) << notes->front();

    document::Job steelless = job;
    steelless.material = "titanium";
    EXPECT_FALSE(document::computeJobFeeds(steelless, 0, nullptr).ok());
}
