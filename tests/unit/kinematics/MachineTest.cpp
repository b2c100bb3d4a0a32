// Machine definitions: the shipped EMCO and MAS files, lookup by id and clear errors for bad files.
#include "kinematics/Machine.h"
#include "toolpath/ProgramStats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace camwb;

namespace {

const char* kMinimal = R"({"format": "camwb-machine", "version": 1, "id": "m", "name": "M", "control": "linuxcnc",
"axes": [{"name": "X", "type": "linear", "min": -10, "max": 10}]})";

// kMinimal with `axis` (a JSON object) as a second axis.
std::string withAxis(const std::string& axis)
{
    std::string json = kMinimal;
    json.insert(json.find("}]}") + 1, ", " + axis);
    return json;
}

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

// The lathe of seed-001 (§1): X (a radius) and Z only, no Y; the spindle limit is Kód 5's LIMS.
TEST(Machine, SkodaSr2000LatheHasXAndZOnly)
{
    auto lathe = kinematics::findMachine("skoda-sr2000-840d", kinematics::defaultMachineDirs());
    ASSERT_TRUE(lathe.ok()) << lathe.error().toString();
    EXPECT_EQ(lathe->control, "sinumerik-840d");
    ASSERT_EQ(lathe->axes.size(), 2u);
    EXPECT_EQ(lathe->axis("Y"), nullptr);
    ASSERT_NE(lathe->axis("X"), nullptr);
    ASSERT_NE(lathe->axis("Z"), nullptr);
    EXPECT_EQ(lathe->axis("X")->max - lathe->axis("X")->min, 1000);   // diameter over bed 2000 mm
    EXPECT_EQ(lathe->axis("Z")->max - lathe->axis("Z")->min, 10000);  // turning length 10000 mm
    EXPECT_EQ(lathe->spindleMaxRpm, 3000);
    EXPECT_TRUE(lathe->hasCoolant("flood"));
    EXPECT_FALSE(lathe->kinematics.fiveAxis());
}

TEST(Machine, MasMcvl1000FromTheThesis)
{
    auto mas = kinematics::findMachine("mas-mcvl1000", kinematics::defaultMachineDirs());
    ASSERT_TRUE(mas.ok()) << mas.error().toString();
    EXPECT_EQ(mas->control, "heidenhain-itnc530");
    const double travel[] = {1016, 610, 660};  // seed-000 §2.1
    for (int i = 0; i < 3; ++i) {
        ASSERT_NE(mas->axis(std::string(1, static_cast<char>('X' + i))), nullptr);
        EXPECT_FALSE(mas->axes[i].rotary);
        EXPECT_EQ(mas->axes[i].max - mas->axes[i].min, travel[i]) << mas->axes[i].name;
    }
    EXPECT_EQ(mas->spindleMinRpm, 20);
    EXPECT_EQ(mas->spindleMaxRpm, 7500);
    EXPECT_EQ(mas->minCuttingFeedMmPerMin, 2);
    EXPECT_EQ(mas->maxCuttingFeedMmPerMin, 12000);
    EXPECT_EQ(mas->rapidMmPerMin, 22000);  // 22 m/min: the thesis' "mm/min" is a typo
    EXPECT_TRUE(mas->manualToolChange);
    EXPECT_EQ(mas->toolStations, 0);
    EXPECT_TRUE(mas->hasCoolant("flood"));
    const kinematics::Axis* b = mas->axis("B");
    ASSERT_NE(b, nullptr);
    EXPECT_TRUE(b->rotary);
    EXPECT_FALSE(b->endless);
    EXPECT_EQ(b->min, -120);  // Sec. 3.2
    EXPECT_EQ(b->max, 30);
    EXPECT_DOUBLE_EQ(b->maxRpm, 11.1);
    const kinematics::Axis* c = mas->axis("C");
    ASSERT_NE(c, nullptr);
    EXPECT_TRUE(c->rotary && c->endless);
    EXPECT_TRUE(std::isinf(c->min) && c->min < 0 && std::isinf(c->max) && c->max > 0);
    EXPECT_DOUBLE_EQ(c->maxRpm, 22.2);
}

// The datasheet's guaranteed B stroke is the same machine with B -105..+15: nothing else may
// drift apart between the two files.
TEST(Machine, MasMcvl1000NikkenGuaranteedDiffersOnlyInB)
{
    auto thesis = kinematics::findMachine("mas-mcvl1000", kinematics::defaultMachineDirs());
    auto nikken = kinematics::findMachine("mas-mcvl1000-nikken-guaranteed", kinematics::defaultMachineDirs());
    ASSERT_TRUE(thesis.ok() && nikken.ok());
    const kinematics::Axis* b = nikken->axis("B");
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->min, -105);
    EXPECT_EQ(b->max, 15);
    kinematics::Machine same = nikken.value();
    same.id = thesis->id;
    same.name = thesis->name;
    same.filePath = thesis->filePath;
    ASSERT_EQ(same.axes.size(), thesis->axes.size());
    for (std::size_t i = 0; i < same.axes.size(); ++i) {
        const kinematics::Axis& x = same.axes[i];
        const kinematics::Axis& y = thesis->axes[i];
        EXPECT_TRUE(x.name == y.name && x.rotary == y.rotary && x.endless == y.endless && x.maxRpm == y.maxRpm &&
                    (x.name == "B" || (x.min == y.min && x.max == y.max)))
            << x.name;
    }
    EXPECT_TRUE(same.control == thesis->control && same.spindleMinRpm == thesis->spindleMinRpm &&
                same.spindleMaxRpm == thesis->spindleMaxRpm && same.manualToolChange == thesis->manualToolChange &&
                same.toolStations == thesis->toolStations && same.maxToolDiameterMm == thesis->maxToolDiameterMm &&
                same.maxToolLengthMm == thesis->maxToolLengthMm &&
                same.minCuttingFeedMmPerMin == thesis->minCuttingFeedMmPerMin &&
                same.maxCuttingFeedMmPerMin == thesis->maxCuttingFeedMmPerMin &&
                same.rapidMmPerMin == thesis->rapidMmPerMin && same.coolants == thesis->coolants);
}

TEST(Machine, EndlessRotaryAxis)
{
    auto m = kinematics::parseMachine(withAxis(R"({"name": "C", "type": "rotary", "endless": true})"), "m.json");
    ASSERT_TRUE(m.ok()) << m.error().toString();
    const kinematics::Axis* c = m->axis("C");
    ASSERT_NE(c, nullptr);
    EXPECT_TRUE(c->endless);
    EXPECT_LT(c->min, -1e300);  // any angle is inside
    EXPECT_GT(c->max, 1e300);
    EXPECT_FALSE(m->axis("X")->endless);
    auto limited = kinematics::parseMachine(
        withAxis(R"({"name": "B", "type": "rotary", "endless": false, "min": -5, "max": 5})"), "m.json");
    ASSERT_TRUE(limited.ok()) << limited.error().toString();
    EXPECT_FALSE(limited->axis("B")->endless);
    EXPECT_EQ(limited->axis("B")->max, 5);
}

TEST(Machine, RapidRateOfTheTimeEstimate)
{
    EXPECT_EQ(kinematics::estimateRapidMmPerMin(nullptr), toolpath::kDefaultRapidMmPerMin);
    kinematics::Machine m;
    EXPECT_EQ(kinematics::estimateRapidMmPerMin(&m), toolpath::kDefaultRapidMmPerMin);  // the file gives none
    m.rapidMmPerMin = 22000;
    EXPECT_EQ(kinematics::estimateRapidMmPerMin(&m), 22000);
}

TEST(Machine, OptionalSectionsDefaultToUnlimited)
{
    auto m = kinematics::parseMachine(kMinimal, "m.json");
    ASSERT_TRUE(m.ok()) << m.error().toString();
    EXPECT_EQ(m->spindleMaxRpm, 0);
    EXPECT_EQ(m->toolStations, 0);
    EXPECT_FALSE(m->manualToolChange);
    EXPECT_EQ(m->minCuttingFeedMmPerMin, 0);
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
    EXPECT_EQ(messageOf(R"({"format": "camwb-machine", "version": 3})"),
              "m.json: machine format version 3 is not supported (this is 2)");
    std::string badAxis = kMinimal;
    badAxis.replace(badAxis.find("\"linear\""), 8, "\"spiral\"");
    EXPECT_EQ(messageOf(badAxis), "m.json: machine.axes[0].type: expected \"linear\" or \"rotary\"");
    std::string swapped = kMinimal;
    swapped.replace(swapped.find("\"min\": -10"), 10, "\"min\": 20");
    EXPECT_EQ(messageOf(swapped), "m.json: machine.axes[0]: min is above max");
    std::string coolant = kMinimal;
    coolant.insert(coolant.size() - 1, ", \"coolants\": [\"air\"]");
    EXPECT_EQ(messageOf(coolant), "m.json: machine.coolants: unknown coolant \"air\" (flood, mist, throughTool)");

    EXPECT_EQ(messageOf(withAxis(R"({"name": "C", "type": "rotary", "endless": true, "min": 0, "max": 360})")),
              "m.json: machine.axes[1]: an endless axis has no min or max (drop them, or \"endless\")");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "C", "type": "rotary", "endless": true, "max": 360})")),
              "m.json: machine.axes[1]: an endless axis has no min or max (drop them, or \"endless\")");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "W", "type": "linear", "endless": true})")),
              "m.json: machine.axes[1]: a linear axis cannot be endless");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "C", "type": "rotary", "endless": "yes"})")),
              "m.json: machine.axes[1].endless: expected true or false");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "W", "type": "linear", "min": 0, "max": 9, "maxRpm": 5})")),
              "m.json: machine.axes[1].maxRpm: only a rotary axis has one (a linear axis' speed is feed.rapid)");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "B", "type": "rotary", "min": 0, "max": 9, "maxRpm": 0})")),
              "m.json: machine.axes[1].maxRpm: expected a speed above 0");
    std::string manual = kMinimal;
    manual.insert(manual.size() - 1, ", \"toolChanger\": {\"manual\": true, \"stations\": 8}");
    EXPECT_EQ(messageOf(manual), "m.json: machine.toolChanger: a manual tool change has no stations");
    std::string feeds = kMinimal;
    feeds.insert(feeds.size() - 1, ", \"feed\": {\"minCutting\": 50, \"maxCutting\": 20}");
    EXPECT_EQ(messageOf(feeds), "m.json: machine.feed: minCutting is above maxCutting");
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

namespace {

// A B/C machine in format version `version` with `chain` as its "kinematics".
std::string fiveAxis(const std::string& chain, int version = 2)
{
    return R"({"format": "camwb-machine", "version": )" + std::to_string(version) +
           R"(, "id": "m", "name": "M", "control": "c", "axes": [
{"name": "X", "type": "linear", "min": -10, "max": 10},
{"name": "B", "type": "rotary", "min": -90, "max": 90}, {"name": "C", "type": "rotary", "endless": true}],
"kinematics": )" +
           chain + "}";
}

const char* kTableTable = R"({"type": "table-table", "rotaries": [
{"axis": "B", "on": "table", "direction": [0, 2, 0], "pivot": [1, 2, 3]},
{"axis": "C", "on": "table", "direction": [0, 0, 1]}], "workpieceZero": [0, 0, 50],
"preferred": {"axis": "B", "sign": "negative"}})";

}  // namespace

TEST(Machine, KinematicChainOfVersion2)
{
    auto m = kinematics::parseMachine(fiveAxis(kTableTable), "m.json");
    ASSERT_TRUE(m.ok()) << m.error().toString();
    const kinematics::KinematicChain& k = m->kinematics;
    EXPECT_EQ(k.type, kinematics::ChainType::TableTable);
    ASSERT_EQ(k.joints.size(), 2u);
    EXPECT_EQ(k.joints[0].axis, "B");
    EXPECT_TRUE(k.joints[0].onTable);
    EXPECT_EQ(k.joints[0].direction, (base::Vec3{0, 1, 0}));  // normalised
    EXPECT_EQ(k.joints[0].pivot, (base::Vec3{1, 2, 3}));
    EXPECT_EQ(k.joints[1].pivot, (base::Vec3{}));
    EXPECT_EQ(k.workpieceZero, (base::Vec3{0, 0, 50}));
    EXPECT_EQ(k.preferredJoint, 0);
    EXPECT_EQ(k.preferredSign, -1);
    // A version 1 file with rotary axes is a three-axis chain, as it always was.
    auto v1 = kinematics::parseMachine(withAxis(R"({"name": "C", "type": "rotary", "endless": true})"), "m.json");
    ASSERT_TRUE(v1.ok()) << v1.error().toString();
    EXPECT_EQ(v1->kinematics.type, kinematics::ChainType::ThreeAxis);
    EXPECT_FALSE(v1->kinematics.fiveAxis());
}

TEST(Machine, BadKinematicChainsGiveClearErrors)
{
    EXPECT_EQ(messageOf(fiveAxis(kTableTable, 1)),
              "m.json: machine.kinematics: a kinematic chain needs format version 2");
    auto with = [](std::string from, const std::string& to) {
        std::string chain = kTableTable;
        chain.replace(chain.find(from), from.size(), to);
        return messageOf(fiveAxis(chain));
    };
    EXPECT_EQ(with("\"axis\": \"B\"", "\"axis\": \"A\""),
              "m.json: machine.kinematics.rotaries[0].axis: A is not a rotary axis of the machine's \"axes\"");
    EXPECT_EQ(with("\"axis\": \"B\"", "\"axis\": \"X\""),
              "m.json: machine.kinematics.rotaries[0].axis: X is not a rotary axis of the machine's \"axes\"");
    EXPECT_EQ(with("table-table", "table-head"),
              "m.json: machine.kinematics.type: expected \"table-table\", \"head-table\" or \"head-head\"");
    EXPECT_EQ(with("table-table", "head-table"),
              "m.json: machine.kinematics.rotaries: a head-table chain has 1 table axes, this one 2");
    EXPECT_EQ(with("[0, 2, 0]", "[0, 0, 0]"),
              "m.json: machine.kinematics.rotaries[0].direction: a zero vector has no direction");
    EXPECT_EQ(with("[0, 2, 0]", "[0, 0, -3]"),
              "m.json: machine.kinematics.rotaries: the two axes are parallel and cannot point a tool");
    EXPECT_EQ(with("\"sign\": \"negative\"", "\"sign\": \"down\""),
              "m.json: machine.kinematics.preferred.sign: expected \"positive\" or \"negative\"");
    EXPECT_EQ(with("\"on\": \"table\", \"direction\": [0, 0, 1]", "\"on\": \"bench\", \"direction\": [0, 0, 1]"),
              "m.json: machine.kinematics.rotaries[1].on: expected \"table\" or \"head\"");
}

TEST(Machine, FiveAxisMachinesFromTheReferences)
{
    const auto dirs = kinematics::defaultMachineDirs();
    struct Expected {
        const char* id;
        kinematics::ChainType type;
        const char* first;
        const char* second;
    };
    for (const Expected& e : {Expected{"mas-mcvl1000", kinematics::ChainType::TableTable, "B", "C"},
                              Expected{"mas-mcvl1000-nikken-guaranteed", kinematics::ChainType::TableTable, "B", "C"},
                              Expected{"kovosvit-mcu700-vt5x", kinematics::ChainType::TableTable, "A", "C"},
                              Expected{"hurco-vmx42sr", kinematics::ChainType::HeadTable, "C", "B"}}) {
        auto m = kinematics::findMachine(e.id, dirs);
        ASSERT_TRUE(m.ok()) << m.error().toString();
        ASSERT_TRUE(m->kinematics.fiveAxis()) << e.id;
        EXPECT_EQ(m->kinematics.type, e.type) << e.id;
        EXPECT_EQ(m->kinematics.joints[0].axis, e.first) << e.id;
        EXPECT_EQ(m->kinematics.joints[1].axis, e.second) << e.id;
    }
}

// The motion plan's limits (issue 14): what a file gives, the stated defaults where it gives none.
TEST(Machine, MotionLimitsFromTheFileOrTheStatedDefaults)
{
    auto m = kinematics::parseMachine(
        withAxis(R"({"name": "C", "type": "rotary", "endless": true, "maxVelocity": 7200, "maxAcceleration": 900})"),
        "m.json");
    ASSERT_TRUE(m.ok()) << m.error().toString();
    const kinematics::Axis* x = m->axis("X");
    EXPECT_FALSE(x->velocityFromFile);
    EXPECT_DOUBLE_EQ(x->maxVelocity, toolpath::kDefaultRapidMmPerMin);  // no feed.rapid either
    EXPECT_DOUBLE_EQ(x->maxAcceleration, kinematics::kDefaultLinearAccelerationMmPerS2);
    const kinematics::Axis* c = m->axis("C");
    EXPECT_TRUE(c->velocityFromFile && c->accelerationFromFile);
    EXPECT_DOUBLE_EQ(c->maxVelocity, 7200);
    EXPECT_DOUBLE_EQ(c->maxAcceleration, 900);
    EXPECT_DOUBLE_EQ(m->toolChangeSeconds, kinematics::kDefaultToolChangeSeconds);
    EXPECT_DOUBLE_EQ(m->spindleRampSeconds, kinematics::kDefaultSpindleRampSeconds);

    std::string timed = withAxis(R"({"name": "B", "type": "rotary", "min": 0, "max": 9, "maxRpm": 15})");
    timed.insert(timed.rfind('}'), R"(, "feed": {"rapid": 24000}, "toolChanger": {"changeSeconds": 3.5},
        "spindle": {"maxRpm": 12000, "rampSeconds": 1.25})");
    auto t = kinematics::parseMachine(timed, "m.json");
    ASSERT_TRUE(t.ok()) << t.error().toString();
    EXPECT_DOUBLE_EQ(t->axis("X")->maxVelocity, 24000);       // the rapid rate
    EXPECT_DOUBLE_EQ(t->axis("B")->maxVelocity, 15 * 360.0);  // maxRpm in deg/min
    EXPECT_DOUBLE_EQ(t->axis("B")->maxAcceleration, kinematics::kDefaultRotaryAccelerationDegPerS2);
    EXPECT_DOUBLE_EQ(t->toolChangeSeconds, 3.5);
    EXPECT_DOUBLE_EQ(t->spindleRampSeconds, 1.25);

    std::string manual = kMinimal;
    manual.insert(manual.rfind('}'), R"(, "toolChanger": {"manual": true})");
    EXPECT_DOUBLE_EQ(kinematics::parseMachine(manual, "m.json")->toolChangeSeconds,
                     kinematics::kDefaultManualToolChangeSeconds);
}

TEST(Machine, ShippedMachinesCarryTheirRapidAsAxisVelocity)
{
    auto kovosvit = kinematics::findMachine("kovosvit-mcu700-vt5x", kinematics::defaultMachineDirs());
    ASSERT_TRUE(kovosvit.ok()) << kovosvit.error().toString();
    for (const char* name : {"X", "Y", "Z"}) {
        EXPECT_TRUE(kovosvit->axis(name)->velocityFromFile) << name;
        EXPECT_DOUBLE_EQ(kovosvit->axis(name)->maxVelocity, 60000) << name;  // seed 003 Tab. 4.1
    }
    EXPECT_FALSE(kovosvit->axis("A")->velocityFromFile);
    EXPECT_DOUBLE_EQ(kovosvit->axis("A")->maxVelocity, kinematics::kDefaultRotaryDegPerMin);
}

TEST(Machine, BadMotionLimitsGiveFileNamedErrors)
{
    EXPECT_EQ(messageOf(withAxis(R"({"name": "W", "type": "linear", "min": 0, "max": 9, "maxVelocity": 0})")),
              "m.json: machine.axes[1].maxVelocity: expected a speed above 0");
    EXPECT_EQ(messageOf(withAxis(R"({"name": "W", "type": "linear", "min": 0, "max": 9, "maxAcceleration": -1})")),
              "m.json: machine.axes[1].maxAcceleration: expected an acceleration above 0");
    EXPECT_EQ(
        messageOf(withAxis(R"({"name": "B", "type": "rotary", "min": 0, "max": 9, "maxRpm": 5, "maxVelocity": 9})")),
        "m.json: machine.axes[1]: maxRpm and maxVelocity both give the axis' speed (keep one)");
    std::string changer = kMinimal;
    changer.insert(changer.rfind('}'), R"(, "toolChanger": {"changeSeconds": 0})");
    EXPECT_EQ(messageOf(changer), "m.json: machine.toolChanger.changeSeconds: expected a time above 0");
    std::string spindle = kMinimal;
    spindle.insert(spindle.rfind('}'), R"(, "spindle": {"rampSeconds": "slow"})");
    EXPECT_NE(messageOf(spindle).find("m.json: machine.spindle.rampSeconds"), std::string::npos);
}
