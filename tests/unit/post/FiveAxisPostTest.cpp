// The five-axis path of a post run: rapid5D/linear5D templates write the tip (or the machine's
// linear axes) and the rotary words the kernel chose, onFiveAxisBegin/End frame each five-axis
// section, onLinear5D gets the machine pose, post.fiveAxis is checked when the post loads.
#include "PostTestSupport.h"

#include <cmath>

namespace camwb::post::test {
namespace {

using namespace toolpath;

// A B/C table in seed 000's convention: B -120..+30 about +Y, C endless about +Z.
kinematics::Machine bcTable()
{
    kinematics::Machine m;
    m.id = "test-bc";
    m.axes = {{"X", false, -1000, 1000},
              {"Y", false, -1000, 1000},
              {"Z", false, -1000, 1000},
              {"B", true, -120, 30},
              {"C", true, -1e300, 1e300, true}};
    m.maxCuttingFeedMmPerMin = 5000;
    m.kinematics.type = kinematics::ChainType::TableTable;
    m.kinematics.joints = {{"B", true, {0, 1, 0}, {}}, {"C", true, {0, 0, 1}, {}}};
    m.kinematics.preferredJoint = 0;
    m.kinematics.preferredSign = -1;  // B < 0: the branch that reaches furthest (-120)
    return m;
}

std::string fivePost(const std::string& output, const std::string& extra = "")
{
    return R"JS(
var post = {id: "five", capabilities: {maxAxes: 5, tolerance: 0.01}, fiveAxis: {output: ")JS" +
           output + R"JS(", feed: "combined"}};
var f = createFormat({decimals: 3, trim: true, forceSign: true});
var a = createFormat({decimals: 3, trim: true, forceSign: true});
var x = createVariable({prefix: "X"}, f), y = createVariable({prefix: "Y"}, f), z = createVariable({prefix: "Z"}, f);
var b = createVariable({prefix: "B"}, a), c = createVariable({prefix: "C"}, a);
var feed = createVariable({prefix: "F"}, createFormat({decimals: 0}));
post.blocks = {
    rapid: ["L", x.bind("x"), y.bind("y"), z.bind("z"), "FMAX"],
    linear: ["L", x.bind("x"), y.bind("y"), z.bind("z"), feed.bind("feed")],
    rapid5D: ["L", x.bind("x"), y.bind("y"), z.bind("z"), c.bind("c"), b.bind("b"), "FMAX"],
    linear5D: ["L", x.bind("x"), y.bind("y"), z.bind("z"), c.bind("c"), b.bind("b"), feed.bind("feed")]
};
function onFiveAxisBegin(s) { writeBlock("BEGIN", s.output, "C" + a.format(s.c), "B" + a.format(s.b)); }
function onFiveAxisEnd(pose) {
    var t = getFiveAxisTravel();
    writeBlock("END", "C" + a.format(pose.c), "BMIN" + a.format(t.b.min), "CMAX" + a.format(t.c.max));
    x.reset(); y.reset(); z.reset();
}
)JS" + extra;
}

base::Result<PostOutput> runFive(const std::string& source, const Toolpath& path)
{
    auto post = PostProcessor::load(writeScript("five.js", source));
    if (!post)
        return post.error();
    RunOptions options;
    options.context = fixedContext();
    options.machine = bcTable();
    return post->run(path, options);
}

Vec3 tilted(double tiltDeg, double azimuthDeg)
{
    const double t = tiltDeg * M_PI / 180, az = azimuthDeg * M_PI / 180;
    return {std::sin(t) * std::cos(az), std::sin(t) * std::sin(az), std::cos(t)};
}

Toolpath program()
{
    Toolpath tp;
    tp.add(SectionBegin{"flat", "profile", 1});
    tp.add(Rapid{{0, 0, 50}});
    tp.add(Linear{{10, 0, 50}, 300});
    tp.add(SectionEnd{});
    tp.add(SectionBegin{"tilted", "swarf", 1});
    tp.add(ToolAxisMove{{0, 0, 20}, tilted(30, 0), 0});
    tp.add(ToolAxisMove{{0, 0, 0}, tilted(30, 0), 600});
    tp.add(ToolAxisMove{{20, 0, 0}, tilted(30, 30), 600});
    tp.add(SectionEnd{});
    tp.add(Rapid{{0, 0, 50}});
    return tp;
}

TEST(FiveAxisPost, TipOutputWritesTheWorkpieceTipAndTheChosenRotaries)
{
    auto output = runFive(fivePost("tip"), program());
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(wordLines(output->text),
              (std::vector<std::string>{"L X+0 Y+0 Z+50 FMAX", "L X+10 F300",
                                        // B-30 C+0 tilts the tool towards +X (K = (-cosC sinB, ..));
                                        // the section's first rapid goes over in X/Y (Y+0 is
                                        // written already), then down.
                                        "BEGIN tip C+0 B-30", "L X+0 C+0 B-30 FMAX", "L Z+20 FMAX", "L Z+0 F600",
                                        "L X+20 C-30", "END C-30 BMIN-30 CMAX+0",
                                        // Unknown after the section: X/Y first, then Z.
                                        "L X+0 Y+0 FMAX", "L Z+50 FMAX"}));
}

TEST(FiveAxisPost, MachineOutputIsLinearisedAndItsFeedConverted)
{
    auto output = runFive(fivePost("machine"), program());
    ASSERT_TRUE(output.ok()) << output.error().toString();
    const auto lines = wordLines(output->text);
    // The move that turns C by 30 degrees about MRZP is cut into many blocks; each has an F.
    int turning = 0;
    for (const std::string& line : lines)
        if (line.rfind("L ", 0) == 0 && line.find(" C-") != std::string::npos && line.find(" F") != std::string::npos)
            ++turning;
    EXPECT_GT(turning, 10) << output->text;
    // The approach: the tip over (0, 0, 20) is machine X-10 Z+17.321 at B-30 (seed 000 eq. 22:
    // Px = sinB Qz); the plunge moves only linear axes, so F is the tip's.
    EXPECT_NE(std::find(lines.begin(), lines.end(), "L X-10 C+0 B-30 FMAX"), lines.end()) << output->text;
    EXPECT_NE(std::find(lines.begin(), lines.end(), "L Z+17.321 FMAX"), lines.end()) << output->text;
    EXPECT_NE(std::find(lines.begin(), lines.end(), "L X+0 Z+0 F600"), lines.end()) << output->text;
}

TEST(FiveAxisPost, OnLinear5DGetsTheMachinePose)
{
    const std::string source = R"JS(
var post = {id: "five", capabilities: {maxAxes: 5}};
function onLinear5D(x, y, z, i, j, k, feed, m) {
    writeBlock(m.kind, "B" + m.b.toFixed(3), "C" + m.c.toFixed(3), "K" + k.toFixed(3), m.pole ? "POLE" : "");
}
)JS";
    Toolpath tp;
    tp.add(ToolAxisMove{{0, 0, 0}, tilted(30, 0), 600});
    tp.add(ToolAxisMove{{1, 0, 0}, {0, 0, 1}, 600});
    auto output = runFive(source, tp);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(wordLines(output->text),
              (std::vector<std::string>{"move B-30.000 C0.000 K0.866", "move B0.000 C0.000 K1.000 POLE"}));
}

TEST(FiveAxisPost, MalformedFiveAxisDeclarationsAreLoadErrors)
{
    auto load = [](const std::string& source) { return PostProcessor::load(writeScript("five.js", source)); };
    auto unknown = load("var post = {id: 'five', capabilities: {maxAxes: 5}, fiveAxis: {ouptut: 'tip'}};");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("post.fiveAxis.ouptut is not a five-axis setting"), std::string::npos);
    auto value = load("var post = {id: 'five', capabilities: {maxAxes: 5}, fiveAxis: {output: 'tcp'}};");
    ASSERT_FALSE(value.ok());
    EXPECT_NE(value.error().message.find("post.fiveAxis.output"), std::string::npos);
    auto threeAxis = load("var post = {id: 'five', fiveAxis: {output: 'tip'}};");
    ASSERT_FALSE(threeAxis.ok());
    EXPECT_NE(threeAxis.error().message.find("maxAxes 5"), std::string::npos);
}

TEST(FiveAxisPost, APoseOutOfReachStopsTheRunNamingTheRecord)
{
    Toolpath tp;
    tp.add(ToolAxisMove{{0, 0, 0}, tilted(30, 0), 600});
    tp.add(ToolAxisMove{{0, 0, 0}, tilted(125, 0), 600});
    auto output = runFive(fivePost("tip"), tp);
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("CL record 1 ToolAxisMove"), std::string::npos) << output.error().message;
}

TEST(FiveAxisPost, AMachineWithoutAChainRefusesFiveAxisMoves)
{
    auto post = PostProcessor::load(writeScript("five.js", fivePost("tip")));
    ASSERT_TRUE(post.ok());
    RunOptions options;
    options.context = fixedContext();
    options.machine = bcTable();
    options.machine->kinematics = {};
    auto output = post->run(program(), options);
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("machine test-bc has no five-axis kinematic chain"), std::string::npos)
        << output.error().message;
}

}  // namespace
}  // namespace camwb::post::test
