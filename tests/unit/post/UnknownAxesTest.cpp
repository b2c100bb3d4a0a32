// Moves that give only some axes (AxisMask) and positions the kernel does not know: the kernel
// writes only the axes it knows, never a guessed one; after a tool change the first rapid goes
// over in X/Y before it moves Z; handlers, templates and getCurrentPosition() agree.
#include "PostTestSupport.h"

namespace camwb::post::test {
namespace {

using namespace toolpath;

const char* kCommon = R"JS(
var f3 = createFormat({decimals: 3});
var x = createVariable({prefix: "X"}, f3), y = createVariable({prefix: "Y"}, f3), z = createVariable({prefix: "Z"}, f3);
var f = createVariable({prefix: "F"}, createFormat({decimals: 0}));
var g = createModal({prefix: "G"});
function onToolChange(tool) { writeBlock("T" + tool.number, "M6"); x.reset(); y.reset(); z.reset(); g.reset(); }
)JS";

const char* kTemplates = R"JS(
var post = {id: "templates"};
post.blocks = {
    rapid: [g.bind("motion"), x.bind("x"), y.bind("y"), z.bind("z")],
    linear: [g.bind("motion"), x.bind("x"), y.bind("y"), z.bind("z"), f.bind("feed")]
};
)JS";

// The same rules as handlers; they also say what the kernel knows before each move.
const char* kHandlers = R"JS(
var post = {id: "handlers"};
var seen = [];
function known() {
    var p = getCurrentPosition();
    return p ? "all" : [getCurrentAxis("x"), getCurrentAxis("y"), getCurrentAxis("z")].join(",");
}
function onRapid(px, py, pz) {
    seen.push(known());
    var a = [x.format(px), y.format(py), z.format(pz)];
    if (a.join("")) writeBlock(g.format(0), a[0], a[1], a[2]);
}
function onLinear(px, py, pz, feed) {
    seen.push(known());
    var a = [x.format(px), y.format(py), z.format(pz)];
    if (a.join("")) writeBlock(g.format(1), a[0], a[1], a[2], f.format(feed));
}
function onClose() { writeln("known before each move: " + seen.join(" | ")); }
)JS";

base::Error failure(const Toolpath& path)
{
    auto post = PostProcessor::load(writeScript("templates.js", std::string(kCommon) + kTemplates));
    EXPECT_TRUE(post.ok()) << post.error().toString();
    auto output = post->run(path, fixedContext());
    EXPECT_FALSE(output.ok());
    return output.ok() ? base::Error{} : output.error();
}

constexpr AxisMask kZ{AxisMask::kZ};
constexpr AxisMask kXY{AxisMask::kX | AxisMask::kY};

std::vector<std::string> withoutLastLine(std::vector<std::string> lines)
{
    if (!lines.empty())
        lines.pop_back();
    return lines;
}

TEST(UnknownAxes, ARetractBeforeTheFirstXYMovesZAlone)
{
    // FreeCAD's usual start: "G0 Z20" before the first "G0 X6 Y-20". A single diagonal
    // "G0 X6 Y-20 Z20" would drop the retract the CL asked for.
    Toolpath path;
    path.add(Rapid{{0, 0, 20}, kZ});
    path.add(Rapid{{6, -20, 0}, kXY});
    path.add(Rapid{{0, 0, 3}, kZ});
    path.add(Linear{{40, 0, 0}, 360, AxisMask{AxisMask::kX}});
    const std::vector<std::string> expected{"N10 G0 Z20.000", "N20 X6.000 Y-20.000", "N30 Z3.000",
                                            "N40 G1 X40.000 F360"};
    EXPECT_EQ(lines(runSource("templates.js", std::string(kCommon) + kTemplates, path).text), expected);
    const std::vector<std::string> handlers =
        lines(runSource("handlers.js", std::string(kCommon) + kHandlers, path).text);
    EXPECT_EQ(withoutLastLine(handlers), expected);
    ASSERT_FALSE(handlers.empty());
    EXPECT_EQ(handlers.back(), "known before each move: ,, | ,,20 | all | all");
}

TEST(UnknownAxes, TheFirstRapidAfterAToolChangeMovesXYThenZ)
{
    Toolpath path;
    path.add(Rapid{{0, 0, 50}});
    path.add(ToolChange{Tool{2}});
    path.add(Rapid{{10, 20, 5}});  // X/Y at the height the change left, then Z
    path.add(Rapid{{30, 20, 5}});  // only the first one
    path.add(ToolChange{Tool{3}});
    path.add(Rapid{{0, 0, 25}, kZ});  // the CL retracts first: kept, X/Y stay unwritten
    path.add(Rapid{{30, 40, 25}});
    path.add(ToolChange{Tool{4}});
    path.add(Linear{{30, 40, 2}, 100});  // a feed move first: as the CL says
    const std::vector<std::string> expected{"N10 G0 X0.000 Y0.000 Z50.000",
                                            "N20 T2 M6",
                                            "N30 G0 X10.000 Y20.000",
                                            "N40 Z5.000",
                                            "N50 X30.000",
                                            "N60 T3 M6",
                                            "N70 G0 Z25.000",
                                            "N80 X30.000 Y40.000",
                                            "N90 T4 M6",
                                            "N100 G1 X30.000 Y40.000 Z2.000 F100"};
    EXPECT_EQ(lines(runSource("templates.js", std::string(kCommon) + kTemplates, path).text), expected);
    const std::vector<std::string> handlers =
        lines(runSource("handlers.js", std::string(kCommon) + kHandlers, path).text);
    EXPECT_EQ(withoutLastLine(handlers), expected);
    ASSERT_FALSE(handlers.empty());
    // A tool change forgets every axis: the changer moved the machine.
    EXPECT_EQ(handlers.back(), "known before each move: ,, | ,, | 10,20, | all | ,, | ,,25 | ,,");
}

TEST(UnknownAxes, ArcsAndCyclesNeedAKnownStart)
{
    Toolpath arc;
    arc.add(Rapid{{0, 0, 10}});
    arc.add(ToolChange{Tool{2}});
    arc.add(Arc{{10, 0, 10}, {5, 0, 10}, {0, 0, 1}, true, 0, 100});
    EXPECT_NE(failure(arc).message.find("arc with an unknown start point"), std::string::npos)
        << failure(arc).toString();

    // The template post has no cycle handler: the kernel expands the holes, which needs the height.
    Cycle drill;
    drill.clearanceZ = 20;
    drill.retractZ = 2;
    drill.bottomZ = -5;
    drill.feedMmPerMin = 100;
    drill.holes = {{5, 5, 0}};
    Toolpath cycle;
    cycle.add(Rapid{{3, 3, 0}, kXY});
    cycle.add(drill);
    EXPECT_NE(failure(cycle).message.find("canned cycle from an unknown height"), std::string::npos)
        << failure(cycle).toString();

    // With Z known (a retract first) the expansion goes over the hole at that height.
    Toolpath retracted;
    retracted.add(Rapid{{0, 0, 20}, kZ});
    retracted.add(drill);
    EXPECT_EQ(lines(runSource("templates.js", std::string(kCommon) + kTemplates, retracted).text),
              (std::vector<std::string>{"N10 G0 Z20.000", "N20 X5.000 Y5.000", "N30 Z2.000", "N40 G1 Z-5.000 F100",
                                        "N50 G0 Z20.000"}));

    // A peck that would make millions of pecks (a slip) fails the post rather than writing them.
    Cycle peck = drill;
    peck.kind = CycleKind::Peck;
    peck.peckMm = 1e-7;
    Toolpath slip;
    slip.add(Rapid{{0, 0, 20}, kZ});
    slip.add(peck);
    EXPECT_NE(failure(slip).message.find("peck depth 0.0000001 mm makes 50000000 pecks over 5 mm"), std::string::npos)
        << failure(slip).toString();
}

// A CL read back from NC whose tool went where the program does not say (an untraced M140 MB MAX
// or SUPA): no post can write that move, and leaving it out would run the next moves from Z -5.
TEST(UnknownAxes, AMoveToAnUnknownPlaceFailsThePostAtItsRecord)
{
    Toolpath path;
    path.add(Rapid{{10, 10, 5}});
    path.add(Linear{{10, 10, -5}, 100});
    path.add(UnknownAxes{kZ}, SourceRef{-1, -1, 7, 0});
    path.add(Rapid{{90, 90, 0}, kXY});
    const base::Error error = failure(path);
    EXPECT_NE(error.message.find("the CL moves Z to a place it does not give"), std::string::npos) << error.toString();
    EXPECT_NE(error.message.find("post templates cannot write that move"), std::string::npos) << error.toString();
}

TEST(UnknownAxes, ExtentsHoldOnlyTheAxesTheMovesGave)
{
    Toolpath path;
    path.add(Rapid{{0, 0, 20}, kZ});
    path.add(Rapid{{0, 0, 5}, kZ});
    const PostOutput output = runSource("extents.js",
                                        "var post = {id: \"extents\"};\n"
                                        "function onOpen(p) { writeln([p.extents.min.x, p.extents.min.z, "
                                        "p.extents.max.y, p.extents.max.z].join(\"|\")); }\n"
                                        "function onRapid() {}\n",
                                        path);
    EXPECT_EQ(output.text, "|5||20\n");
}

}  // namespace
}  // namespace camwb::post::test
