// The SINUMERIK 840D lathe post (posts/sinumerik840d-turn.js) on the Škoda SR 2000 machine file:
// the Kód 5 frame, DIAMON doubling X and DIAMOF not, F in mm/rev, rapids along one axis as the CL
// gives them, and the groove as the five R-parameter subprograms (mode B), every output read back
// by our SINUMERIK interpreter. The kernel services it needs (openFile/closeFile companion files,
// readPostFile) are tested in PostCompanionTest.cpp.
#include "CompanionResolver.h"
#include "PostTestSupport.h"

#include "base/AtomicFile.h"
#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <cmath>
#include <map>

namespace camwb::post::test {
namespace {

using namespace toolpath;
namespace fs = std::filesystem;

const std::string kPost = kPostsDir + "/sinumerik840d-turn.js";
const std::string kMachine = std::string(CAMWB_TEST_DATA_DIR) + "/resources/machines/skoda-sr2000-840d.json";
const std::string kSeedSpf = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/seed-001/reconstructed/";
const char* const kGrooveFiles[] = {"PODPROG_ZAPICH", "PODPROG_ZL", "PODPROG_ZP", "PODPROG_DNO_ZL", "PODPROG_DNO_ZP"};

constexpr AxisMask kX{AxisMask::kX};
constexpr AxisMask kZ{AxisMask::kZ};
constexpr AxisMask kXZ{AxisMask::kX | AxisMask::kZ};

// The thesis' Kód 1 inputs, as the groove operation puts them on its section.
std::vector<std::pair<std::string, double>> kod1(double fallback = 0)
{
    return {{"R0", 180}, {"R1", 185}, {"R2", 21.801}, {"R3", 170},  {"R4", 45}, {"R5", 6.71}, {"R6", 4.09},
            {"R7", 0.5}, {"R8", 0.5}, {"R9", 3},      {"R10", 0.8}, {"R11", 1}, {"R30", 1},   {"fallback", fallback}};
}

// A small lathe CL as the groove operation writes one: X a radius, Y never given, rapids along
// one axis, plunges in X, one diagonal slide, all in G95 at 0.2 mm/rev under G96 300 m/min.
Toolpath latheCl(const std::string& strategy = "groove-roughing", double fallback = 0)
{
    Toolpath p;
    SectionBegin section;
    section.operationName = "Groove";
    section.strategy = strategy;
    section.toolNumber = 5;
    section.feeds.cuttingMmPerMin = 0.2;
    section.strategyParameters = kod1(fallback);
    p.add(section);
    p.add(ToolChange{Tool{5, "groover", "groove", 3}});
    p.add(FeedModeChange{FeedMode::PerRevolution});
    p.add(Spindle{3000, true, 300});
    p.add(Coolant{CoolantMode::Flood});
    p.add(Rapid{{280, 0, 0}, kX});
    p.add(Rapid{{280, 0, 150.5}, kZ});
    p.add(Rapid{{176.25, 0, 150.5}, kX});
    p.add(Linear{{170, 0, 150.5}, 0.2, kX});
    p.add(Rapid{{176.25, 0, 150.5}, kX});
    p.add(Rapid{{176.25, 0, 153.1}, kZ});
    p.add(Linear{{169, 0, 153.1}, 0.2, kX});
    p.add(Linear{{168.5, 0, 151}, 0.2, kXZ});
    p.add(Rapid{{280, 0, 151}, kX});
    p.add(SectionEnd{});
    return p;
}

// The words of a block by address letter (X, Z, F, S; "LIMS=3000" as LIMS), without N.
std::map<std::string, double> addresses(const std::string& line)
{
    std::map<std::string, double> result;
    std::istringstream in(words(line));
    for (std::string word; in >> word;) {
        if (word[0] == ';')
            break;
        const std::size_t eq = word.find('=');
        std::size_t split = eq;
        if (eq == std::string::npos)
            for (split = 0; split < word.size() && std::isalpha(static_cast<unsigned char>(word[split]));)
                ++split;
        const std::string value = word.substr(eq == std::string::npos ? split : eq + 1);
        if (split > 0 && !value.empty() && (std::isdigit(static_cast<unsigned char>(value[0])) || value[0] == '-'))
            result[word.substr(0, split)] = std::stod(value);
    }
    return result;
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// Where a line is in the output (from line `from` on), as words without the block number; -1
// when it is not there.
int indexOf(const std::vector<std::string>& lines, const std::string& wordsOfLine, int from = 0)
{
    for (std::size_t i = static_cast<std::size_t>(std::max(from, 0)); i < lines.size(); ++i)
        if (lines[i] == wordsOfLine)
            return static_cast<int>(i);
    return -1;
}

struct Move {
    bool rapid;
    Vec3 to;
    AxisMask axes;
};

// The moves of a toolpath (rapids and feeds) with the axes each gives.
std::vector<Move> movesOf(const Toolpath& path)
{
    std::vector<Move> moves;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (const auto* r = std::get_if<Rapid>(&path.record(i)))
            moves.push_back({true, r->to, r->axes});
        else if (const auto* l = std::get_if<Linear>(&path.record(i)))
            moves.push_back({false, l->to, l->axes});
    }
    return moves;
}

// The NC read back where it may stop with an error: its diagnostics for the test to check.
Toolpath readBackAllowingErrors(const PostOutput& output, std::vector<nc::Diagnostic>& diagnostics)
{
    nc::InterpretOptions options;
    options.dialect = nc::Dialect::Sinumerik;
    options.fileName = "PART1.MPF";
    options.resolveProgram = companionResolver(output.files);
    ToolpathRecorder recorder;
    diagnostics = nc::interpret(output.text, options, recorder).diagnostics;
    return recorder.toolpath();
}

// The NC read back by our SINUMERIK interpreter, called programs found among `files`: no
// diagnostics.
Toolpath readBack(const PostOutput& output)
{
    std::vector<nc::Diagnostic> diagnostics;
    Toolpath path = readBackAllowingErrors(output, diagnostics);
    for (const nc::Diagnostic& d : diagnostics)
        ADD_FAILURE() << base::formatDiagnostic(d);
    return path;
}

class SinumerikTurnPost : public testing::Test {
protected:
    base::Result<PostOutput> tryRun(const Toolpath& path, std::map<std::string, std::string> properties = {},
                                    const std::string& postPath = kPost)
    {
        auto post = PostProcessor::load(postPath);
        if (!post)
            return post.error();
        RunOptions options;
        options.context = fixedContext();
        options.properties = std::move(properties);
        auto machine = kinematics::loadMachine(kMachine);
        EXPECT_TRUE(machine.ok()) << machine.error().toString();
        if (machine.ok())
            options.machine = machine.value();
        return post->run(path, options);
    }

    PostOutput run(const Toolpath& path, std::map<std::string, std::string> properties = {},
                   const std::string& postPath = kPost)
    {
        auto output = tryRun(path, std::move(properties), postPath);
        EXPECT_TRUE(output.ok()) << output.error().toString();
        return output.ok() ? output.value() : PostOutput{};
    }

    // The post copied into a folder of its own with the thesis' reconstructed subprograms as the
    // groove/ files it ships (the subprograms of the groove strategy are another branch's work):
    // mode B's mechanics with real SPF code.
    std::string postWithSeedSubprograms()
    {
        const fs::path dir = fs::path(writeScript("mode-b-folder", "")).parent_path() / "turn-mode-b";
        fs::create_directories(dir);
        fs::copy_file(kPost, dir / "sinumerik840d-turn.js", fs::copy_options::overwrite_existing);
        fs::create_directories(dir / "sinumerik840d-turn" / "groove");
        for (const char* name : kGrooveFiles)
            fs::copy_file(kSeedSpf + name + ".SPF",
                          dir / "sinumerik840d-turn" / "groove" / (std::string(name) + ".SPF"),
                          fs::copy_options::overwrite_existing);
        return (dir / "sinumerik840d-turn.js").string();
    }
};

TEST_F(SinumerikTurnPost, WritesTheKod5FrameInItsOrder)
{
    const std::vector<std::string> out = wordLines(run(latheCl()).text);
    const int frame[] = {indexOf(out, "G54 G18"),      indexOf(out, "G90 G71"), indexOf(out, "DIAMON"),
                         indexOf(out, "G0 X960.0000"),  // safe X before the tool: (280 + 200) * 2
                         indexOf(out, "T=5 D1"),       indexOf(out, "G95"),     indexOf(out, "G96 S300 LIMS=3000 M3"),
                         indexOf(out, "M8"),           indexOf(out, "M9 M5"),   indexOf(out, "M30")};
    for (std::size_t i = 0; i < std::size(frame); ++i) {
        EXPECT_GE(frame[i], 0) << i;
        if (i > 0)
            EXPECT_LT(frame[i - 1], frame[i]) << i;
    }
    EXPECT_EQ(out.back(), "M30");
}

TEST_F(SinumerikTurnPost, DiamonDoublesXAndDiamofWritesTheRadius)
{
    const Toolpath cl = latheCl("turning");
    const std::vector<Move> clMoves = movesOf(cl);
    for (const bool diameter : {true, false}) {
        const PostOutput output = run(cl, {{"diameterProgramming", diameter ? "true" : "false"}});
        const std::vector<std::string> out = wordLines(output.text);
        EXPECT_GE(indexOf(out, diameter ? "DIAMON" : "DIAMOF"), 0);
        EXPECT_LT(indexOf(out, diameter ? "DIAMOF" : "DIAMON"), 0);
        // The X words as written, in order, against the CL's radii (the first is the safe X).
        std::vector<double> written;
        for (const std::string& line : out)
            if ((startsWith(line, "G0") || startsWith(line, "G1") || startsWith(line, "X")) &&
                addresses(line).count("X"))
                written.push_back(addresses(line).at("X"));
        std::vector<double> expected{280 + 200};
        for (const Move& m : clMoves)
            if (m.axes.has(0) && (expected.size() == 1 || m.to.x != expected.back()))
                expected.push_back(m.to.x);
        ASSERT_EQ(written.size(), expected.size()) << output.text;
        for (std::size_t i = 0; i < written.size(); ++i)
            EXPECT_NEAR(written[i], expected[i] * (diameter ? 2 : 1), 1e-9) << i;

        // Read back: the control's moves are the CL's, X as a radius whatever the mode.
        const std::vector<Move> back = movesOf(readBack(output));
        ASSERT_EQ(back.size(), clMoves.size() + 1);  // + the safe X before the tool
        EXPECT_NEAR(back[0].to.x, 480, 1e-9);
        for (std::size_t i = 0; i < clMoves.size(); ++i) {
            EXPECT_EQ(back[i + 1].rapid, clMoves[i].rapid) << i;
            EXPECT_NEAR(back[i + 1].to.x, clMoves[i].to.x, 1e-9) << i;
            if (clMoves[i].axes.has(2))
                EXPECT_NEAR(back[i + 1].to.z, clMoves[i].to.z, 1e-9) << i;
        }
    }
}

TEST_F(SinumerikTurnPost, FeedInMmPerRevAndRapidsAlongOneAxis)
{
    const std::vector<std::string> out = wordLines(run(latheCl("turning")).text);
    int feeds = 0;
    for (const std::string& line : out) {
        const std::map<std::string, double> a = addresses(line);
        if (startsWith(line, "G0 ")) {
            EXPECT_EQ(a.count("X") + a.count("Z"), 1u) << line;
            EXPECT_EQ(a.count("F"), 0u) << line;
        }
        EXPECT_EQ(a.count("Y"), 0u) << line;
        if (a.count("F")) {
            EXPECT_DOUBLE_EQ(a.at("F"), 0.2) << line;
            ++feeds;
        }
    }
    EXPECT_EQ(feeds, 1) << "F is modal: written with the first G1 only";
    EXPECT_GE(indexOf(out, "G1 X340.0000 F0.2"), 0);
    EXPECT_GE(indexOf(out, "X337.0000 Z151.0000"), 0);  // the diagonal slide: G1 is modal
}

TEST_F(SinumerikTurnPost, ALatheMoveOffTheXZPlaneIsAnError)
{
    Toolpath cl = latheCl("turning");
    cl.add(Rapid{{280, 5, 151}});
    auto output = tryRun(cl);
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("the lathe has no Y axis"), std::string::npos) << output.error().toString();
    EXPECT_EQ(output.error().file, kPost);
    EXPECT_GT(output.error().line, 0);
}

TEST_F(SinumerikTurnPost, ModeBWritesTheInputBlockTheCallAndTheFiveSubprograms)
{
    const PostOutput output = run(latheCl(), {{"grooveOutput", "subprograms"}});
    const std::vector<std::string> out = wordLines(output.text);
    const int safeX = indexOf(out, "G0 X560.0000");  // the section's leading retract in X: 280 * 2
    const int r0 = indexOf(out, "R0=180 ;start point P: X, radius");
    const int r2 = indexOf(out, "R2=21.801 ;cone angle, deg");
    const int r30 = indexOf(out, "R30=1 ;safety distance");
    const int feed = indexOf(out, "F0.2");
    const int diamof = indexOf(out, "DIAMOF");
    const int call = indexOf(out, "PODPROG_ZAPICH");
    const int diamon = indexOf(out, "DIAMON", diamof);
    EXPECT_TRUE(safeX >= 0 && safeX < r0 && r0 < r2 && r2 < r30 && r30 < feed && feed < diamof && diamof < call &&
                call < diamon)
        << output.text;
    for (const char* name :
         {"R1=185", "R3=170", "R4=45", "R5=6.71", "R6=4.09", "R7=0.5", "R8=0.5", "R9=3", "R10=0.8", "R11=1"})
        EXPECT_NE(output.text.find(std::string(" ") + name + " ;"), std::string::npos) << name;
    // The section's moves are the subprograms' to make: no G1 in the main program.
    for (const std::string& line : out)
        EXPECT_FALSE(startsWith(line, "G1")) << line;

    ASSERT_EQ(output.files.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(output.files[i].name, std::string(kGrooveFiles[i]) + ".SPF");
        auto shipped = base::readTextFile(kPostsDir + "/sinumerik840d-turn/groove/" + kGrooveFiles[i] + ".SPF");
        ASSERT_TRUE(shipped.ok());
        EXPECT_EQ(output.files[i].text, shipped.value()) << "copied as shipped";
    }
    // Read back with the subprograms: no diagnostics, and after the two rapids in X (the safe X
    // before the tool and the section's retract) the moves of the thesis' own main program Kód 5
    // after its safe X: our subprograms make the thesis' 574 moves for Kód 1 (§5.2), whose inputs
    // reach none of the fixes.
    const std::vector<Move> back = movesOf(readBack(output));
    ToolpathRecorder kod5;
    nc::InterpretOptions kod5Options;
    kod5Options.resolveProgram = nc::folderResolver(kSeedSpf, {".SPF"});
    const nc::InterpretResult kod5Run =
        nc::interpretFile(std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/nc/seed-001/KOD5.MPF", nc::Dialect::Sinumerik,
                          kod5Options, kod5);
    ASSERT_TRUE(kod5Run.completed);
    const std::vector<Move> thesis = movesOf(kod5.toolpath());
    ASSERT_EQ(thesis.size(), 1u + 574u);  // Kód 5's G0 X=R0+200, then the subprograms' moves
    ASSERT_EQ(back.size(), thesis.size() + 1);
    EXPECT_NEAR(back[0].to.x, 480, 1e-9);
    EXPECT_NEAR(back[1].to.x, 280, 1e-9);
    for (std::size_t i = 1; i < thesis.size(); ++i) {
        EXPECT_EQ(back[i + 1].rapid, thesis[i].rapid) << i;
        // X and Z as the thesis' program gives them (DIAMON/DIAMOF make the interpreter's Y a
        // known 0: a lathe's tool works where Y is 0).
        EXPECT_EQ(back[i + 1].axes.bits & 5, thesis[i].axes.bits & 5) << i;
        if (i > 1)  // N72 G0 Z runs at the X the caller left: 280 here, Kód 5's 200 there
            EXPECT_NEAR(back[i + 1].to.x, thesis[i].to.x, 1e-7) << i;
        EXPECT_NEAR(back[i + 1].to.z, thesis[i].to.z, 1e-7) << i;
    }
}

// After the call the program stops unless the subprograms finished the groove (R31 = 1): the
// thesis' own subprograms never set R31, so with them in the post's place the program stops
// there with alarm 65019 (on the control: after an alarm in PODPROG_ZAPICH was acknowledged).
TEST_F(SinumerikTurnPost, ModeBStopsWhenTheSubprogramsDidNotFinishTheGroove)
{
    const PostOutput output = run(latheCl(), {{"grooveOutput", "subprograms"}}, postWithSeedSubprograms());
    std::vector<nc::Diagnostic> diagnostics;
    const std::vector<Move> back = movesOf(readBackAllowingErrors(output, diagnostics));
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_NE(diagnostics[0].message.find("alarm 65019 (SETAL): stopped: groove Groove not finished"),
              std::string::npos)
        << diagnostics[0].message;
    EXPECT_EQ(back.size(), 2u + 574u);  // the thesis' moves ran; nothing after the call
}

TEST_F(SinumerikTurnPost, ModeBWritesOtherSectionsExpanded)
{
    const PostOutput output = run(latheCl("turning"), {{"grooveOutput", "subprograms"}}, postWithSeedSubprograms());
    EXPECT_TRUE(output.files.empty());
    EXPECT_EQ(output.text.find("PODPROG_ZAPICH"), std::string::npos);
    EXPECT_GE(indexOf(wordLines(output.text), "G1 X340.0000 F0.2"), 0);
}

TEST_F(SinumerikTurnPost, ModeBRefusesTheNarrowGrooveFallback)
{
    auto output = tryRun(latheCl("groove-roughing", 1), {{"grooveOutput", "subprograms"}}, postWithSeedSubprograms());
    ASSERT_FALSE(output.ok());
    EXPECT_NE(output.error().message.find("narrow-groove fallback"), std::string::npos) << output.error().toString();
    EXPECT_NE(output.error().message.find("grooveOutput=expanded"), std::string::npos);
    // Mode A writes it as blocks.
    EXPECT_TRUE(tryRun(latheCl("groove-roughing", 1)).ok());
}

}  // namespace
}  // namespace camwb::post::test
