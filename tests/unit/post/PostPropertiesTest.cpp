// Post declarations: typed properties, capabilities and metadata, read without running handlers,
// and the values a run gets from the user or the defaults.
#include "PostTestSupport.h"

namespace camwb::post::test {
namespace {

using namespace toolpath;

const char* kDeclaringPost = R"JS(var post = {
    id: "declaring",
    description: "declares one of each",
    capabilities: {arcPlanes: ["XY"], helicalArcs: false, maxArcSweep: 90, arcWords: "radius", tolerance: 0.002,
                   cycles: ["drill", "peck"], maxAxes: 3},
    properties: {
        numbers: {title: "Block numbers", type: "bool", default: true, description: "N words"},
        start: {type: "int", default: 10, min: 0, max: 9000},
        scale: {type: "number", default: 0.5},
        calls: {type: "enum", values: ["mcall", "perHole"], default: "perHole"},
        text: {type: "string", default: "Tool change"}
    }
};
var startAtLoad = getProperty("start");
function onOpen() {
    writeln([getProperty("numbers"), getProperty("start") + 1, getProperty("scale") * 2, getProperty("calls"),
             getProperty("text"), startAtLoad].join("|"));
}
function onCycle(cycle) {}
)JS";

TEST(PostProperties, DeclarationsAreReadWithoutRunningHandlers)
{
    const std::string throwing =
        std::string(kDeclaringPost) +
        "function onOpen() { throw new Error('handlers do not run when a post is loaded'); }\n";
    auto post = PostProcessor::load(writeScript("declaring.js", throwing));
    ASSERT_TRUE(post.ok()) << post.error().toString();
    const PostInfo& info = post->info();
    EXPECT_EQ(info.description, "declares one of each");
    EXPECT_EQ(info.extension, "nc");
    ASSERT_EQ(info.properties.size(), 5u);
    const PropertyDef* numbers = info.property("numbers");
    ASSERT_NE(numbers, nullptr);
    EXPECT_EQ(numbers->type, PropertyType::Bool);
    EXPECT_EQ(numbers->title, "Block numbers");
    EXPECT_EQ(numbers->defaultValue, "true");
    EXPECT_EQ(numbers->line, 7);
    const PropertyDef* start = info.property("start");
    ASSERT_NE(start, nullptr);
    EXPECT_EQ(start->title, "start");  // the name when no title is given
    EXPECT_EQ(start->defaultValue, "10");
    EXPECT_EQ(*start->min, 0);
    EXPECT_EQ(*start->max, 9000);
    EXPECT_EQ(info.property("scale")->defaultValue, "0.5");
    EXPECT_EQ(info.property("calls")->values, (std::vector<std::string>{"mcall", "perHole"}));
    EXPECT_EQ(info.property("nope"), nullptr);

    const PostCapabilities& caps = info.capabilities;
    EXPECT_EQ(caps.arcPlanes, std::vector<std::string>{"XY"});
    EXPECT_TRUE(caps.helicalPlanes.empty());
    EXPECT_EQ(caps.maxArcSweepDeg, 90);
    EXPECT_TRUE(caps.arcRadiusWords);
    EXPECT_EQ(caps.toleranceMm, 0.002);
    EXPECT_TRUE(caps.cyclesDeclared);
    EXPECT_TRUE(caps.writesCycle("peck"));
    EXPECT_FALSE(caps.writesCycle("tap"));
}

TEST(PostProperties, RunsSeeDefaultsOrTheUsersValues)
{
    auto quiet = PostProcessor::load(writeScript("declaring.js", kDeclaringPost));
    ASSERT_TRUE(quiet.ok()) << quiet.error().toString();
    RunOptions options;
    options.context = fixedContext();
    auto text = quiet->run(Toolpath{}, options);
    ASSERT_TRUE(text.ok()) << text.error().toString();
    EXPECT_EQ(text->text, "true|11|1|perHole|Tool change|10\n");

    options.properties = {
        {"numbers", "false"}, {"start", "100"}, {"scale", "-1.25"}, {"calls", "mcall"}, {"text", "Vymena nastroje"}};
    text = quiet->run(Toolpath{}, options);
    ASSERT_TRUE(text.ok()) << text.error().toString();
    EXPECT_EQ(text->text, "false|101|-2.5|mcall|Vymena nastroje|100\n");  // top-level code sees them too
}

TEST(PostProperties, BadValuesSayWhatTheyAccept)
{
    PostInfo info;
    info.id = "p";
    info.properties = {{"flag", "", "", PropertyType::Bool, "false"},
                       {"count", "", "", PropertyType::Integer, "1", 1.0, 10.0},
                       {"ratio", "", "", PropertyType::Number, "0.5"},
                       {"mode", "", "", PropertyType::Enum, "a", {}, {}, {"a", "b"}}};
    auto message = [&](const std::map<std::string, std::string>& values) {
        auto resolved = resolveProperties(info, values);
        EXPECT_FALSE(resolved.ok());
        return resolved.ok() ? std::string() : resolved.error().message;
    };
    EXPECT_EQ(message({{"flag", "maybe"}}), "property 'flag' is a bool: use true or false, not 'maybe'");
    EXPECT_EQ(message({{"count", "1.5"}}), "property 'count' is an integer, not '1.5'");
    EXPECT_EQ(message({{"count", "11"}}), "property 'count' must be in 1..10, not 11");
    EXPECT_EQ(message({{"ratio", "half"}}), "property 'ratio' is a number, not 'half'");
    EXPECT_EQ(message({{"mode", "c"}}), "property 'mode' is one of a, b, not 'c'");
    EXPECT_EQ(message({{"colour", "red"}}), "post p has no property 'colour'; it has: flag, count, ratio, mode");

    auto resolved = resolveProperties(info, {{"flag", "yes"}, {"count", "+7"}});
    ASSERT_TRUE(resolved.ok()) << resolved.error().message;
    EXPECT_TRUE(resolved->at("flag").boolean);
    EXPECT_TRUE(resolved->at("flag").fromUser);
    EXPECT_EQ(resolved->at("count").number, 7);
    EXPECT_EQ(resolved->at("ratio").number, 0.5);
    EXPECT_FALSE(resolved->at("ratio").fromUser);
    EXPECT_EQ(resolved->at("mode").text, "a");

    EXPECT_EQ(splitPropertyAssignment("a=b=c")->second, "b=c");
    EXPECT_FALSE(splitPropertyAssignment("=x").ok());
    EXPECT_FALSE(splitPropertyAssignment("novalue").ok());
}

struct BadDeclaration {
    const char* name;
    const char* script;
    const char* message;
    int line;
};

TEST(PostProperties, MalformedDeclarationsAreLoadErrorsWithTheirLine)
{
    const BadDeclaration cases[] = {
        {"notype.js", "var post = {properties: {\n  a: {default: 1}\n}};\n", "post.properties.a: type must be", 2},
        {"nodefault.js", "var post = {properties: {\n\n  a: {type: \"int\"}}};\n", "post.properties.a: no default", 3},
        {"range.js", "var post = {properties: {\n  a: {type: \"int\", default: 20, max: 10}}};\n",
         "post.properties.a: default: property 'a' must be in", 2},
        {"enum.js", "var post = {properties: {\n  a: {type: \"enum\", default: \"x\"}}};\n", "an enum needs values", 2},
        {"typo.js", "var post = {capabilities: {\n  maxArcSwep: 90}};\n",
         "post.capabilities.maxArcSwep is not a capability", 2},
        {"sweep.js", "var post = {capabilities: {maxArcSweep: 400}};\n",
         "post.capabilities.maxArcSweep must be a number in 1..360", 1},
        {"plane.js", "var post = {capabilities: {arcPlanes: [\"XZ\"]}};\n", "unknown entry \"XZ\"", 1},
        {"cycles.js", "var post = {\n capabilities: {cycles: [\"drill\"]}};\n",
         "lists native cycles but the post has no onCycle", 2},
        {"id.js", "var post = {\n\n id: \"other\"};\n", "post.id \"other\" does not match the file name id.js", 3},
        {"getprop.js", "var post = {};\nvar x = getProperty(\"missing\");\n", "the post declares no property 'missing'",
         2},
        {"machine.js", "var post = {machines: [\"a\"],\n machine: \"b\"};\n",
         "post.machine \"b\" is not in post.machines", 2},
    };
    for (const BadDeclaration& c : cases) {
        const std::string path = writeScript(c.name, c.script);
        auto post = PostProcessor::load(path);
        ASSERT_FALSE(post.ok()) << c.name;
        EXPECT_NE(post.error().message.find(c.message), std::string::npos) << c.name << ": " << post.error().message;
        EXPECT_EQ(post.error().file, path) << c.name;
        EXPECT_EQ(post.error().line, c.line) << c.name << ": " << post.error().message;
    }
}

TEST(PostProperties, MachineIsGivenToTheScriptAndMustBeAccepted)
{
    const std::string script = writeScript("machines.js", R"JS(var post = {machines: ["emco-concept-mill-105"]};
function onOpen() { writeln(machine ? machine.name + " " + machine.axes[0].name + machine.axes[0].max + " " +
                                      machine.spindleMaxRpm + " " + machine.coolants.join() : "none"); }
)JS");
    auto post = PostProcessor::load(script);
    ASSERT_TRUE(post.ok()) << post.error().toString();
    RunOptions options;
    options.context = fixedContext();
    EXPECT_EQ(post->run(Toolpath{}, options)->text, "none\n");
    auto emco = kinematics::findMachine("emco-concept-mill-105", kinematics::defaultMachineDirs());
    ASSERT_TRUE(emco.ok()) << emco.error().toString();
    options.machine = emco.value();
    EXPECT_EQ(post->run(Toolpath{}, options)->text, "EMCO Concept MILL 105 X200 5000 flood\n");
    options.machine->id = "other-mill";
    auto refused = post->run(Toolpath{}, options);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message,
              "post machines does not drive machine other-mill (it is written for: emco-concept-mill-105)");
}

}  // namespace
}  // namespace camwb::post::test
