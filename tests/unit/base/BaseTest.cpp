#include "base/AtomicFile.h"
#include "base/NumberFormat.h"
#include "base/Result.h"

#include "../../support/DecimalCommaLocale.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

using namespace camwb::base;
namespace fs = std::filesystem;

// Pseudo-random numbers for the randomised checks: the same values every run.
struct Xorshift {
    std::uint64_t state;
    std::uint64_t operator()()
    {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    }
};

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

TEST(NumberFormat, FastPathWritesWhatToCharsWrites)
{
    // formatFixed takes a shortcut for most values; std::to_chars is the reference it must match,
    // ties and near-ties included (they go the slow way).
    Xorshift next{88172645463325252ull};
    char reference[400];
    for (int i = 0; i < 200000; ++i) {
        const int decimals = static_cast<int>(next() % 7);
        double value = static_cast<double>(static_cast<std::int64_t>(next() % 2000000001) - 1000000000) /
                       std::pow(10.0, static_cast<double>(next() % 9));
        if (i % 4 == 0)  // exact ties at this precision: 0.5 ulp of the last digit
            value = (std::floor(value * std::pow(10.0, decimals)) + 0.5) / std::pow(10.0, decimals);
        auto [end, ec] =
            std::to_chars(reference, reference + sizeof reference, value, std::chars_format::fixed, decimals);
        std::string expected(reference, end);
        if (expected[0] == '-' && expected.find_first_not_of("0.", 1) == std::string::npos)
            expected.erase(0, 1);
        ASSERT_EQ(formatFixed(value, decimals), expected) << value << " at " << decimals << " decimals";
    }
    EXPECT_EQ(formatFixed(1e15, 3), "1000000000000000.000");  // beyond the shortcut's range
    EXPECT_EQ(formatFixed(0.0005, 3), "0.001");               // 0.0005 is a little above the tie
    EXPECT_EQ(formatFixed(2.675, 2), "2.67");                 // 2.675 is a little below it
    EXPECT_EQ(formatFixed(-0.0004, 3), "0.000");
    EXPECT_EQ(formatFixed(0, 0), "0");
    EXPECT_EQ(formatFixed(-7, 0), "-7");
}

TEST(NumberFormat, GeneralWritesWhatPrintfWritesInTheCLocale)
{
    // printf's "%g" is the reference for the text (in the "C" locale the tests run in).
    for (double value : {0.0, 1.5, -2.25, 0.0001, 0.00001234, 123456.0, 1234567.0, 1e300, -1e-300, 99999.9991,
                         1.0 / 3.0, 6.35, 0.3125 * 25.4})
        for (int significant : {1, 3, 6}) {
            char expected[64];
            std::snprintf(expected, sizeof expected, "%.*g", significant, value);
            EXPECT_EQ(formatGeneral(value, significant), expected) << value << " to " << significant;
        }
    EXPECT_EQ(formatGeneral(HUGE_VAL, 6), "inf");
    EXPECT_EQ(formatGeneral(-HUGE_VAL, 6), "-inf");
    EXPECT_EQ(formatGeneral(std::nan(""), 6), "nan");
}

TEST(NumberFormat, TheDecimalPointStaysAPointInADecimalCommaLocale)
{
    camwb::test::DecimalCommaLocale comma;
    if (!comma.active())
        GTEST_SKIP() << comma.missing();
    char printed[16];
    std::snprintf(printed, sizeof printed, "%.1f", 1.5);
    ASSERT_STREQ(printed, "1,5") << "the C library follows " << comma.name();
    EXPECT_EQ(formatFixed(1.5, 3), "1.500");
    EXPECT_EQ(formatFixed(1e15 + 0.5, 1), "1000000000000000.5");  // the slow path too
    EXPECT_EQ(formatGeneral(1.5, 6), "1.5");
    EXPECT_EQ(formatGeneral(1.5e-7, 6), "1.5e-07");
    EXPECT_EQ((NumberFormat{3, true, false, true}.format(-0.25)), "-0.25");
    EXPECT_DOUBLE_EQ((NumberFormat{3, false, false, false, true, 10.0}.roundedValue(1e300)), 1e300);
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
    EXPECT_EQ((NumberFormat{3, true, false, true, false}.format(0.5)), "+.5");
    EXPECT_EQ((NumberFormat{3, true, false, true}.format(-0.0004)), "+0");
}

// The text rules of NumberFormat applied to formatFixed's text with string operations: the
// reference formatTo's in-place shortcuts must match for every option combination.
std::string referenceText(const NumberFormat& f, double value)
{
    std::string text = formatFixed(value * f.scale, f.decimals);
    if (f.trimTrailingZeros && text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.' && !f.keepDecimalPoint)
            text.pop_back();
        if (text.empty() || text == "-" || text == "-.")
            text = "0";
    }
    if (!f.leadingZero && text.rfind("0.", 0) == 0 && text.size() > 2)
        text.erase(0, 1);
    else if (!f.leadingZero && text.rfind("-0.", 0) == 0 && text.size() > 3)
        text.erase(1, 1);
    if (f.forceSign && text[0] != '-')
        text.insert(0, "+");
    return text;
}

TEST(NumberFormat, EveryOptionCombinationFollowsTheTextRules)
{
    Xorshift next{0x9E3779B97F4A7C15ull};
    for (int i = 0; i < 100000; ++i) {
        NumberFormat f{static_cast<int>(next() % 13), next() % 2 == 0, next() % 2 == 0, next() % 2 == 0,
                       next() % 2 == 0};
        if (next() % 4 == 0)
            f.scale = 1 / 25.4;
        // Magnitudes from 1e-13 to 1e13: both sides of the shortcut's 2^40 limit at every precision.
        const double value = static_cast<double>(static_cast<std::int64_t>(next() % 2000000001) - 1000000000) *
                             std::pow(10.0, static_cast<double>(next() % 27) - 22);
        char buffer[NumberFormat::kBufferSize];
        const std::string text(buffer, f.formatTo(value, buffer));
        ASSERT_EQ(text, referenceText(f, value))
            << value << " at " << f.decimals << " decimals, trim " << f.trimTrailingZeros << f.keepDecimalPoint
            << ", sign " << f.forceSign << ", leading zero " << f.leadingZero;
    }
    EXPECT_EQ((NumberFormat{4}.format(1099511.62777)), "1099511.6278");  // just past 2^40 at 4 decimals
    EXPECT_EQ((NumberFormat{4}.format(-0.00004)), "0.0000");
    EXPECT_EQ((NumberFormat{12}.format(0.5)), "0.500000000000");
    EXPECT_EQ((NumberFormat{0}.format(9.5)), "10");
}

TEST(NumberFormat, ScaleAppliesBeforeRounding)
{
    NumberFormat inch{4};
    inch.scale = 1 / 25.4;
    EXPECT_EQ(inch.format(25.4), "1.0000");
    EXPECT_EQ(inch.format(-0.001), "0.0000");  // -0.00004 inch rounds to a zero that carries no sign
    NumberFormat rpm{0};
    rpm.scale = 60;
    EXPECT_EQ(rpm.format(3.3333), "200");
}

TEST(NumberFormat, LongestNumbersFitTheBuffer)
{
    NumberFormat widest{12, false, false, true};
    char buffer[NumberFormat::kBufferSize];
    const std::string text(buffer, widest.formatTo(-1.7976931348623157e308, buffer));
    EXPECT_EQ(text.size(), 323u);  // '-', 309 digits, '.', 12 decimals
    EXPECT_EQ(text.substr(0, 8), "-1797693");
    EXPECT_EQ(widest.format(1.7976931348623157e308).substr(0, 8), "+1797693");
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

TEST_F(AtomicFileTest, ReadsWholeFilesAndRefusesFolders)
{
    std::string large;
    for (int i = 0; large.size() < 300000; ++i)
        large += "N" + std::to_string(i) + " G1 X1.000 Y2.000\n";
    const std::string path = (dir / "large.nc").string();
    ASSERT_TRUE(writeFileAtomically(path, large));
    EXPECT_EQ(readTextFile(path).value(), large);
    ASSERT_TRUE(writeFileAtomically(path, ""));
    EXPECT_EQ(readTextFile(path).value(), "");
    auto folder = readTextFile(dir.string());
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error().message, "cannot read: it is a folder, not a file");
    EXPECT_EQ(readTextFile("/proc/self/status").value().rfind("Name:", 0), 0u);  // size 0 until read
}

// A file that must be text: binary data (a NUL byte) is an error naming its line; Latin-1
// comments of an old control's program are text.
TEST_F(AtomicFileTest, PlainTextRefusesBinaryDataAtItsLine)
{
    const std::string path = (dir / "picked-by-mistake.nc").string();
    ASSERT_TRUE(writeFileAtomically(path, std::string("G0 X0\nG1 X1\n\x89PNG\0\x1a\nG1 X2\n", 25)));
    auto binary = readPlainTextFile(path);
    ASSERT_FALSE(binary);
    EXPECT_EQ(binary.error().file, path);
    EXPECT_EQ(binary.error().line, 3);
    EXPECT_EQ(binary.error().message, "not a text file (binary data: a NUL byte on this line)");
    EXPECT_TRUE(readTextFile(path)) << "any bytes are read where the caller takes them";
    const std::string latin1 = "G0 X0 (Fr\xe4ser \xd8 6)\nM30\n";
    ASSERT_TRUE(writeFileAtomically(path, latin1));
    EXPECT_EQ(readPlainTextFile(path).value(), latin1);
    EXPECT_FALSE(readPlainTextFile((dir / "missing.nc").string()));
}

TEST(NumberFormat, RoundedValueIsWhatTheTextReadsBackAs)
{
    Xorshift next{0x2545F4914F6CDD1Dull};
    for (int i = 0; i < 100000; ++i) {
        NumberFormat format{static_cast<int>(next() % 6), next() % 2 == 0, false, next() % 3 == 0};
        if (i % 5 == 0)
            format.scale = 1 / 25.4;
        const double value = static_cast<double>(static_cast<std::int64_t>(next() % 2000001) - 1000000) /
                             std::pow(10.0, static_cast<double>(next() % 7));
        const std::string text = format.format(value);
        double read = 0;
        std::from_chars(text.data() + (text[0] == '+' ? 1 : 0), text.data() + text.size(), read);
        ASSERT_EQ(format.roundedValue(value), read / format.scale) << text;
    }
}
