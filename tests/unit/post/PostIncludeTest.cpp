// include("name") in post scripts: the library's functions and variables are the post's, errors
// and warnings inside it name the library file and line, and no other file can be reached.
#include "PostTestSupport.h"

#include <filesystem>

namespace camwb::post::test {
namespace {

using namespace toolpath;

// include/<name>.js beside the scripts writeScript() writes; its path.
std::string writeInclude(const std::string& name, const std::string& source)
{
    const std::filesystem::path dir = std::filesystem::path(writeScript("anchor.js", "")).parent_path() / "include";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / (name + ".js"), std::ios::binary) << source;
    return (dir / (name + ".js")).string();
}

Toolpath oneMove()
{
    Toolpath tp;
    tp.add(Rapid{{1, 2, 3}});
    return tp;
}

TEST(PostInclude, TheLibrarysFunctionsAndVariablesAreThePosts)
{
    writeInclude("lib-words", "var loads = (typeof loads == 'undefined' ? 0 : loads) + 1;\n"
                              "function words(x) {\n    return 'X' + x;\n}\n");
    const PostOutput out = runSource("includer.js", R"JS(
var post = {id: "includer"};
include("lib-words");
include("lib-words");  // once per run: evaluated again, `loads` would be 2
function onRapid(x, y, z) { writeBlock(words(x), "L" + loads); }
)JS",
                                     oneMove());
    EXPECT_EQ(out.text, "N10 X1 L1\n");
}

TEST(PostInclude, AnErrorInTheLibraryNamesItsFileAndLine)
{
    const std::string library =
        writeInclude("lib-fails", "function check(x) {\n    if (x > 0)\n        error('x is positive');\n}\n"
                                  "function note() {\n    warning('noted');\n}\n");
    auto post = PostProcessor::load(writeScript("failing.js", R"JS(var post = {id: "failing"};
include("lib-fails");
function onRapid(x, y, z) { note(); check(x); }
)JS"));
    ASSERT_TRUE(post.ok()) << post.error().toString();
    const auto run = post->run(oneMove(), fixedContext());
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().file, library) << run.error().toString();
    EXPECT_EQ(run.error().line, 3) << run.error().toString();
    EXPECT_NE(run.error().message.find("x is positive"), std::string::npos);
}

TEST(PostInclude, WarningsInTheLibraryNameIt)
{
    const std::string library = writeInclude("lib-warns", "function note() {\n    warning('noted');\n}\n");
    const PostOutput out = runSource("warner.js", R"JS(var post = {id: "warner"};
include("lib-warns");
function onRapid(x, y, z) { note(); }
)JS",
                                     oneMove());
    ASSERT_EQ(out.messages.size(), 1u);
    EXPECT_EQ(out.messages[0].file, library);
    EXPECT_EQ(out.messages[0].line, 2);
}

TEST(PostInclude, OnlyPlainNamesOfExistingLibraries)
{
    for (const char* bad : {"\"../anchor\"", "\"/etc/passwd\"", "\"\"", "42"}) {
        auto post = PostProcessor::load(
            writeScript("bad-include.js", std::string("var post = {id: \"bad-include\"};\ninclude(") + bad + ");\n"));
        ASSERT_FALSE(post.ok()) << bad;
        EXPECT_NE(post.error().message.find("plain name"), std::string::npos) << post.error().toString();
        EXPECT_EQ(post.error().line, 2);
    }
    auto missing = PostProcessor::load(
        writeScript("missing-include.js", "var post = {id: \"missing-include\"};\ninclude(\"no-such-lib\");\n"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("no-such-lib"), std::string::npos) << missing.error().toString();
    EXPECT_NE(missing.error().message.find("include"), std::string::npos) << missing.error().toString();
}

}  // namespace
}  // namespace camwb::post::test
