// Klartext source handling: a diagnostics reporter with the interpreter's limits, the split of a
// program text into blocks (block number, `~` and indented-Q continuation lines, `;` comments)
// and a character cursor over a block's segments with exact line and column.
#pragma once

#include "nc/Diagnostic.h"
#include "nc/heidenhain/Program.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc::heidenhain {

// Collects diagnostics up to a limit and counts the rest; `quiet` silences look-ahead evaluation.
class Reporter {
public:
    Reporter(std::vector<Diagnostic>& out, std::size_t limit, std::size_t& dropped) :
        m_out(out),
        m_limit(limit),
        m_dropped(dropped)
    {
    }
    void report(Severity severity, const std::string& file, int line, int column, std::string message);
    bool quiet = false;
    bool errorSeen = false;

private:
    std::vector<Diagnostic>& m_out;
    std::size_t m_limit;
    std::size_t& m_dropped;
};

// One logical block as split from the text: its segments are appended to `segments`.
struct RawBlock {
    int firstSegment = 0;
    int segmentCount = 0;
    int line = 0;
    std::int64_t number = -1;
    int numberColumn = 0;
    std::string_view comment;
    int commentLine = 0;
    bool numberTooLong = false;
};

// Splits `text` into blocks; CR, CRLF and LF line ends; NUL and other control bytes stay in the
// code and are reported by the parser.
std::vector<RawBlock> splitBlocks(std::string_view text, std::vector<Segment>& segments);

// Reads a block's code segment by segment; segment ends count as white space.
class Cursor {
public:
    Cursor(const Segment* segments, int count) : m_seg(segments), m_count(count) {}

    void skipSpace();
    bool atEnd();  // skips white space first
    char peek(int ahead = 0) const;
    void advance(int n = 1);
    int line() const;
    int column() const;

    // Case-insensitive keyword followed by a non-letter; consumed when it matches.
    bool keyword(std::string_view word);
    // A run of letters and underscores (may be empty).
    std::string_view letters();
    // A run of characters up to white space.
    std::string_view token();
    // The rest of the current line's code (trailing blanks removed).
    std::string_view rest();
    // An unsigned integer (digits only); nullopt when none.
    std::optional<std::int64_t> integer();
    // [+-]digits[.digits] (a decimal comma is read as a point and flagged).
    std::optional<double> number(bool* decimalComma = nullptr, bool* outOfRange = nullptr);
    // "text" without the quotes; nullopt when not at a quote. `closed` false when unterminated.
    std::optional<std::string_view> quoted(bool* closed);

    struct Mark {
        int segment;
        std::size_t pos;
    };
    Mark mark() const { return {m_index, m_pos}; }
    void reset(Mark m)
    {
        m_index = m.segment;
        m_pos = m.pos;
    }

private:
    const Segment* m_seg;
    int m_count;
    int m_index = 0;
    std::size_t m_pos = 0;
};

bool isLetter(char c);
bool isDigit(char c);
char upper(char c);
bool equalsIgnoreCase(std::string_view a, std::string_view b);

}  // namespace camwb::nc::heidenhain
