// PositionedText: text joined from pieces of several lines knows where each character came from,
// the line breaks between pieces included, and a slice keeps those positions.
#include "toolpath/ClText.h"

#include <gtest/gtest.h>

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
