// C++ block templates: the native per-move path must write exactly what the same post writes
// through script handlers, share the modal state with the script, and refuse malformed templates.
#include "PostTestSupport.h"

#include <cmath>

namespace camwb::post::test {
namespace {

using namespace toolpath;

// The same output rules twice: once as handlers, once as templates.
const char* kCommon = R"JS(
var f3 = createFormat({decimals: 3});
var x = createVariable({prefix: "X"}, f3), y = createVariable({prefix: "Y"}, f3), z = createVariable({prefix: "Z"}, f3);
var i = createVariable({prefix: "I", force: true}, f3), j = createVariable({prefix: "J", force: true}, f3);
var k = createVariable({prefix: "K", force: true}, f3), r = createVariable({prefix: "CR="}, f3);
var f = createVariable({prefix: "F"}, createFormat({decimals: 0}));
var g = createModal({prefix: "G"}), plane = createModal({prefix: "G"}), comp = createModal({prefix: "G"});
function onToolChange(tool) { writeBlock("T" + tool.number); x.reset(); y.reset(); z.reset(); g.reset(); }
function onCutterComp(side) {}
)JS";

const char* kHandlers = R"JS(
var post = {id: "handlers", capabilities: {arcWords: "radius"}};
var side = 40;
function onCutterComp(s) { side = s == "left" ? 41 : s == "right" ? 42 : 40; }
function axes(px, py, pz) { return [x.format(px), y.format(py), z.format(pz)]; }
function onRapid(px, py, pz) {
    var a = axes(px, py, pz);
    if (a.join("")) writeBlock(g.format(0), comp.format(side), a[0], a[1], a[2]);
}
function onLinear(px, py, pz, feed) {
    var a = axes(px, py, pz);
    if (a.join("")) writeBlock(g.format(1), comp.format(side), a[0], a[1], a[2], feed > 0 ? f.format(feed) : "");
}
function onCircular(cw, cx, cy, cz, px, py, pz, feed, arc) {
    var s = getCurrentPosition();
    if (arc.helical) { x.reset(); y.reset(); z.reset(); }
    var c = arc.plane == "XY" ? [i.format(cx - s.x), j.format(cy - s.y)]
          : arc.plane == "ZX" ? [i.format(cx - s.x), k.format(cz - s.z)] : [j.format(cy - s.y), k.format(cz - s.z)];
    writeBlock(plane.format(arc.plane == "XY" ? 17 : arc.plane == "ZX" ? 18 : 19), g.format(cw ? 2 : 3),
               x.format(px), y.format(py), z.format(pz), c[0], c[1], r.format(arc.radius), f.format(feed));
}
)JS";

const char* kTemplates = R"JS(
var post = {id: "templates", capabilities: {arcWords: "radius"}};
post.blocks = {
    rapid: [g.bind("motion"), comp.bind("comp"), x.bind("x"), y.bind("y"), z.bind("z")],
    linear: [g.bind("motion"), comp.bind("comp"), x.bind("x"), y.bind("y"), z.bind("z"), f.bind("feed")],
    circular: {
        forceOnHelical: [x, y, z],
        XY: [plane.bind("plane"), g.bind("motion"), x.bind("x"), y.bind("y"), z.bind("z"), i.bind("i"), j.bind("j"),
             r.bind("radius"), f.bind("feed")],
        ZX: [plane.bind("plane"), g.bind("motion"), x.bind("x"), y.bind("y"), z.bind("z"), i.bind("i"), k.bind("k"),
             r.bind("radius"), f.bind("feed")],
        YZ: [plane.bind("plane"), g.bind("motion"), x.bind("x"), y.bind("y"), z.bind("z"), j.bind("j"), k.bind("k"),
             r.bind("radius"), f.bind("feed")]
    }
};
)JS";

Toolpath mixedMoves()
{
    Toolpath path;
    path.add(Rapid{{0, 0, 20}});
    path.add(Rapid{{0, 0, 20}});  // no axis changes: no block
    path.add(Linear{{10, 0, 5}, 300});
    path.add(Linear{{10, 0, 5}, 400});  // no axis changes: no block, F stays modal
    path.add(Arc{{0, 10, 5}, {0, 0, 5}, {0, 0, 1}, false, 0, 300});
    path.add(Arc{{0, 10, 5}, {0, 0, 5}, {0, 0, -1}, false, 0, 300});  // full circle, seen from below
    path.add(Arc{{0, 10, 2}, {0, 0, 5}, {0, 0, 1}, true, 1, 250});    // helix with an extra turn
    path.add(CutterComp{CutterCompSide::Left});
    path.add(Linear{{5, 15, 2}, 250});
    path.add(CutterComp{CutterCompSide::Off});
    path.add(Rapid{{5, 15, 30}});
    path.add(ToolChange{Tool{2}});
    path.add(Rapid{{5, 15, 30}});  // after the tool change: X/Y, then Z, forced by the script's reset()
    path.add(Arc{{5, 25, 40}, {5, 20, 35}, {1, 0, 0}, true, 0, 100});     // YZ
    path.add(Arc{{10, 25, 45}, {10, 25, 40}, {0, 1, 0}, false, 0, 100});  // ZX, a quarter from -X towards +Z
    path.add(Linear{{0, 0, 0}, 0});                                       // feed missing: F left out
    return path;
}

TEST(BlockTemplates, WriteWhatTheSameRulesWriteAsHandlers)
{
    const PostOutput handlers = runSource("handlers.js", std::string(kCommon) + kHandlers, mixedMoves());
    const PostOutput templates = runSource("templates.js", std::string(kCommon) + kTemplates, mixedMoves());
    EXPECT_EQ(templates.text, handlers.text);
    EXPECT_EQ(templates.lineOperation, handlers.lineOperation);
    EXPECT_EQ(
        lines(templates.text),
        (std::vector<std::string>{
            "N10 G0 G40 X0.000 Y0.000 Z20.000", "N20 G1 X10.000 Z5.000 F300",
            "N30 G17 G3 X0.000 Y10.000 I-10.000 J0.000 CR=10.000", "N40 G2 Y-10.000 I0.000 J-10.000",
            "N50 Y10.000 I0.000 J10.000", "N60 X0.000 Y-10.000 Z4.250 I0.000 J-10.000 F250",
            "N70 X0.000 Y10.000 Z3.500 I0.000 J10.000", "N80 X0.000 Y-10.000 Z2.750 I0.000 J-10.000",
            "N90 X0.000 Y10.000 Z2.000 I0.000 J10.000", "N100 G1 G41 X5.000 Y15.000", "N110 G0 G40 Z30.000", "N120 T2",
            "N130 G0 X5.000 Y15.000", "N140 Z30.000", "N150 G19 G2 Y25.000 Z40.000 J5.000 K5.000 CR=7.071 F100",
            "N160 G18 G3 X10.000 Z45.000 I5.000 K0.000 CR=5.000", "N170 G1 X0.000 Y0.000 Z0.000"}))
        << templates.text;
    ASSERT_EQ(templates.messages.size(), 1u);
    EXPECT_EQ(templates.messages[0].message, "1 feed move without a feed rate: F not written (first: CL record 15)");
}

TEST(BlockTemplates, MalformedTemplatesAreLoadErrors)
{
    const std::pair<const char*, const char*> cases[] = {
        {"post.blocks = {rapid: \"G0 X Y Z\"};", "post.blocks.rapid must be an array of words"},
        {"post.blocks = {rapid: [g.bind(\"motion\"), f.bind(\"feed\"), x.bind(\"x\")]};",
         "post.blocks.rapid[1]: a rapid block cannot write 'feed'"},
        {"post.blocks = {linear: [g.bind(\"motion\"), i.bind(\"i\"), x.bind(\"x\")]};",
         "post.blocks.linear[1]: a linear block cannot write 'i'"},
        {"post.blocks = {linear: [g.bind(\"motion\"), 12]};", "post.blocks.linear[1]: expected a string or a variable"},
        {"post.blocks = {linear: [g.bind(\"motion\"), f.bind(\"feed\")]};", "post.blocks.linear writes no axis"},
        {"post.blocks = {circular: {XY: [x.bind(\"x\")], forceOnHelical: [f3]}};",
         "post.blocks.circular.forceOnHelical[0]: expected a variable from createVariable()"},
        {"post.blocks = {rapid: [x.bind(\"speed\")]};", "bind(): unknown move value 'speed'"},
    };
    for (const auto& [blocks, message] : cases) {
        auto post = PostProcessor::load(
            writeScript("badblocks.js", std::string("var post = {id: \"badblocks\"};\n") + kCommon + blocks + "\n"));
        ASSERT_FALSE(post.ok()) << blocks;
        EXPECT_NE(post.error().message.find(message), std::string::npos) << post.error().message;
        EXPECT_GT(post.error().line, 0) << blocks;
    }
}

TEST(BlockTemplates, HandlersWinOverTemplates)
{
    Toolpath path;
    path.add(Rapid{{1, 2, 3}});
    const PostOutput output = runSource(
        "templates.js",
        std::string(kCommon) + kTemplates + "function onRapid(px, py, pz) { writeln(\"handler \" + px); }\n", path);
    EXPECT_EQ(output.text, "handler 1\n");
}

}  // namespace
}  // namespace camwb::post::test

namespace camwb::post::test {
namespace {

TEST(BlockTemplates, CentreWordsAreMeasuredFromTheWrittenStart)
{
    // The start Y0.0004 is written Y0.000, and the control measures J from there: 10.0008 -> J10.001.
    // Measured from the exact start, J would be 10.0004 -> J10.000, a centre 0.0008 mm off.
    Toolpath path;
    path.add(Rapid{{0, 0.0004, 0}});
    path.add(Arc{{0, 20.0012, 0}, {0, 10.0008, 0}, {0, 0, 1}, true, 0, 100});
    const PostOutput output = runSource("templates.js", std::string(kCommon) + kTemplates, path);
    EXPECT_EQ(lines(output.text).back(), "N20 G17 G2 Y20.001 I0.000 J10.001 CR=10.000 F100");
}

TEST(BlockTemplates, AnArcWhoseWrittenEndIsItsStartIsAStraightMove)
{
    // 0.2 degrees of a 0.1 mm circle: start and end both write X10.000 Y0.000, which a control would
    // read as a full circle. As a straight move it changes no written axis, so it writes nothing.
    Toolpath path;
    path.add(Rapid{{10, 0, 0}});
    const double a = 0.2 * 3.14159265358979 / 180;
    path.add(Arc{{9.9 + 0.1 * std::cos(a), 0.1 * std::sin(a), 0}, {9.9, 0, 0}, {0, 0, 1}, false, 0, 100});
    path.add(Arc{{10, 0, 0}, {9.9, 0, 0}, {0, 0, 1}, false, 0, 100});  // the rest of the circle: a real arc
    const PostOutput output = runSource("templates.js", std::string(kCommon) + kTemplates, path);
    EXPECT_EQ(lines(output.text),
              (std::vector<std::string>{"N10 G0 G40 X10.000 Y0.000 Z0.000",
                                        "N20 G17 G3 X9.800 I-0.100 J0.000 CR=0.100 F100", "N30 X10.000 I0.100 J0.000"}))
        << output.text;
}

TEST(BlockTemplates, ForcedWordsAreWrittenInEveryBlock)
{
    Toolpath path;
    path.add(Rapid{{0, 0, 0}});
    path.add(FeedModeChange{FeedMode::InverseTime});
    path.add(Linear{{1, 0, 0}, 60});
    path.add(Linear{{2, 0, 0}, 60});
    path.add(FeedModeChange{FeedMode::PerMinute});
    path.add(Linear{{3, 0, 0}, 60});
    const PostOutput output = runSource("templates.js",
                                        std::string(kCommon) + kTemplates +
                                            "function onFeedMode(mode) { f.setForce(mode == \"inverseTime\"); }\n",
                                        path);
    EXPECT_EQ(wordLines(output.text),
              (std::vector<std::string>{"G0 G40 X0.000 Y0.000 Z0.000", "G1 X1.000 F60", "X2.000 F60", "X3.000"}));
}

TEST(BlockTemplates, CompensationWorksInXYOnly)
{
    Toolpath path;
    path.add(Rapid{{-10, 0, 0}});
    path.add(CutterComp{CutterCompSide::Left});
    path.add(Linear{{0, 0, 0}, 100});
    path.add(Arc{{10, 0, 0}, {5, 0, 0}, {0, 1, 0}, true, 0, 100});
    auto post = PostProcessor::load(writeScript("templates.js", std::string(kCommon) + kTemplates));
    ASSERT_TRUE(post.ok());
    auto refused = post->run(path, fixedContext());
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message,
              "arc outside the XY plane with cutter compensation on: compensation works in XY (CL record 3 Arc)");
}

}  // namespace
}  // namespace camwb::post::test
