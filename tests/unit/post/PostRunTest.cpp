// Running posts: the per-call script budget, output streamed atomically into files, where posts are
// found (user folders over built-in ones), and the kernel services around the moves.
#include "PostTestSupport.h"

#include "post/OutputWriter.h"
#include "post/PostRegistry.h"
#include "post/detail/ScriptWatchdog.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>

namespace camwb::post::test {
namespace {

using namespace toolpath;
namespace fs = std::filesystem;

base::Result<PostOutput> runWith(const std::string& name, const std::string& source, const Toolpath& path,
                                 std::chrono::milliseconds budget = std::chrono::seconds(10))
{
    auto post = PostProcessor::load(writeScript(name, source), budget);
    if (!post)
        return post.error();
    RunOptions options;
    options.context = fixedContext();
    options.scriptBudget = budget;
    return post->run(path, options);
}

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

fs::path freshDir(const std::string& name)
{
    const fs::path dir = fs::path(testing::TempDir()) / ("camwb-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// No test here measures time: a runaway loop never ends by itself, so being interrupted is the
// outcome to check, and the deadline bookkeeping is checked against a clock the test sets.
TEST(ScriptBudget, RunawayHandlerIsInterruptedWithItsPlace)
{
    auto output = runWith("runaway.js", "var post = {};\nfunction onOpen() {\n  while (true) {}\n}\n", {},
                          std::chrono::milliseconds(200));
    ASSERT_FALSE(output.ok());
    EXPECT_EQ(output.error().message,
              "the post script ran longer than its budget of 0.2 s and was interrupted (in onOpen)");
    EXPECT_NE(output.error().file.find("runaway.js"), std::string::npos);
}

TEST(ScriptBudget, RunawayTopLevelCodeFailsTheLoad)
{
    auto post =
        PostProcessor::load(writeScript("loops.js", "var post = {};\nfor (;;) {}\n"), std::chrono::milliseconds(200));
    ASSERT_FALSE(post.ok());
    EXPECT_EQ(post.error().message,
              "the post script ran longer than its budget of 0.2 s while loading and was interrupted");
}

// A clock that stands still until the test moves it.
struct ManualClock {
    std::shared_ptr<std::atomic<long long>> seconds = std::make_shared<std::atomic<long long>>(100);
    ScriptWatchdog::Clock clock() const
    {
        return [s = seconds] { return std::chrono::nanoseconds(std::chrono::seconds(s->load())); };
    }
    void set(long long value) { seconds->store(value); }
};

TEST(ScriptWatchdog, TheBudgetIsPerCallNotPerRun)
{
    QJSEngine engine;
    ManualClock time;
    ScriptWatchdog watchdog(engine, std::chrono::seconds(10), time.clock());
    // Three calls of 8 s each: 24 s in all, more than the budget; none is interrupted.
    for (long long start : {100, 108, 116}) {
        time.set(start);
        watchdog.enter();
        EXPECT_EQ(engine.evaluate("1 + 1").toInt(), 2);
        time.set(start + 8);
        EXPECT_FALSE(watchdog.expired()) << "call from " << start << " s";
        EXPECT_FALSE(watchdog.leave());
    }
    EXPECT_FALSE(watchdog.expired());  // between calls nothing is armed
}

TEST(ScriptWatchdog, NestedCallsKeepTheOutermostDeadline)
{
    QJSEngine engine;
    ManualClock time;
    ScriptWatchdog watchdog(engine, std::chrono::seconds(10), time.clock());
    watchdog.enter();
    time.set(108);
    watchdog.enter();  // a handler called from a handler: still due at 110
    time.set(111);
    EXPECT_TRUE(watchdog.expired());
}

TEST(ScriptWatchdog, ACallPastItsDeadlineIsInterrupted)
{
    QJSEngine engine;
    ManualClock time;
    ScriptWatchdog watchdog(engine, std::chrono::seconds(10), time.clock());
    watchdog.enter();
    time.set(111);  // the loop below runs until the watcher sees the deadline passed
    const QJSValue result = engine.evaluate("for (;;) {}");
    EXPECT_TRUE(result.isError());
    EXPECT_TRUE(watchdog.leave());
    // The engine runs again afterwards.
    watchdog.enter();
    EXPECT_EQ(engine.evaluate("6 * 7").toInt(), 42);
    EXPECT_FALSE(watchdog.leave());
}

TEST(RunToFile, WritesWhatRunReturnsStreamedInChunks)
{
    auto post = PostProcessor::load(kEmcoPost);
    ASSERT_TRUE(post.ok()) << post.error().toString();
    Toolpath path;
    path.add(Rapid{{0, 0, 10}});
    for (int i = 0; i < 60000; ++i)  // about 1.5 MB: more than one chunk of the stream
        path.add(Linear{{static_cast<double>(i % 100), static_cast<double>(i / 100), -1}, 500.0 + i % 7});
    RunOptions options;
    options.context = fixedContext();
    const fs::path dir = freshDir("runtofile");
    auto summary = post->runToFile(path, options, (dir / "out.mpf").string());
    ASSERT_TRUE(summary.ok()) << summary.error().toString();
    auto inMemory = post->run(path, options);
    ASSERT_TRUE(inMemory.ok());
    const std::string written = readFile(dir / "out.mpf");
    EXPECT_GT(written.size(), std::size_t(1) << 20);
    EXPECT_EQ(written, inMemory->text);
    EXPECT_EQ(summary->bytes, written.size());
    EXPECT_EQ(summary->lines, inMemory->lineOperation.size());
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);  // no temporary left
}

TEST(RunToFile, AFailedRunLeavesTheOutputAsItWas)
{
    const std::string script = writeScript("failslate.js", R"JS(var post = {};
function onRapid(x, y, z) { writeln("G0 X" + x); if (x > 1) error("refused"); }
)JS");
    auto post = PostProcessor::load(script);
    ASSERT_TRUE(post.ok()) << post.error().toString();
    Toolpath path;
    path.add(Rapid{{1, 0, 0}});
    path.add(Rapid{{2, 0, 0}});
    const fs::path dir = freshDir("keeps");
    std::ofstream(dir / "out.nc") << "previous\n";
    RunOptions options;
    options.context = fixedContext();
    auto summary = post->runToFile(path, options, (dir / "out.nc").string());
    ASSERT_FALSE(summary.ok());
    EXPECT_EQ(summary.error().message, "refused (in onRapid, CL record 1 Rapid)");
    EXPECT_EQ(readFile(dir / "out.nc"), "previous\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_FALSE(post->runToFile(path, options, (dir / "no-such-dir" / "out.nc").string()).ok());
}

TEST(PostRegistry, UserFoldersOverrideBuiltInOnesAndTheListingSaysSo)
{
    const fs::path user = freshDir("user-posts");
    std::ofstream(user / "sinumerik828d-emco.js") << "var post = {};\n";
    std::ofstream(user / "mine.js") << "var post = {};\n";
    std::ofstream(user / "notes.txt") << "not a post\n";
    const std::vector<base::DataDir> dirs{{user.string(), false}, {kPostsDir, true}, {kPostsDir, true}};
    const std::vector<PostEntry> posts = listPosts(dirs);
    ASSERT_EQ(posts.size(), 6u);  // sorted by id; the built-in folder twice is still one folder
    EXPECT_EQ(posts[0].id, "heidenhain-itnc530");
    EXPECT_TRUE(posts[0].builtIn);
    EXPECT_EQ(posts[1].id, "linuxcnc");
    EXPECT_TRUE(posts[1].builtIn);
    EXPECT_TRUE(posts[1].shadows.empty());
    EXPECT_EQ(posts[2].id, "mine");
    EXPECT_FALSE(posts[2].builtIn);
    EXPECT_EQ(posts[3].id, "sinumerik828d-emco");
    EXPECT_EQ(posts[3].path, (user / "sinumerik828d-emco.js").string());
    EXPECT_FALSE(posts[3].builtIn);
    EXPECT_EQ(posts[3].shadows, std::vector<std::string>{kEmcoPost});
    EXPECT_EQ(posts[4].id, "sinumerik840d");
    EXPECT_TRUE(posts[4].builtIn);
    EXPECT_EQ(posts[5].id, "sinumerik840d-turn");
    EXPECT_TRUE(posts[5].builtIn);
    EXPECT_EQ(findPost("sinumerik828d-emco", dirs).value(), (user / "sinumerik828d-emco.js").string());
}

TEST(KernelMoves, InverseTimeFeedsAreScaledToEachPieceOfASplitArc)
{
    Toolpath path;
    path.add(Rapid{{10, 0, 0}});
    path.add(FeedModeChange{FeedMode::InverseTime});
    path.add(Arc{{10, 0, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 2});      // a full circle in half a minute
    path.add(Arc{{0, 10, 0}, {0, 0, 0}, {0.6, 0.8, 0}, false, 0, 3});  // oblique: linearised
    auto output = runWith("inverse.js", R"JS(var post = {capabilities: {tolerance: 1}};
function onFeedMode(mode) {}
function onRapid(x, y, z) {}
function onLinear(x, y, z, feed) { writeln("line " + feed); }
function onCircular(cw, cx, cy, cz, x, y, z, feed, arc) { writeln("arc " + feed + " of " + arc.pieces); }
)JS",
                          path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    const std::vector<std::string> all = lines(output->text);
    ASSERT_GE(all.size(), 3u);
    EXPECT_EQ(all[0], "arc 4 of 2");
    EXPECT_EQ(all[1], "arc 4 of 2");
    const std::size_t segments = all.size() - 2;
    EXPECT_EQ(all[2], "line " + std::to_string(3 * segments));
}

TEST(KernelMoves, FiveAxisMovesAlongZAreThreeAxisMovesOthersAreRefused)
{
    const std::string source = R"JS(var post = {};
function onRapid(x, y, z) { writeln("rapid " + z); }
function onLinear(x, y, z, feed) { writeln("linear " + z + " " + feed); }
)JS";
    Toolpath along;
    along.add(ToolAxisMove{{0, 0, 10}, {0, 0, 1}, 0});
    along.add(ToolAxisMove{{0, 0, 5}, {0, 0, 1}, 200});
    auto output = runWith("threeaxis.js", source, along);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "rapid 10\nlinear 5 200\n");
    Toolpath tilted;
    tilted.add(ToolAxisMove{{0, 0, 10}, {0, 0.6, 0.8}, 100});
    auto refused = runWith("threeaxis.js", source, tilted);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message, "five-axis move (tool axis 0.000000, 0.600000, 0.800000) but post threeaxis "
                                       "drives 3 axes (CL record 0 ToolAxisMove)");
}

TEST(KernelMoves, OnOpenGetsTheProgramSummary)
{
    Toolpath path;
    path.add(WorkOffset{3});
    path.add(ToolChange{Tool{4, "Drill", "drill", 6.8}});
    path.add(Rapid{{10, 0, 5}});
    path.add(Arc{{-10, 0, 5}, {0, 0, 5}, {0, 0, 1}, false, 0, 100});  // over +Y: y reaches 10
    path.add(ToolChange{Tool{4}});
    path.add(ToolChange{Tool{2, "Flat", "flat", 10}});
    auto output = runWith("summary.js", R"JS(var post = {};
function onOpen(program) {
    var e = program.extents;
    writeln([program.workOffset, program.tools.map(function (t) { return "T" + t.number + " " + t.diameter; }).join(),
             e.min.x, e.min.y, e.max.x, e.max.y, e.max.z].join("|"));
}
function onToolChange(tool) {}
function onWorkOffset(index) {}
function onRapid(x, y, z) {}
function onCircular() {}
)JS",
                          path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "3|T4 6.8,T2 10|-10|0|10|10|5\n");
}

TEST(OutputWriter, LinesStayLinesAndKnowTheirOperation)
{
    OutputWriter writer;
    writer.setOperation(0);
    writer.writeBlock({"G0", "X1\nY2", "", "Z3\r"});
    writer.writeComment("two\nlines");
    writer.setOperation(2);
    writer.writeLine("raw\r\nsecond");
    writer.beginBlock();
    EXPECT_FALSE(writer.endBlock());       // no words: no line, no number
    writer.writeCleanBlock("G1 X4 F100");  // a block template's words, joined already
    writer.setOperation(-1);
    writer.writeBlock({"M30"});
    EXPECT_EQ(writer.text(), "N10 G0 X1 Y2 Z3\nN20 ;two lines\nraw\nsecond\nN30 G1 X4 F100\nN40 M30\n");
    EXPECT_EQ(writer.lineOperations(), (std::vector<int>{0, 0, 2, 2, 2, -1}));
    EXPECT_EQ(writer.lineCount(), 6u);
}

}  // namespace
}  // namespace camwb::post::test

namespace camwb::post::test {
namespace {

TEST(KernelMoves, ArcsThePostCannotWriteBecomeLinesForTheStatedReason)
{
    Toolpath path;
    path.add(Rapid{{0.5, 0, 0}});
    path.add(Arc{{0, 0.5, 0}, {0, 0, 0}, {0, 0, 1}, false, 0, 100});  // radius 0.5: below the minimum
    path.add(Rapid{{10, 0, 0}});
    path.add(Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, 1}, false, 0, 100});   // a helix: not written
    path.add(Arc{{0, 10, -2}, {0, 0, -2}, {0, 0, 1}, false, 0, 100});  // planar, radius 10: written
    auto output = runWith("limited.js", R"JS(var post = {capabilities: {minArcRadius: 1, helicalArcs: false}};
function onRapid(x, y, z) {}
function onLinear(x, y, z, feed) { writeln("line " + x.toFixed(3) + " " + y.toFixed(3) + " " + z.toFixed(3)); }
function onCircular(cw, cx, cy, cz, x, y, z, feed, arc) { writeln("arc " + arc.radius); }
)JS",
                          path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    const std::vector<std::string> all = lines(output->text);
    ASSERT_GT(all.size(), 3u);
    EXPECT_EQ(all.back(), "arc 10");
    EXPECT_EQ(std::count(all.begin(), all.end(), "arc 10"), 1);
    EXPECT_NE(std::find(all.begin(), all.end(), "line 10.000 0.000 -2.000"), all.end());  // the helix ends exactly
    ASSERT_EQ(output->messages.size(), 2u);
    EXPECT_EQ(output->messages[0].message, "1 arc helical in the XY plane, which the post does not write: written as "
                                           "lines within 0.01 mm (first: CL record 3)");
    EXPECT_EQ(output->messages[1].message,
              "1 arc outside the post's arc radius range: written as lines within 0.01 mm (first: CL record 1)");
}

TEST(KernelMoves, CyclePointsCanBeExpandedByTheKernel)
{
    Toolpath path;
    path.add(Rapid{{0, 0, 20}});
    path.add(Cycle{CycleKind::Drill, 20, 2, 0, -5, 0, 0, 100, {{10, 0, 0}, {20, 0, 0}}});
    auto output = runWith("expands.js", R"JS(var post = {};
function onCycle(cycle) { writeln("cycle " + cycle.kind + " " + cycle.holes.length); }
function onCyclePoint(x, y, z) { if (x > 15) expandCyclePoint(x, y, z); else writeln("native " + x); }
function onCycleEnd(cycle) { writeln("end"); }
function onRapid(x, y, z) { writeln("G0 " + x + " " + y + " " + z); }
function onLinear(x, y, z, feed) { writeln("G1 " + z + " F" + feed); }
)JS",
                          path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text,
              "G0 0 0 20\ncycle drill 2\nnative 10\nG0 20 0 20\nG0 20 0 2\nG1 -5 F100\nG0 20 0 20\nend\n");

    auto outside = runWith("outside.js", "var post = {};\nfunction onOpen() {\n  expandCyclePoint(1, 2, 3);\n}\n", {});
    ASSERT_FALSE(outside.ok());
    EXPECT_EQ(outside.error().line, 3);
    EXPECT_NE(outside.error().message.find("expandCyclePoint() works only inside onCyclePoint()"), std::string::npos);
}

}  // namespace
}  // namespace camwb::post::test
