#include "base/AtomicFile.h"
#include "base/NumberFormat.h"
#include "base/Result.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

using namespace camwb::base;
namespace fs = std::filesystem;

TEST(Error, NamesFileLineAndColumnWhenKnown)
{
    EXPECT_EQ(makeError("bad", "a.nc", 3, 7).toString(), "a.nc:3:7: bad");
    EXPECT_EQ(makeError("bad", "a.nc", 3).toString(), "a.nc:3: bad");
    EXPECT_EQ(makeError("bad", "a.nc").toString(), "a.nc: bad");
    EXPECT_EQ(makeError("bad").toString(), "bad");
}

TEST(NumberFormat, FixedDecimalsRoundNotTruncate)
{
    EXPECT_EQ(formatFixed(199.998, 0), "200");
    EXPECT_EQ(formatFixed(3.3333 * 60, 0), "200");
    EXPECT_EQ(formatFixed(-6.47749, 3), "-6.477");
    EXPECT_EQ(formatFixed(12.5, 3), "12.500");
}

TEST(NumberFormat, NegativeZeroIsNeverWritten)
{
    EXPECT_EQ(formatFixed(-0.0, 3), "0.000");
    EXPECT_EQ(formatFixed(-0.0004, 3), "0.000");
    EXPECT_EQ((NumberFormat{3, true}.format(-0.0001)), "0");
    EXPECT_EQ((NumberFormat{3, false, false, true}.format(-0.0001)), "+0.000");
}

TEST(NumberFormat, TrimSignAndLeadingZero)
{
    EXPECT_EQ((NumberFormat{3, true}.format(1.5)), "1.5");
    EXPECT_EQ((NumberFormat{3, true}.format(2.0)), "2");
    EXPECT_EQ((NumberFormat{3, true, true}.format(2.0)), "2.");
    EXPECT_EQ((NumberFormat{3, false, false, true}.format(2.0)), "+2.000");
    EXPECT_EQ((NumberFormat{3, false, false, false, false}.format(0.5)), ".500");
    EXPECT_EQ((NumberFormat{3, false, false, false, false}.format(-0.5)), "-.500");
}

class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir = fs::temp_directory_path() / ("camwb-atomic-" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::size_t fileCount() const
    {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
    }
    fs::path dir;
};

TEST_F(AtomicFileTest, WritesAndReplaces)
{
    const std::string path = (dir / "a.txt").string();
    ASSERT_TRUE(writeFileAtomically(path, "one\n"));
    ASSERT_TRUE(writeFileAtomically(path, "two\n"));
    EXPECT_EQ(readTextFile(path).value(), "two\n");
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(AtomicFileTest, AbortLeavesTargetUntouchedAndNoTempFile)
{
    const std::string path = (dir / "a.txt").string();
    ASSERT_TRUE(writeFileAtomically(path, "original\n"));
    {
        AtomicFileWriter writer(path);
        ASSERT_TRUE(writer.open());
        writer.write("half of a new");
    }  // destroyed without commit
    EXPECT_EQ(readTextFile(path).value(), "original\n");
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(AtomicFileTest, MissingFolderIsAnErrorNamingTheFile)
{
    const std::string path = (dir / "no" / "such" / "a.txt").string();
    Status status = writeFileAtomically(path, "x");
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error().file, path);
    auto read = readTextFile(path);
    ASSERT_FALSE(read);
    EXPECT_EQ(read.error().file, path);
}
