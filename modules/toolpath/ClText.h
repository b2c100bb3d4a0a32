// Text plumbing shared by the CL importers (lines come from base::LineReader): text joined from
// pieces of several lines that still knows the line and column of every character, and
// locale-independent numbers (std::from_chars, never an exception).
#pragma once

#include "base/LineReader.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

// 1-based line and column; columns count bytes, a tab is one column.
struct TextPos {
    int line = 0;
    int column = 0;
};

// Text assembled from pieces of source lines (a statement continued over several lines). It
// keeps where each piece starts rather than a position per character, and clear() keeps its
// storage, so a reader that reuses one for every statement allocates nothing per line.
class PositionedText {
public:
    // Appends `piece`, whose first character sits at `line`:`firstColumn`.
    void append(std::string_view piece, int line, int firstColumn);
    // One blank standing for a line break, so that pieces never glue two tokens together.
    void appendBreak();
    void clear();

    const std::string& text() const { return m_text; }
    bool empty() const { return m_text.empty(); }
    std::size_t size() const { return m_text.size(); }
    // Position of character `index`; index == size() gives the place just after the last one.
    TextPos position(std::size_t index) const;
    // The characters [begin, end) with their positions, into `out` (its storage reused).
    void slice(std::size_t begin, std::size_t end, PositionedText& out) const;

private:
    struct Piece {
        std::size_t start = 0;  // index of its first character in m_text
        TextPos pos;            // where that character sits; the others follow on the same line
    };

    std::string m_text;
    std::vector<Piece> m_pieces;
};

// A line with something on it: its text without the blanks around it, its 1-based number and the
// column where the text starts.
struct ContentLine {
    std::string_view text;
    int number = 0;
    int column = 0;
};
// The next line that is not blank (the blank ones skipped); nullopt at the end of the input.
std::optional<ContentLine> nextContentLine(base::LineReader& lines);

// A whole token as a finite number: [+|-]digits[.digits][(e|E)[+|-]digits], also "5." and ".5".
// Anything else (two points, letters, inf, nan, overflow) gives nullopt.
std::optional<double> parseNumber(std::string_view token);
// The usual short decimal at the start of `text` ("[+|-]digits[.digits]", at most 18 digits) and
// in `length` how many characters it takes: what parseNumber gives for them, bit for bit, without
// finding the token's end first. nullopt when what starts there is not such a number (an
// exponent, more digits): then read the whole token with parseNumber.
std::optional<double> parseDecimalPrefix(std::string_view text, std::size_t& length);

// Inline: the importers call these for every character of a file.
inline bool isSpace(char c) { return c == ' ' || c == '\t'; }  // a blank or a tab
inline std::size_t leadingSpaces(std::string_view text)
{
    std::size_t n = 0;
    while (n < text.size() && isSpace(text[n]))
        ++n;
    return n;
}
inline std::string_view trimRight(std::string_view text)
{
    while (!text.empty() && isSpace(text.back()))
        text.remove_suffix(1);
    return text;
}
inline std::string_view trim(std::string_view text) { return trimRight(text.substr(leadingSpaces(text))); }
std::string toUpper(std::string_view text);
bool equalsNoCase(std::string_view a, std::string_view b);
bool startsWithNoCase(std::string_view text, std::string_view prefix);

// A length or angle for messages: up to 4 decimals, trailing zeros trimmed ("21", "0.0125").
std::string formatForMessage(double value);

}  // namespace camwb::toolpath
