// The post kernel: script services, error reporting with file and line, and the post registry.
#include "PostTestSupport.h"

#include "post/PostRegistry.h"

#include <cstdlib>

namespace camwb::post::test {
namespace {

using namespace toolpath;

base::Result<PostOutput> runScript(const std::string& name, const std::string& source, const Toolpath& path = {})
{
    auto post = PostProcessor::load(writeScript(name, source));
    if (!post.ok())
        return post.error();
    return post->run(path, fixedContext());
}

TEST(PostKernel, BlockNumberingIsConfigurable)
{
    const auto output = runScript("numbering.js", R"JS(
var post = {id: "numbering"};
function onOpen() {
    writeBlock("G0", "", "X1");
    writeBlock("", undefined, null);          // nothing: no line, no number
    setBlockNumbering(100, 5, true);
    writeBlock("A");
    writeComment("c");
    writeln("raw line");
    writeBlock("B", 7, 2.5);
    setBlockNumbering(1, 1, false);
    writeBlock("C");
}
)JS");
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "N10 G0 X1\nN100 A\nN105 ;c\nraw line\nN110 B 7 2.500\nC\n");
}

TEST(PostKernel, FormatsVariablesAndModals)
{
    const auto output = runScript("formats.js", R"JS(
var post = {id: "formats"};
var f3 = createFormat({decimals: 3});
var trim = createFormat({decimals: 4, trim: true});
var signed = createFormat({decimals: 1, forceSign: true});
var x = createVariable({prefix: "X"}, f3);
var i = createVariable({prefix: "I", force: true}, f3);
var g = createModal({prefix: "G"});
var m = createModal({prefix: "M"}, createFormat({decimals: 0}));
function onOpen() {
    writeln([f3.format(-0.0001), trim.format(1.5), trim.format(2), signed.format(1), signed.format(-0.01)].join("|"));
    writeln([x.format(1), x.format(1.0002), x.format(1.0006), i.format(0), i.format(0)].join("|"));
    x.reset();
    writeln([x.format(1.0006), g.format(0), g.format(0), g.format("1"), g.format(1), m.format(3)].join("|"));
}
)JS");
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "0.000|1.5|2|+1.0|+0.0\nX1.000||X1.001|I0.000|I0.000\nX1.001|G0||G1||M3\n");
}

TEST(PostKernel, ContextValuesAndPosition)
{
    Toolpath path;
    path.add(Rapid{{1, 2, 3}});
    path.add(Rapid{{4, 5, 6}});
    const auto output = runScript("context.js", R"JS(
var post = {id: "context"};
function onOpen() { writeln([programName, user, version, dateString, getCurrentPosition()].join("|")); }
function onRapid(x, y, z) { var p = getCurrentPosition(); writeln(p ? p.x + "," + p.y + "," + p.z : "none"); }
)JS",
                                  path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "PART1|tester|0.1.0|15.05.2018 21:09:46|\nnone\n1,2,3\n");
}

TEST(PostKernel, MissingHandlersWarnOncePerKind)
{
    Toolpath path;
    path.add(Rapid{{1, 2, 3}});
    path.add(Rapid{{4, 5, 6}});
    path.add(Dwell{1});
    const auto output = runScript("partial.js", "var post = {id: 'partial'};\n", path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "");
    ASSERT_EQ(output->messages.size(), 2u);
    EXPECT_EQ(output->messages[0].message, "post partial has no handler for Dwell (onDwell); 1 record not output");
    EXPECT_EQ(output->messages[1].message, "post partial has no handler for Rapid (onRapid); 2 records not output");
}

TEST(PostKernel, HandlersMayBeMethodsOfPost)
{
    Toolpath path;
    path.add(Comment{"hello"});
    const auto output = runScript("methods.js", R"JS(
var post = {id: "methods", onComment: function (text) { writeComment(text + " " + this.id); }};
)JS",
                                  path);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "N10 ;hello methods\n");
}

TEST(PostKernel, WarningNamesFileAndLine)
{
    const std::string source = "var post = {id: 'warn'};\nfunction onOpen() {\n    warning('careful');\n}\n";
    const auto output = runScript("warn.js", source);
    ASSERT_TRUE(output.ok()) << output.error().toString();
    ASSERT_EQ(output->messages.size(), 1u);
    EXPECT_EQ(output->messages[0].message, "careful");
    EXPECT_EQ(output->messages[0].line, 3);
    EXPECT_NE(output->messages[0].file.find("warn.js"), std::string::npos);
}

TEST(PostKernel, SyntaxErrorGivesFileAndLine)
{
    const std::string path =
        writeScript("syntax.js", "var post = {id: 'syntax'};\n\nvar b = (;\nfunction onOpen() {}\n");
    const auto post = PostProcessor::load(path);
    ASSERT_FALSE(post.ok());
    EXPECT_EQ(post.error().file, path);
    EXPECT_EQ(post.error().line, 3);
    EXPECT_NE(post.error().message.find("SyntaxError"), std::string::npos) << post.error().message;
}

TEST(PostKernel, ThrowingHandlerGivesFileLineAndRecord)
{
    Toolpath path;
    path.add(Rapid{{0, 0, 0}});
    path.add(Linear{{1, 0, 0}, 100});
    const std::string script = writeScript("throws.js", R"JS(var post = {id: "throws"};
function onRapid(x, y, z) {}
function onLinear(x, y, z, f) {
    var word = undefinedFormat.format(x);
}
)JS");
    const auto post = PostProcessor::load(script);
    ASSERT_TRUE(post.ok()) << post.error().toString();
    const auto output = post->run(path, fixedContext());
    ASSERT_FALSE(output.ok());
    EXPECT_EQ(output.error().file, script);
    EXPECT_EQ(output.error().line, 4);
    EXPECT_EQ(output.error().message,
              "ReferenceError: undefinedFormat is not defined (in onLinear, CL record 1 Linear)");
}

TEST(PostKernel, ErrorCallAbortsWithItsText)
{
    const auto output =
        runScript("error.js", "var post = {id: 'error'};\nfunction onClose() {\n  error('no way');\n}\n");
    ASSERT_FALSE(output.ok());
    EXPECT_EQ(output.error().line, 3);
    EXPECT_EQ(output.error().message, "no way (in onClose)");
}

TEST(PostKernel, ThrownNonErrorValuesAreFailures)
{
    const auto output = runScript("string.js", "var post = {};\nfunction onOpen() { throw 'oops'; }\n");
    ASSERT_FALSE(output.ok());
    EXPECT_EQ(output.error().message, "uncaught exception: oops (in onOpen)");
    const auto top = PostProcessor::load(writeScript("top.js", "var post = {id: 'top'};\n\nthrow 'at load';\n"));
    ASSERT_FALSE(top.ok());
    EXPECT_EQ(top.error().line, 3);
}

TEST(PostKernel, ScriptWithoutPostObjectIsRejected)
{
    const auto post = PostProcessor::load(writeScript("nopost.js", "var x = 1;\n"));
    ASSERT_FALSE(post.ok());
    EXPECT_NE(post.error().message.find("`post`"), std::string::npos);
}

TEST(PostKernel, ClockAndRandomNumbersRepeat)
{
    // A post that reads the clock or draws random numbers still writes the same bytes every run.
    const std::string source = R"JS(var post = {};
function onOpen() { writeln([new Date().toISOString(), Date.now(), Math.random(), Math.random()].join("|")); }
)JS";
    const auto first = runScript("clock.js", source);
    const auto second = runScript("clock.js", source);
    ASSERT_TRUE(first.ok()) << first.error().toString();
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(first->text, second->text);
    EXPECT_EQ(first->text.substr(0, 39), "2018-05-15T21:09:46.000Z|1526418586000|");  // the injected date
}

TEST(PostKernel, NoSandboxEscapes)
{
    const auto output = runScript("sandbox.js", R"JS(
var post = {id: "sandbox"};
function onOpen() { writeln([typeof console, typeof print, typeof XMLHttpRequest, typeof Qt, typeof require].join(" ")); }
)JS");
    ASSERT_TRUE(output.ok()) << output.error().toString();
    EXPECT_EQ(output->text, "undefined undefined undefined undefined undefined\n");
}

TEST(PostRegistry, FindsPostsAndListsWhereItLooked)
{
    const std::vector<base::DataDir> dirs{{"/nonexistent", false}, {kPostsDir, true}};
    const auto found = findPost("sinumerik828d-emco", dirs);
    ASSERT_TRUE(found.ok()) << found.error().toString();
    EXPECT_EQ(found.value(), kEmcoPost);

    const auto missing = findPost("no-such-post", dirs);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("post 'no-such-post' not found"), std::string::npos);
    EXPECT_NE(missing.error().message.find("/nonexistent/no-such-post.js"), std::string::npos);
    EXPECT_NE(missing.error().message.find(kPostsDir + "/no-such-post.js"), std::string::npos);

    EXPECT_FALSE(findPost("../etc/passwd", dirs).ok());
}

TEST(PostRegistry, DefaultDirsHonourCamwbPostPath)
{
    setenv("CAMWB_POST_PATH", "/a:/b", 1);
    const std::vector<base::DataDir> dirs = defaultPostDirs({"/extra"});
    unsetenv("CAMWB_POST_PATH");
    ASSERT_GE(dirs.size(), 4u);
    EXPECT_EQ(dirs[0].path, "/extra");
    EXPECT_EQ(dirs[1].path, "/a");
    EXPECT_EQ(dirs[2].path, "/b");
    EXPECT_FALSE(dirs[0].builtIn || dirs[1].builtIn || dirs[2].builtIn);
    EXPECT_EQ(dirs.back().path, std::string(CAMWB_TEST_DATA_DIR) + "/posts");
    EXPECT_TRUE(dirs.back().builtIn);
    EXPECT_TRUE(findPost("sinumerik828d-emco", defaultPostDirs()).ok());
}

}  // namespace
}  // namespace camwb::post::test
