// base::LineReader: the same lines from memory and from a file read in chunks, whatever falls on
// a chunk boundary (a CR before its LF, a line longer than the buffer, a peeked line), with the
// byte order mark and a missing last line break handled as an editor shows them.
#include "base/LineReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

using namespace camwb::base;

namespace {

std::vector<std::string> allLines(LineReader& reader)
{
    std::vector<std::string> lines;
    while (const auto line = reader.next())
        lines.emplace_back(*line);
    return lines;
}

std::string writeFile(const std::string& name, const std::string& content)
{
    const auto path = std::filesystem::path(testing::TempDir()) / (std::to_string(::getpid()) + "-" + name);
    std::ofstream(path, std::ios::binary) << content;
    return path.string();
}

std::vector<std::string> fileLines(const std::string& content)
{
    auto reader = LineReader::open(writeFile("lines.txt", content));
    EXPECT_TRUE(reader.ok());
    return reader.ok() ? allLines(reader.value()) : std::vector<std::string>{};
}

}  // namespace

TEST(LineReader, LinesFromMemory)
{
    LineReader reader("\xEF\xBB\xBF"
                      "first\r\n\nthird");
    EXPECT_EQ(reader.lineNumber(), 0);
    EXPECT_EQ(*reader.next(), "first");  // no byte order mark, no CR
    EXPECT_EQ(reader.lineNumber(), 1);
    EXPECT_EQ(*reader.peek(), "");
    EXPECT_EQ(*reader.next(), "");
    EXPECT_EQ(*reader.next(), "third");  // the last line needs no line break
    EXPECT_FALSE(reader.peek());
    EXPECT_FALSE(reader.next());
    EXPECT_EQ(reader.lineNumber(), 3);
    LineReader empty("");
    EXPECT_FALSE(empty.next());
    LineReader oneBreak("a\n");
    EXPECT_EQ(allLines(oneBreak), std::vector<std::string>{"a"});
}

TEST(LineReader, FileLinesMatchMemoryAcrossChunks)
{
    // Lines of every length around the 1 MiB chunk, CRs that end up at a chunk's end, one line
    // longer than a chunk: the file reader gives what the memory reader gives.
    std::string content = "\xEF\xBB\xBF";
    for (int i = 0; content.size() < 5u * 1024 * 1024; ++i)
        content += std::string(static_cast<std::size_t>(i * 7919 % 3001), static_cast<char>('a' + i % 26)) +
                   (i % 3 == 0 ? "\r\n" : "\n");
    content += std::string(3u * 1024 * 1024, 'x') + "\r\n" + "tail";
    LineReader memory(content);
    const std::vector<std::string> expected = allLines(memory);
    EXPECT_EQ(fileLines(content), expected);
    ASSERT_GT(expected.size(), 1000u);
    EXPECT_EQ(expected.back(), "tail");
}

TEST(LineReader, APeekedLineLeavesTheCurrentOneValid)
{
    // Each line is read, then the next peeked, across chunk boundaries: both views stay good.
    std::string content;
    std::vector<std::string> expected;
    for (int i = 0; content.size() < 3u * 1024 * 1024; ++i) {
        expected.push_back("line " + std::to_string(i) + std::string(static_cast<std::size_t>(i % 977), '.'));
        content += expected.back() + "\n";
    }
    auto reader = LineReader::open(writeFile("peek.txt", content));
    ASSERT_TRUE(reader.ok());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const std::string_view current = *reader->next();
        const auto following = reader->peek();
        ASSERT_EQ(current, expected[i]) << i;
        if (i + 1 < expected.size())
            ASSERT_EQ(*following, expected[i + 1]) << i;
        else
            ASSERT_FALSE(following);
    }
    EXPECT_FALSE(reader->readError());
}

TEST(LineReader, OpenErrorsNameTheFile)
{
    auto missing = LineReader::open("/nonexistent/file.dump");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().toString(), "/nonexistent/file.dump: cannot open: No such file or directory");
    auto folder = LineReader::open(testing::TempDir());
    ASSERT_FALSE(folder.ok());
    EXPECT_NE(folder.error().message.find("it is a folder"), std::string::npos);
}
