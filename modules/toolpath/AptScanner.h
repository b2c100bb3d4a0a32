// The lexical layer of the APT CL reader: physical lines become statements (continuation with `$`
// joined, every character keeping its line and column), `$$` remarks and literal text statements
// (PPRINT, PARTNO, INSERT, REMARK, TPRINT); a statement splits into its major words and an
// argument list of numbers, words and parenthesised (WORD/...) geometry groups.
#pragma once

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

// Reads units one after the other. Remarks found inside a continued statement, or after it on its
// line, come right after the statement.
class AptScanner {
public:
    AptScanner(std::string_view text, ClBuilder& out);

    // The next unit; nullopt at the end of input; an Error for a continuation that never ends.
    base::Result<std::optional<AptUnit>> next();
    // Number of lines of the whole input.
    int lineCount() const { return static_cast<int>(m_lines.size()); }
    // Where the first non-blank text after the lines read so far starts (nullopt: none).
    std::optional<TextPos> nextText() const;

private:
    base::Result<std::optional<AptUnit>> statement(std::string_view line, int lineNumber, int firstColumn);

    std::vector<std::string_view> m_lines;
    std::size_t m_next = 0;
    ClBuilder& m_out;
    std::vector<AptUnit> m_queued;
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

// Splits a statement unit at its first '/'. A statement without '/' normally holds only words
// ("RAPID", "END-OF-PATH"); for "GOTO 1,2,3" junkPos marks the "1", and the reader decides whether
// that is an Error (a known statement missing its '/') or an unknown statement.
base::Result<AptStatement> splitStatement(const AptUnit& unit, const ClBuilder& out);

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

// The comma-separated arguments: numbers, words and (WORD/arguments) groups. Malformed numbers,
// empty values, unbalanced parentheses and stray characters are Errors with line and column.
base::Result<std::vector<AptItem>> tokenizeArguments(const PositionedText& args, const ClBuilder& out);

}  // namespace camwb::toolpath
