// Machine definitions: the shipped EMCO file, lookup by id and clear errors for bad files.
#include "kinematics/Machine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace camwb;

namespace {

const char* kMinimal = R"({"format": "camwb-machine", "version": 1, "id": "m", "name": "M", "control": "linuxcnc",
"axes": [{"name": "X", "type": "linear", "min": -10, "max": 10}]})";

std::string messageOf(const std::string& json)
{
    auto machine = kinematics::parseMachine(json, "m.json");
    EXPECT_FALSE(machine.ok()) << json;
    return machine.ok() ? std::string() : machine.error().toString();
}

}  // namespace

TEST(Machine, EmcoConceptMill105FromTheThesis)
{
    auto emco = kinematics::findMachine("emco-concept-mill-105", kinematics::defaultMachineDirs());
    ASSERT_TRUE(emco.ok()) << emco.error().toString();
    EXPECT_EQ(emco->name, "EMCO Concept MILL 105");
    EXPECT_EQ(emco->control, "sinumerik-828d");
    ASSERT_EQ(emco->axes.size(), 3u);
    const double travel[] = {200, 150, 250};  // seed-004 Tab. 11
    for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(emco->axes[i].rotary);
        EXPECT_EQ(emco->axes[i].max - emco->axes[i].min, travel[i]) << emco->axes[i].name;
    }
    EXPECT_EQ(emco->spindleMinRpm, 150);
    EXPECT_EQ(emco->spindleMaxRpm, 5000);
    EXPECT_EQ(emco->toolStations, 10);
    EXPECT_EQ(emco->maxToolDiameterMm, 55);
    EXPECT_EQ(emco->maxToolLengthMm, 50);
    EXPECT_TRUE(emco->hasCoolant("flood"));
    EXPECT_FALSE(emco->hasCoolant("mist"));
}

TEST(Machine, OptionalSectionsDefaultToUnlimited)
{
    auto m = kinematics::parseMachine(kMinimal, "m.json");
    ASSERT_TRUE(m.ok()) << m.error().toString();
    EXPECT_EQ(m->spindleMaxRpm, 0);
    EXPECT_EQ(m->toolStations, 0);
    EXPECT_TRUE(m->coolants.empty());
    ASSERT_NE(m->axis("X"), nullptr);
    EXPECT_EQ(m->axis("Y"), nullptr);
    EXPECT_EQ(m->filePath, "m.json");
}

TEST(Machine, BadFilesGiveClearErrors)
{
    EXPECT_EQ(messageOf("{\"format\": \"camwb-machine\",\n \"version\": }"),
              "m.json:2:13: malformed JSON: syntax error while parsing value - unexpected '}'; expected '[', '{', or a "
              "literal");
    EXPECT_EQ(messageOf(R"({"format": "camwb-job"})"),
              "m.json: not a CAM Workbench machine (format is not \"camwb-machine\")");
    EXPECT_EQ(messageOf(R"({"format": "camwb-machine", "version": 2})"),
              "m.json: machine format version 2 is not supported (this is 1)");
    std::string badAxis = kMinimal;
    badAxis.replace(badAxis.find("\"linear\""), 8, "\"spiral\"");
    EXPECT_EQ(messageOf(badAxis), "m.json: machine.axes[0].type: expected \"linear\" or \"rotary\"");
    std::string swapped = kMinimal;
    swapped.replace(swapped.find("\"min\": -10"), 10, "\"min\": 20");
    EXPECT_EQ(messageOf(swapped), "m.json: machine.axes[0]: min is above max");
    std::string coolant = kMinimal;
    coolant.insert(coolant.size() - 1, ", \"coolants\": [\"air\"]");
    EXPECT_EQ(messageOf(coolant), "m.json: machine.coolants: unknown coolant \"air\" (flood, mist, throughTool)");
}

TEST(Machine, LookupByIdWhereTheFileNameIsTheId)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("camwb-machines-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "m.json") << kMinimal;
    std::ofstream(dir / "other.json") << kMinimal;
    EXPECT_TRUE(kinematics::findMachine("m", {dir.string()}).ok());
    auto mismatch = kinematics::findMachine("other", {dir.string()});
    ASSERT_FALSE(mismatch.ok());
    EXPECT_NE(mismatch.error().message.find("the file name is the id"), std::string::npos);
    auto missing = kinematics::findMachine("nope", {"/nowhere", dir.string()});
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("/nowhere/nope.json"), std::string::npos);
    EXPECT_FALSE(kinematics::findMachine("../m", {dir.string()}).ok());
    std::filesystem::remove_all(dir);
}
