// The lexical layer of the APT CL reader: physical lines become statements (continuation with `$`
// joined, every character keeping its line and column), `$$` remarks and literal text statements
// (PPRINT, PARTNO, INSERT, REMARK, TPRINT); a statement splits into its major words and an
// argument list of numbers, words and parenthesised (WORD/...) geometry groups.
#pragma once

#include "base/LineReader.h"
#include "toolpath/ClBuilder.h"
#include "toolpath/ClText.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

struct AptUnit {
    enum class Kind { Statement, Remark, Text };
    Kind kind = Kind::Statement;
    int line = 0;         // first line
    TextPos start;        // its first character ("$$" of a remark)
    PositionedText text;  // Statement: its text without remarks, continuation lines joined
    std::string keyword;  // Text: the keyword, upper-case ("PPRINT")
    std::string body;     // Remark and Text: the text after `$$` / the keyword, trimmed
    TextPos bodyPos;
};

// Reads units one after the other, a line at a time. Remarks found inside a continued statement,
// or after it on its line, come right after the statement.
class AptScanner {
public:
    AptScanner(base::LineReader& lines, ClBuilder& out) : m_lines(lines), m_out(out) {}

    // The next unit into `unit` (its storage reused); false at the end of input; an Error for a
    // continuation that never ends.
    base::Result<bool> next(AptUnit& unit);
    // Number of the last line read (after skipToEnd() or at the end: of the whole input).
    int lineCount() const { return m_lines.lineNumber(); }
    // Reads the rest of the input; where its first non-blank text starts (nullopt: none).
    base::Result<std::optional<TextPos>> skipToEnd();

private:
    base::Status statement(std::string_view line, int lineNumber, int firstColumn, AptUnit& unit);

    base::LineReader& m_lines;
    ClBuilder& m_out;
    std::vector<AptUnit> m_queued;
    std::size_t m_queuedNext = 0;
};

struct AptStatement {
    int line = 0;
    std::vector<std::string> words;  // major words, upper-case: {"GOTO"}, {"TLON", "GOFWD"}, {"TOOL PATH"}
    TextPos wordPos;                 // where the first major word starts
    bool hasSlash = false;
    TextPos argsPos;                 // just after the '/' (or after the words)
    PositionedText args;             // the text after the '/'
    bool pointLine = false;          // "x, y, z" alone: more points of the GOTO before it (args = all of it)
    std::optional<TextPos> junkPos;  // no '/' and not only words ("GOTO 1,2,3"): where that starts

    bool is(std::string_view word) const { return words.size() == 1 && words[0] == word; }
};

// Splits a statement unit at its first '/' into `s` (its storage reused). A statement without '/'
// normally holds only words ("RAPID", "END-OF-PATH"); for "GOTO 1,2,3" junkPos marks the "1", and
// the reader decides whether that is an Error (a known statement missing its '/') or an unknown
// statement.
base::Status splitStatement(const AptUnit& unit, const ClBuilder& out, AptStatement& s);

struct AptItem {
    enum class Kind { Number, Word, Group };
    Kind kind = Kind::Number;
    double number = 0;
    std::string word;  // Word: upper-case; Group: its word ("CIRCLE")
    TextPos pos;
    std::vector<AptItem> items;  // Group: its arguments

    bool isWord(std::string_view w) const { return kind == Kind::Word && word == w; }
};

// An item as messages name it: the word, or "(CIRCLE/...)" for a group.
std::string describeItem(const AptItem& item);

// The comma-separated arguments into `items` (its storage reused): numbers, words and
// (WORD/arguments) groups. Malformed numbers, empty values, unbalanced parentheses and stray
// characters are Errors with line and column.
base::Status tokenizeArguments(const PositionedText& args, const ClBuilder& out, std::vector<AptItem>& items);

}  // namespace camwb::toolpath
