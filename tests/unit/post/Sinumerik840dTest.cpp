// The SINUMERIK 840D sl post on the DMU 50-class B/C table: five-axis moves under TRAORI with the
// tool vector A3= B3= C3= (normalised, the CL's within 1e-6), every TRAORI closed by TRAFOOF,
// G93 feeds that are the block's time, and errors instead of output where the machine cannot do it.
#include "PostTestSupport.h"

#include "kinematics/Machine.h"
#include "kinematics/PoseSolver.h"
#include "toolpath/ClImport.h"

#include <cmath>
#include <map>
#include <random>

namespace camwb::post::test {
namespace {

using namespace toolpath;

const std::string kPost = kPostsDir + "/sinumerik840d.js";
const std::string kMachines = std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines/";

// The words of a block by address ("X", "A3", "F"; "A3=0.5" and "X1.5" alike), without the N number.
std::map<std::string, double> addresses(const std::string& line)
{
    std::map<std::string, double> result;
    std::istringstream in(words(line));
    for (std::string word; in >> word;) {
        const std::size_t eq = word.find('=');
        std::size_t split = eq;
        if (eq == std::string::npos) {
            split = 0;
            while (split < word.size() && std::isalpha(static_cast<unsigned char>(word[split])))
                ++split;
        }
        const std::string value = word.substr(eq == std::string::npos ? split : eq + 1);
        if (split == 0 || value.empty() || !(std::isdigit(static_cast<unsigned char>(value[0])) || value[0] == '-'))
            continue;
        result[word.substr(0, split)] = std::stod(value);
    }
    return result;
}

bool has(const std::string& line, const std::string& word)
{
    std::istringstream in(words(line));
    for (std::string w; in >> w;)
        if (w == word)
            return true;
    return false;
}

class Sinumerik840dPost : public testing::Test {
protected:
    void SetUp() override
    {
        auto loaded = PostProcessor::load(kPost);
        ASSERT_TRUE(loaded.ok()) << loaded.error().toString();
        m_post = std::move(loaded).value();
    }

    base::Result<PostOutput> tryRun(const Toolpath& path, std::map<std::string, std::string> properties = {},
                                    const std::string& machineId = "dmu50-840d")
    {
        RunOptions options;
        options.context = fixedContext();
        options.properties = std::move(properties);
        auto machine = kinematics::loadMachine(kMachines + machineId + ".json");
        EXPECT_TRUE(machine.ok()) << machine.error().toString();
        if (machine.ok())
            options.machine = machine.value();
        return m_post->run(path, options);
    }

    std::vector<std::string> run(const Toolpath& path, std::map<std::string, std::string> properties = {})
    {
        auto output = tryRun(path, std::move(properties));
        EXPECT_TRUE(output.ok()) << output.error().toString();
        return output.ok() ? lines(output.value().text) : std::vector<std::string>{};
    }

    static Toolpath start()
    {
        Toolpath path;
        path.add(SectionBegin{"Swarf", "swarf", 1, {}});
        path.add(ToolChange{Tool{1, "D10", "ball", 10}});
        path.add(Spindle{8000, true});
        return path;
    }

    std::optional<PostProcessor> m_post;
};

TEST_F(Sinumerik840dPost, ToolVectorIsNormalisedAndTheClsWithin1e6)
{
    std::mt19937 random(840);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), tilt(0, 110 * M_PI / 180);
    Toolpath path = start();
    std::vector<Vec3> vectors;
    for (int n = 0; n < 200; ++n) {
        const double a = angle(random), t = tilt(random);
        vectors.push_back({std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)});
        // Every other one at three times its length, as a hand-written trace may give it: written normalised.
        path.add(ToolAxisMove{{double(n), 0, 5}, vectors.back() * (n % 2 ? 3.0 : 1.0), 500});
    }
    std::size_t seen = 0;
    for (const std::string& line : run(path)) {
        const auto words = addresses(line);
        if (!words.count("A3"))
            continue;
        ASSERT_TRUE(words.count("B3") && words.count("C3")) << line << ": the control sets a missing component to 0";
        ASSERT_LT(seen, vectors.size());
        const Vec3 written{words.at("A3"), words.at("B3"), words.at("C3")};
        EXPECT_NEAR(written.length(), 1, 1e-6) << line;
        EXPECT_NEAR((written - vectors[seen]).length(), 0, 1e-6) << line;
        ++seen;
    }
    EXPECT_EQ(seen, vectors.size());
}

TEST_F(Sinumerik840dPost, EveryTraoriIsClosedByTrafoofBeforeAToolChangeOrTheEnd)
{
    Toolpath path = start();
    path.add(Rapid{{0, 0, 50}});
    path.add(ToolAxisMove{{0, 0, 10}, {0.5, 0, std::sqrt(0.75)}, 0});
    path.add(ToolAxisMove{{10, 0, 0}, {0, 0.5, std::sqrt(0.75)}, 400});
    path.add(SectionEnd{});
    path.add(SectionBegin{"Second", "swarf", 2, {}});
    path.add(ToolChange{Tool{2, "D6", "ball", 6}});
    path.add(ToolAxisMove{{10, 0, 0}, {0, -0.5, std::sqrt(0.75)}, 400});
    path.add(Linear{{20, 0, 0}, 400});  // along +Z: the vector goes back to vertical in the same block
    path.add(ToolAxisMove{{30, 0, 0}, {0.1, 0, std::sqrt(0.99)}, 400});
    const std::vector<std::string> all = run(path);
    bool open = false;
    int runs = 0;
    for (const std::string& line : all) {
        if (has(line, "TRAORI")) {
            EXPECT_FALSE(open) << line;
            open = true;
            ++runs;
        } else if (has(line, "TRAFOOF")) {
            EXPECT_TRUE(open) << line;
            open = false;
        } else if (has(line, "M6") || has(line, "M30")) {
            EXPECT_FALSE(open) << line << ": TRAORI still on";
        } else if (addresses(line).count("A3")) {
            EXPECT_TRUE(open) << line << ": a tool vector without TRAORI";
        }
    }
    EXPECT_EQ(runs, 2);
    EXPECT_FALSE(open);
    const auto vertical =
        std::find_if(all.begin(), all.end(), [](const std::string& l) { return words(l).rfind("X20.000", 0) == 0; });
    ASSERT_NE(vertical, all.end());
    EXPECT_EQ(words(*vertical), "X20.000 A3=0 B3=0 C3=1");
}

TEST_F(Sinumerik840dPost, AFiveAxisMoveAfterAVerticalOneWritesItsVectorAgain)
{
    Toolpath path = start();
    const Vec3 tilted{0, -0.5, std::sqrt(0.75)};
    path.add(ToolAxisMove{{0, 0, 5}, tilted, 0});
    path.add(Linear{{10, 0, 5}, 400});                // the tool vertical: A3=0 B3=0 C3=1
    path.add(ToolAxisMove{{20, 0, 5}, tilted, 400});  // tilted again: the vector must be written
    const std::vector<std::string> all = run(path);
    ASSERT_GE(all.size(), 4u);
    const std::vector<std::string> last{words(all[all.size() - 8]), words(all[all.size() - 7])};
    EXPECT_EQ(last[0], "G1 X10.000 A3=0 B3=0 C3=1 F400") << last[0];
    EXPECT_EQ(last[1], "X20.000 A3=0 B3=-0.5 C3=0.8660254") << last[1];
}

TEST_F(Sinumerik840dPost, InverseTimeFeedIsTheBlocksLengthOverItsFeed)
{
    Toolpath path = start();
    path.add(Rapid{{0, 0, 50}});
    path.add(ToolAxisMove{{0, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 0});
    const std::vector<std::pair<Vec3, double>> moves = {
        {{12.5, 3, 1}, 800}, {{13, 3, 1}, 1200}, {{-40, 7.25, -2}, 250}, {{-40.001, 7.25, -2}, 600}};
    for (std::size_t n = 0; n < moves.size(); ++n)
        path.add(ToolAxisMove{
            moves[n].first, {0.01 * double(n), 0.3, std::sqrt(0.91 - 1e-4 * double(n * n))}, moves[n].second});
    path.add(ToolAxisMove{{-40.001, 7.25, -2}, {0.1, 0.3, std::sqrt(0.9)}, 300});  // the tip stands: deg/min
    const std::vector<std::string> all = run(path, {{"inverseTime", "true"}});
    std::vector<double> feeds;
    bool g93 = false;
    for (const std::string& line : all) {
        g93 = has(line, "G93") ? true : has(line, "G94") ? false : g93;
        const auto words = addresses(line);
        if (words.count("F") && (words.count("X") || words.count("A3"))) {
            EXPECT_TRUE(g93) << line;
            feeds.push_back(words.at("F"));
        }
    }
    EXPECT_FALSE(g93) << "G94 again after the five-axis moves";
    ASSERT_EQ(feeds.size(), moves.size() + 1);
    Vec3 from{0, 0, 5};
    for (std::size_t n = 0; n < moves.size(); ++n) {
        const double minutes = (moves[n].first - from).length() / moves[n].second;
        EXPECT_NEAR(feeds[n], 1 / minutes, 0.5e-4 + 1e-9 / minutes) << n;
        from = moves[n].first;
    }
    const double turn =
        std::acos(Vec3{0.03, 0.3, std::sqrt(0.91 - 9e-4)}.dot(Vec3{0.1, 0.3, std::sqrt(0.9)})) * 180 / M_PI;
    EXPECT_NEAR(feeds.back(), 300 / turn, 0.5e-4);
}

TEST_F(Sinumerik840dPost, AFiveAxisMoveOnAMachineWithoutAChainIsAnError)
{
    Toolpath path = start();
    path.add(ToolAxisMove{{0, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 500});
    auto output = tryRun(path, {}, "emco-concept-mill-105");
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("machine emco-concept-mill-105 has no five-axis kinematic chain"),
              std::string::npos)
        << output.error().toString();
    // A vertical one is a three-axis move there.
    Toolpath vertical = start();
    vertical.add(ToolAxisMove{{0, 0, 5}, {0, 0, 1}, 500});
    auto written = tryRun(vertical, {}, "emco-concept-mill-105");
    ASSERT_TRUE(written.ok()) << written.error().toString();
    EXPECT_EQ(written.value().text.find("TRAORI"), std::string::npos);
}

TEST_F(Sinumerik840dPost, AFeedAboveTheMachinesMaximumIsAnErrorInInverseTime)
{
    Toolpath path = start();
    path.add(Rapid{{0, 0, 50}});
    path.add(ToolAxisMove{{0, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 24000});
    EXPECT_TRUE(tryRun(path, {{"inverseTime", "true"}}).ok());
    path.add(ToolAxisMove{{10, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 24001});
    auto output = tryRun(path, {{"inverseTime", "true"}});
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("feed 24001 mm/min is above"), std::string::npos)
        << output.error().toString();
    EXPECT_NE(output.error().message.find("CL record 5 ToolAxisMove"), std::string::npos) << output.error().toString();
}

TEST_F(Sinumerik840dPost, AnInverseTimeBeyondTheControlsRangeIsAnError)
{
    Toolpath path = start();
    path.add(Rapid{{0, 0, 50}});
    path.add(ToolAxisMove{{0, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 0});
    path.add(ToolAxisMove{{0.02, 0, 5}, {0, 0.3, std::sqrt(0.91)}, 20000});  // F1000000: 0.06 ms
    EXPECT_TRUE(tryRun(path).ok()) << "G94: F20000 is a feed the machine has";
    auto output = tryRun(path, {{"inverseTime", "true"}});
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("beyond the largest value the control reads"), std::string::npos)
        << output.error().toString();
}

TEST_F(Sinumerik840dPost, AToolVectorBeyondTheTiltIsAnError)
{
    Toolpath path = start();
    path.add(ToolAxisMove{{0, 0, 5}, {std::sin(1.93), 0, std::cos(1.93)}, 500});  // 110.6 deg from Z
    auto output = tryRun(path);
    ASSERT_FALSE(output.ok());
    // The kernel's pose solver (or, without its five-axis planning, the post) names the limit.
    const std::string& message = output.error().message;
    EXPECT_TRUE(message.find("B axis reaches -5..110 deg") != std::string::npos ||
                message.find("B110.5809 is above the axis' limit 110") != std::string::npos)
        << output.error().toString();
    Toolpath within = start();
    within.add(ToolAxisMove{{0, 0, 5}, {std::sin(1.91), 0, std::cos(1.91)}, 500});  // 109.4 deg
    EXPECT_TRUE(tryRun(within).ok());
}

}  // namespace
}  // namespace camwb::post::test

namespace camwb::post::test {
namespace {

// The machine file's chain as SINUMERIK counts table axes (V1 = -Y, V2 = -Z): a tool tilted towards
// +X of the workpiece is B+30 at C0, towards -X B+30 at C180 (B reaches only -5 the other way).
TEST(Dmu50Machine, ChainCountsTableAxesAsSinumerikDoes)
{
    auto machine = kinematics::loadMachine(kMachines + "dmu50-840d.json");
    ASSERT_TRUE(machine.ok()) << machine.error().toString();
    ASSERT_TRUE(machine.value().kinematics.fiveAxis());
    EXPECT_EQ(machine.value().kinematics.type, kinematics::ChainType::TableTable);
    const kinematics::PoseSolver solver(machine.value());
    const double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
    auto plusX = solver.solve({{0, 0, 0}, {s, 0, c}}, nullptr);
    ASSERT_TRUE(plusX.ok()) << plusX.error().toString();
    EXPECT_NEAR(plusX.value().pose.rotaryDeg[0], 30, 1e-9);
    EXPECT_NEAR(std::remainder(plusX.value().pose.rotaryDeg[1], 360), 0, 1e-9);
    auto minusX = solver.solve({{0, 0, 0}, {-s, 0, c}}, nullptr);
    ASSERT_TRUE(minusX.ok()) << minusX.error().toString();
    EXPECT_NEAR(minusX.value().pose.rotaryDeg[0], 30, 1e-9);
    EXPECT_NEAR(std::abs(std::remainder(minusX.value().pose.rotaryDeg[1], 360)), 180, 1e-9);
}

}  // namespace
}  // namespace camwb::post::test

namespace camwb::post::test {
namespace {

// Three-axis output is the 828D post's, word for word: the 828D goldens' inputs through both posts
// give the same blocks but for the header's post and machine and the table home after M6.
TEST(Sinumerik840dThreeAxis, WritesWhatThe828dPostWrites)
{
    auto sinumerik840d = PostProcessor::load(kPost);
    auto emco = PostProcessor::load(kEmcoPost);
    ASSERT_TRUE(sinumerik840d.ok() && emco.ok());
    std::map<std::string, std::string> properties;
    auto blocks = [&properties](PostProcessor& post, const toolpath::Toolpath& path, const std::string& machineId) {
        RunOptions options;
        options.context = fixedContext();
        options.properties = properties;
        options.machine = kinematics::loadMachine(kMachines + machineId + ".json").value();
        auto output = post.run(path, options);
        EXPECT_TRUE(output.ok()) << output.error().toString();
        std::vector<std::string> kept;
        for (const std::string& line : wordLines(output.ok() ? output.value().text : ""))
            if (line.rfind(";generated by", 0) != 0 && line.rfind(";machine ", 0) != 0 && line != "G0 B0 C=DC(0)")
                kept.push_back(line);
        return kept;
    };
    for (const char* name : {"every-record", "arcs", "cycles", "cycles-per-hole", "inch", "toolchange-xyz"}) {
        const std::string dir = kPostsDir + "/sinumerik828d-emco/tests/" + name;
        const std::string input = dir + "/input.trace";
        properties.clear();
        std::ifstream lines(dir + "/properties");
        for (std::string line; std::getline(lines, line);)
            if (const std::size_t eq = line.find('='); eq != std::string::npos && line[0] != '#')
                properties[line.substr(0, eq)] = line.substr(eq + 1);
        auto cl = toolpath::readClFile(input, *toolpath::clFormatFromExtension(input));
        ASSERT_TRUE(cl.ok()) << cl.error().toString();
        const std::vector<std::string> expected = blocks(emco.value(), cl.value().toolpath, "emco-concept-mill-105");
        EXPECT_GT(expected.size(), 8u) << name;
        EXPECT_EQ(blocks(sinumerik840d.value(), cl.value().toolpath, "dmu50-840d"), expected) << name;
    }
}

}  // namespace
}  // namespace camwb::post::test
