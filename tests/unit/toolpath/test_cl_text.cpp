// PositionedText: text joined from pieces of several lines knows where each character came from,
// the line breaks between pieces included, and a slice keeps those positions.
#include "toolpath/ClText.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>

using namespace camwb::toolpath;

namespace {

std::string where(const PositionedText& text, std::size_t index)
{
    const TextPos p = text.position(index);
    return std::to_string(p.line) + ":" + std::to_string(p.column);
}

}  // namespace

TEST(PositionedText, PositionsOfPiecesAndBreaks)
{
    PositionedText text;
    EXPECT_EQ(where(text, 0), "0:0");
    text.append("GOTO/1,", 3, 5);
    text.appendBreak();
    text.append("", 4, 1);  // nothing to place
    text.append("2,3", 4, 9);
    EXPECT_EQ(text.text(), "GOTO/1, 2,3");
    EXPECT_EQ(where(text, 0), "3:5");
    EXPECT_EQ(where(text, 6), "3:11");
    EXPECT_EQ(where(text, 7), "3:12");  // the break: just after the piece before it
    EXPECT_EQ(where(text, 8), "4:9");
    EXPECT_EQ(where(text, 10), "4:11");
    EXPECT_EQ(where(text, 11), "4:12");  // past the end: after the last character
    EXPECT_EQ(where(text, 99), "4:12");

    PositionedText args;
    text.slice(5, 10, args);
    EXPECT_EQ(args.text(), "1, 2,");
    EXPECT_EQ(where(args, 0), "3:10");
    EXPECT_EQ(where(args, 2), "3:12");
    EXPECT_EQ(where(args, 3), "4:9");
    EXPECT_EQ(where(args, 5), "4:11");

    text.clear();
    EXPECT_TRUE(text.empty());
    text.append("x", 9, 2);
    EXPECT_EQ(where(text, 0), "9:2");
}

TEST(ClText, NumbersAreExactlyWhatFromCharsReads)
{
    // parseNumber reads the usual short decimals without std::from_chars; it must give the very
    // same double, bit for bit, for every length, sign and number of decimals.
    std::mt19937_64 random(20261126);
    for (int i = 0; i < 200000; ++i) {
        const int digits = 1 + static_cast<int>(random() % 19);
        std::string token = random() % 2 ? "-" : "";
        const int point = static_cast<int>(random() % static_cast<unsigned>(digits + 1));
        for (int d = 0; d < digits; ++d) {
            if (d == point && d > 0)
                token += '.';
            token += static_cast<char>('0' + random() % 10);
        }
        const std::string_view body = std::string_view(token).substr(token[0] == '-' ? 1 : 0);
        double expected = 0;
        std::from_chars(body.data(), body.data() + body.size(), expected);
        if (token[0] == '-')
            expected = -expected;
        const std::optional<double> parsed = parseNumber(token);
        ASSERT_TRUE(parsed) << token;
        ASSERT_EQ(std::memcmp(&*parsed, &expected, sizeof expected), 0) << token;
        // Read where it stands in a line: the same bits, and it says where the number ends.
        std::size_t length = 0;
        const std::optional<double> prefix = parseDecimalPrefix(token + " Y:2", length);
        if (digits <= 15) {  // up to 15 digits the mantissa is always below 2^53
            ASSERT_TRUE(prefix) << token;
            ASSERT_EQ(length, token.size()) << token;
            ASSERT_EQ(std::memcmp(&*prefix, &expected, sizeof expected), 0) << token;
        }
    }
    EXPECT_EQ(parseNumber("+1.5"), 1.5);
    EXPECT_EQ(parseNumber("5."), 5.0);
    EXPECT_EQ(parseNumber(".5"), 0.5);
    EXPECT_EQ(parseNumber("1.5E+01"), 15.0);
    EXPECT_TRUE(std::signbit(*parseNumber("-0")));
    for (const char* bad : {"", "-", ".", "1.2.3", "1e", "inf", "nan", "0x10", "1,5", "1e999"})
        EXPECT_FALSE(parseNumber(bad)) << bad;
    std::size_t length = 0;
    EXPECT_FALSE(parseDecimalPrefix("1.5e3 ", length));  // an exponent: the long way
    EXPECT_FALSE(parseDecimalPrefix("1.2.3", length));
    EXPECT_EQ(parseDecimalPrefix("-2.5]", length), -2.5);
    EXPECT_EQ(length, 4u);
}
