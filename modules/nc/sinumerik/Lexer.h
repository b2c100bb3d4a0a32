// Tokens of one SINUMERIK block line with their exact line and column: names, numbers, strings,
// operators and the trailing ';' comment. No allocation per token: texts are views of the line.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace camwb::nc::sinumerik {

enum class Tok : std::uint8_t {
    Name,    // [A-Za-z_$][A-Za-z0-9_]*, with a decimal part glued when it ends in digits (X10.5)
    Number,  // 12, 1.5, .5 (value in `number`)
    String,  // "text" (text without the quotes)
    Plus,
    Minus,
    Star,
    Slash,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Comma,
    Assign,
    Colon,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    Ellipsis,  // ... (a listing cut short)
    Comment,   // ; to the end of the line (text without the ';')
    Invalid,   // a character no SINUMERIK block has
};

struct Token {
    Tok kind = Tok::Invalid;
    bool spaceBefore = false;  // whitespace between this token and the previous one
    int line = 0;
    int column = 0;  // 1-based
    std::string_view text;
    double number = 0;
};

// Appends the tokens of `line` (no line break in it) to `out`.
void lexLine(std::string_view line, int lineNumber, std::vector<Token>& out);

// The physical lines of a text: "\n", "\r\n" and a lone "\r" all end a line.
class LineSplitter {
public:
    explicit LineSplitter(std::string_view text) : m_text(text) {}
    bool next(std::string_view& line);

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
};

}  // namespace camwb::nc::sinumerik
