// What block templates write beyond numbers: texts per code (DR+/DR-, R0/RL/RR), forced words,
// one-shot pending words and blocks, arcs in several blocks (CC then C) and helices in their own
// words (CP IPA IZ), axes a move leaves unwritten written again next, a format's largest value,
// parametric feeds by feed kind, and block numbers without "N".
#include "PostTestSupport.h"

namespace camwb::post::test {
namespace {

using namespace toolpath;

const char* kKlartextLike = R"JS(
var post = {id: "klartext", capabilities: {helicalArcs: ["XY"], maxHelixSweep: 3600}};
var f = createFormat({decimals: 3, trim: true, forceSign: true, max: 99999.9999});
var x = createVariable({prefix: "X"}, f), y = createVariable({prefix: "Y"}, f), z = createVariable({prefix: "Z"}, f);
var cx = createVariable({prefix: "X", force: true}, f), cy = createVariable({prefix: "Y", force: true}, f);
var ipa = createVariable({prefix: "IPA", force: true}, createFormat({decimals: 4, trim: true, forceSign: true}));
var iz = createVariable({prefix: "IZ", force: true}, f);
var feed = createVariable({prefix: "F"}, createFormat({decimals: 0}));
var comp = createModal({prefix: ""}), dr = createModal({prefix: "DR", force: true});
var start = createPending(), coolant = createPending(), call = createPending();
var compTexts = {40: "R0", 41: "RL", 42: "RR"};
post.blocks = {
    rapid: ["L", x.bind("x"), y.bind("y"), z.bind("z"), comp.bind("comp", {force: true, texts: compTexts}), "FMAX",
            start],
    linear: ["L", x.bind("x"), y.bind("y"), z.bind("z"), comp.bind("comp", {texts: compTexts}), feed.bind("feed"),
             start],
    circular: {
        XY: [["CC", cx.bind("cx"), cy.bind("cy")],
             ["C", x.bind("x", {force: true}), y.bind("y", {force: true}), dr.bind("motion", {texts: {2: "-", 3: "+"}}),
              feed.bind("feed")]],
        helix: {XY: [["CC", cx.bind("cx"), cy.bind("cy")],
                     ["CP", ipa.bind("angle"), iz.bind("axial"), dr.bind("motion", {texts: {2: "-", 3: "+"}}),
                      feed.bind("feed")]]}
    },
    before: [call],
    after: [coolant]
};
function onOpen() { setBlockNumbering(0, 1, true, ""); }
function onToolChange(tool) { call.set("TOOL CALL " + tool.number + " Z"); }
function onSpindle(rpm, cw) { start.set(cw ? "M3" : "M4"); }
function onCoolant(mode) { coolant.set("L M8"); }
function onCutterComp(side) {}
function onSection(section) {
    feed.setFeedParameters(section.feeds.cutting > 0 ? {cutting: {text: "+Q601", feed: section.feeds.cutting}} : {});
}
)JS";

base::Result<PostOutput> runKlartext(const Toolpath& path)
{
    auto post = PostProcessor::load(writeScript("klartext.js", kKlartextLike));
    if (!post)
        return post.error();
    return post->run(path, fixedContext());
}

std::vector<std::string> postedLines(const Toolpath& path)
{
    auto output = runKlartext(path);
    EXPECT_TRUE(output.ok()) << output.error().toString();
    return output.ok() ? lines(output->text) : std::vector<std::string>{};
}

TEST(TemplateWords, PendingWordsAndBlocksGoOutOnceAroundTheFirstMove)
{
    Toolpath path;
    path.add(ToolChange{});
    path.add(Spindle{3500, true});
    path.add(Coolant{CoolantMode::Flood});
    path.add(Rapid{{-49.048, -74.356, 150}, AxisMask{AxisMask::kX | AxisMask::kY}});
    path.add(Rapid{{-49.048, -74.356, 150}, AxisMask{AxisMask::kZ}});
    path.add(Linear{{-49.048, -74.356, 90.053}, 300});
    EXPECT_EQ(postedLines(path), (std::vector<std::string>{"0 TOOL CALL 1 Z", "1 L X-49.048 Y-74.356 R0 FMAX M3",
                                                           "2 L M8", "3 L Z+150 R0 FMAX", "4 L Z+90.053 F300"}));
}

TEST(TemplateWords, TextsPerCodeWriteTheCompensationSideAndTheDirection)
{
    Toolpath path;
    path.add(Rapid{{10, 0, 5}});
    path.add(CutterComp{CutterCompSide::Left});
    path.add(Linear{{0, 0, 5}, 200});
    path.add(Linear{{0, 10, 5}, 200});
    Arc arc;
    arc.to = {10, 10, 5};
    arc.center = {5, 10, 5};
    arc.clockwise = true;
    arc.feedMmPerMin = 200;
    path.add(arc);
    path.add(CutterComp{CutterCompSide::Off});
    path.add(Linear{{20, 10, 5}, 200});
    EXPECT_EQ(postedLines(path), (std::vector<std::string>{"0 L X+10 Y+0 Z+5 R0 FMAX", "1 L X+0 RL F200", "2 L Y+10",
                                                           "3 CC X+5 Y+10", "4 C X+10 Y+10 DR-", "5 L X+20 R0"}));
}

TEST(TemplateWords, HelicesTakeTheirOwnWordsAndTheAxesTheyLeftAreWrittenAgain)
{
    Toolpath path;
    path.add(Rapid{{10, 0, 5}});
    Arc helix;  // two and a half turns down 5 mm about (0, 0), counter-clockwise
    helix.to = {-10, 0, 0};
    helix.center = {0, 0, 5};
    helix.turns = 2;
    helix.feedMmPerMin = 100;
    path.add(helix);
    // Where the helix ended: the CP block wrote no X or Z, so they are written here although the
    // move changes nothing; Y did not move and stays unwritten.
    path.add(Linear{{-10, 0, 0}, 100});
    path.add(Linear{{-10, 5, 0}, 100});
    EXPECT_EQ(postedLines(path), (std::vector<std::string>{"0 L X+10 Y+0 Z+5 R0 FMAX", "1 CC X+0 Y+0",
                                                           "2 CP IPA+900 IZ-5 DR+ F100", "3 L X-10 Z+0", "4 L Y+5"}));
}

TEST(TemplateWords, AValueBeyondTheFormatsMaxStopsTheRunNamingTheRecord)
{
    Toolpath path;
    path.add(Rapid{{10, 0, 5}});
    path.add(Linear{{123456.5, 0, 5}, 100});
    auto output = runKlartext(path);
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("X123456.5 is beyond the largest value the control reads (99999.9999)"),
              std::string::npos)
        << output.error().message;
    EXPECT_NE(output.error().message.find("CL record 1"), std::string::npos) << output.error().message;
}

TEST(TemplateWords, MalformedTextsAndPendingListsAreLoadErrors)
{
    auto texts = PostProcessor::load(writeScript("badtexts.js",
                                                 "var post = {}; var g = createModal({prefix: \"\"});\n"
                                                 "post.blocks = {rapid: [g.bind(\"comp\", {texts: {left: \"RL\"}}), "
                                                 "createVariable({prefix: \"X\"}).bind(\"x\")]};\n"));
    ASSERT_FALSE(texts.ok());
    EXPECT_NE(texts.error().message.find("texts keys must be whole numbers"), std::string::npos);
    auto after = PostProcessor::load(writeScript("badafter.js", "var post = {}; post.blocks = {after: [\"M8\"]};\n"));
    ASSERT_FALSE(after.ok());
    EXPECT_NE(after.error().message.find("post.blocks.after[0]: expected createPending()"), std::string::npos);
}

}  // namespace
}  // namespace camwb::post::test
