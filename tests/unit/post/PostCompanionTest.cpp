// Files a post writes beside its program (openFile/closeFile) and files it ships beside itself
// (readPostFile): block numbers restart in a companion file, every misuse is an error at the
// post's line, runToFile writes all files or none, and readPostFile reaches nothing outside the
// post folders.
#include "PostTestSupport.h"

#include "base/AtomicFile.h"

#include <filesystem>

namespace camwb::post::test {
namespace {

using namespace toolpath;
namespace fs = std::filesystem;

Toolpath oneMove()
{
    Toolpath tp;
    tp.add(Rapid{{1, 2, 3}});
    return tp;
}

// A folder of this test's own (under the per-process script folder), emptied.
fs::path freshDir(const std::string& name)
{
    const fs::path dir = fs::path(writeScript("anchor.js", "")).parent_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The post's run error; a run that succeeds is a test failure.
base::Error runError(const std::string& scriptPath)
{
    auto post = PostProcessor::load(scriptPath);
    EXPECT_TRUE(post.ok()) << post.error().toString();
    if (!post.ok())
        return post.error();
    auto run = post->run(oneMove(), fixedContext());
    EXPECT_FALSE(run.ok()) << run.value().text;
    return run.ok() ? base::Error{} : run.error();
}

const char* kTwoFiles = R"JS(var post = {id: "two-files"};
function onOpen() {
    setBlockNumbering(10, 10);
    writeBlock("G0");
    openFile("SUB_1.SPF");
    writeComment("sub one");
    writeBlock("G1");
    setBlockNumbering(5, 5);
    writeBlock("G2");
    closeFile();
    writeBlock("G3");
    openFile("sub-2.txt");
    writeln("raw\nlines");
    writeBlock("M17");
    closeFile();
}
function onRapid(x, y, z) { writeBlock("X" + x); }
function onClose() { writeBlock("M30"); }
)JS";

TEST(PostCompanion, FilesBesideTheProgramRestartTheirBlockNumbers)
{
    const PostOutput out = runSource("two-files.js", kTwoFiles, oneMove());
    EXPECT_EQ(out.text, "N10 G0\nN20 G3\nN30 X1\nN40 M30\n");
    ASSERT_EQ(out.files.size(), 2u);
    EXPECT_EQ(out.files[0].name, "SUB_1.SPF");
    // The main program's numbering from its start; a change inside applies to that file only.
    EXPECT_EQ(out.files[0].text, "N10 ;sub one\nN20 G1\nN5 G2\n");
    EXPECT_EQ(out.files[1].name, "sub-2.txt");
    EXPECT_EQ(out.files[1].text, "raw\nlines\nN10 M17\n");
    EXPECT_EQ(out.lineOperation.size(), 4u);
}

TEST(PostCompanion, MisuseIsAnErrorAtThePostsLine)
{
    const struct {
        const char* code;
        const char* message;
    } cases[] = {
        {"openFile('../X.SPF');", "a plain file name"},
        {"openFile('sub/X.SPF');", "a plain file name"},
        {"openFile('/tmp/X.SPF');", "a plain file name"},
        {"openFile('..');", "a plain file name"},
        {"openFile('.hidden');", "a plain file name"},
        {"openFile('');", "a plain file name"},
        {"openFile(42);", "a plain file name"},
        {"openFile('A.SPF'); closeFile(); openFile('a.spf');", "the run already wrote \"A.SPF\""},
        {"openFile('A.SPF'); openFile('B.SPF');", "while \"A.SPF\" is open: closeFile() first"},
        {"closeFile();", "closeFile() without an openFile()"},
    };
    for (const auto& c : cases) {
        const std::string path = writeScript("misuse.js", std::string("var post = {id: \"misuse\"};\n"
                                                                      "function onRapid(x, y, z) {\n") +
                                                              "    " + c.code + "\n}\n");
        const base::Error error = runError(path);
        EXPECT_NE(error.message.find(c.message), std::string::npos) << c.code << ": " << error.toString();
        EXPECT_EQ(error.file, path) << c.code;
        EXPECT_EQ(error.line, 3) << c.code;
    }
}

TEST(PostCompanion, AFileLeftOpenFailsTheRun)
{
    const base::Error error = runError(writeScript("left-open.js", R"JS(var post = {id: "left-open"};
function onClose() { openFile("X.SPF"); writeBlock("M17"); }
)JS"));
    EXPECT_NE(error.message.find("openFile(\"X.SPF\") was never closed"), std::string::npos) << error.toString();
}

TEST(PostCompanion, RunToFileWritesEveryFileBesideTheOutput)
{
    const fs::path dir = freshDir("companion-out");
    auto post = PostProcessor::load(writeScript("two-files.js", kTwoFiles));
    ASSERT_TRUE(post.ok()) << post.error().toString();
    RunOptions options;
    options.context = fixedContext();
    auto summary = post->runToFile(oneMove(), options, (dir / "MAIN.MPF").string());
    ASSERT_TRUE(summary.ok()) << summary.error().toString();
    EXPECT_EQ(summary->companionPaths,
              (std::vector<std::string>{(dir / "SUB_1.SPF").string(), (dir / "sub-2.txt").string()}));
    EXPECT_EQ(base::readTextFile((dir / "MAIN.MPF").string()).value(), "N10 G0\nN20 G3\nN30 X1\nN40 M30\n");
    EXPECT_EQ(base::readTextFile((dir / "SUB_1.SPF").string()).value(), "N10 ;sub one\nN20 G1\nN5 G2\n");
    EXPECT_EQ(base::readTextFile((dir / "sub-2.txt").string()).value(), "raw\nlines\nN10 M17\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 3) << "no temporary files left";
}

TEST(PostCompanion, AFailingRunWritesNothingAndReplacesNothing)
{
    const fs::path dir = freshDir("companion-fail");
    std::ofstream(dir / "MAIN.MPF") << "old main\n";
    std::ofstream(dir / "SUB.SPF") << "old sub\n";
    // The companion file is complete when the run fails, in its last handler.
    auto post = PostProcessor::load(writeScript("fails-late.js", R"JS(var post = {id: "fails-late"};
function onOpen() { openFile("SUB.SPF"); writeBlock("M17"); closeFile(); openFile("NEW.SPF"); closeFile(); }
function onRapid(x, y, z) { writeBlock("X" + x); }
function onClose() { error("the post gives up"); }
)JS"));
    ASSERT_TRUE(post.ok()) << post.error().toString();
    RunOptions options;
    options.context = fixedContext();
    auto summary = post->runToFile(oneMove(), options, (dir / "MAIN.MPF").string());
    ASSERT_FALSE(summary.ok());
    EXPECT_NE(summary.error().message.find("the post gives up"), std::string::npos);
    EXPECT_EQ(base::readTextFile((dir / "MAIN.MPF").string()).value(), "old main\n");
    EXPECT_EQ(base::readTextFile((dir / "SUB.SPF").string()).value(), "old sub\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2) << "no new or temporary files";
}

TEST(PostCompanion, ACompanionNamedAsTheOutputIsRefused)
{
    const fs::path dir = freshDir("companion-clash");
    auto post = PostProcessor::load(writeScript("clash.js", R"JS(var post = {id: "clash"};
function onOpen() { openFile("MAIN.MPF"); writeBlock("M17"); closeFile(); }
)JS"));
    ASSERT_TRUE(post.ok()) << post.error().toString();
    RunOptions options;
    options.context = fixedContext();
    auto summary = post->runToFile(oneMove(), options, (dir / "MAIN.MPF").string());
    ASSERT_FALSE(summary.ok());
    EXPECT_NE(summary.error().message.find("would overwrite the output"), std::string::npos);
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(PostReadFile, ReadsAFileShippedInThePostsFolder)
{
    const fs::path dir = freshDir("shipping");
    fs::create_directories(dir / "shipper" / "nc");
    std::ofstream(dir / "shipper" / "nc" / "SUB.SPF", std::ios::binary) << "PROC SUB\nM17\n";
    const fs::path script = dir / "shipper.js";
    std::ofstream(script) << R"JS(var post = {id: "shipper"};
function onClose() { writeln(readPostFile("shipper/nc/SUB.SPF")); }
)JS";
    auto post = PostProcessor::load(script.string());
    ASSERT_TRUE(post.ok()) << post.error().toString();
    auto run = post->run(oneMove(), fixedContext());
    ASSERT_TRUE(run.ok()) << run.error().toString();
    EXPECT_EQ(run->text, "PROC SUB\nM17\n\n");  // the text as it is, its last newline included
}

TEST(PostReadFile, NothingOutsideThePostFolderAndNoMissingFile)
{
    const fs::path dir = freshDir("sandbox");
    std::ofstream(dir.parent_path() / "outside.txt") << "secret\n";
    fs::create_directories(dir / "sub");
    std::error_code ec;
    fs::create_symlink(dir.parent_path() / "outside.txt", dir / "sub" / "link.txt", ec);
    const struct {
        const char* path;
        const char* message;
    } cases[] = {
        {"../outside.txt", "a path with '..'"},
        {"sub/../../outside.txt", "a path with '..'"},
        {"/etc/hostname", "an absolute path"},
        {"", "an empty path"},
        {"./sub/x.txt", "a path with an empty or '.' part"},
        {"sub/missing.txt", "no such file in"},
        {"sub/link.txt", "leads out of the post folder"},
    };
    for (const auto& c : cases) {
        if (std::string(c.path) == "sub/link.txt" && ec)
            continue;  // no symbolic links here
        const fs::path script = dir / "reader.js";
        std::ofstream(script) << "var post = {id: \"reader\"};\nfunction onRapid(x, y, z) {\n"
                              << "    writeln(readPostFile(\"" << c.path << "\"));\n}\n";
        const base::Error error = runError(script.string());
        EXPECT_NE(error.message.find(c.message), std::string::npos) << c.path << ": " << error.toString();
        EXPECT_NE(error.message.find(std::string("readPostFile(\"") + c.path), std::string::npos) << c.path;
        EXPECT_EQ(error.file, script.string()) << c.path;
        EXPECT_EQ(error.line, 3) << c.path;
    }
}

}  // namespace
}  // namespace camwb::post::test
