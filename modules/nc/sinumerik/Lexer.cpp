#include "nc/sinumerik/Lexer.h"

#include <charconv>

namespace camwb::nc::sinumerik {

namespace {

bool isAlpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '$'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

double parseNumber(std::string_view text)
{
    double value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc())
        return text.size() > 0 && result.ec == std::errc::result_out_of_range ? 1e300 : 0.0;
    return value;
}

}  // namespace

bool LineSplitter::next(std::string_view& line)
{
    if (m_pos >= m_text.size())
        return false;
    std::size_t end = m_pos;
    while (end < m_text.size() && m_text[end] != '\n' && m_text[end] != '\r')
        ++end;
    line = m_text.substr(m_pos, end - m_pos);
    m_pos = end + 1;
    if (end + 1 < m_text.size() && m_text[end] == '\r' && m_text[end + 1] == '\n')
        ++m_pos;
    return true;
}

void lexLine(std::string_view line, int lineNumber, std::vector<Token>& out)
{
    std::size_t i = 0;
    const std::size_t n = line.size();
    bool space = true;
    auto push = [&](Tok kind, std::size_t start, std::size_t length, double number = 0) {
        Token t;
        t.kind = kind;
        t.spaceBefore = space;
        t.line = lineNumber;
        t.column = static_cast<int>(start) + 1;
        t.text = line.substr(start, length);
        t.number = number;
        out.push_back(t);
        space = false;
    };
    while (i < n) {
        const char c = line[i];
        if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
            ++i;
            space = true;
            continue;
        }
        if (c == ';') {
            push(Tok::Comment, i + 1, n - i - 1);
            out.back().column = static_cast<int>(i) + 1;
            return;
        }
        if (isAlpha(c)) {
            std::size_t j = i + 1;
            while (j < n && (isAlpha(line[j]) || isDigit(line[j])))
                ++j;
            // X10.5: an address with a decimal value stays one token, split by the parser.
            if (j < n && line[j] == '.' && isDigit(line[j - 1])) {
                ++j;
                while (j < n && isDigit(line[j]))
                    ++j;
            }
            push(Tok::Name, i, j - i);
            i = j;
            continue;
        }
        if (isDigit(c) || (c == '.' && i + 1 < n && isDigit(line[i + 1]))) {
            std::size_t j = i;
            while (j < n && isDigit(line[j]))
                ++j;
            if (j < n && line[j] == '.') {
                ++j;
                while (j < n && isDigit(line[j]))
                    ++j;
            }
            // 1.5EX3: the SINUMERIK exponent.
            if (j + 2 < n && (line[j] == 'E' || line[j] == 'e') && (line[j + 1] == 'X' || line[j + 1] == 'x')) {
                std::size_t k = j + 2;
                bool negative = false;
                if (k < n && (line[k] == '-' || line[k] == '+')) {
                    negative = line[k] == '-';
                    ++k;
                }
                const std::size_t digits = k;
                while (k < n && isDigit(line[k]))
                    ++k;
                if (k > digits && k - digits <= 3) {
                    double mantissa = parseNumber(line.substr(i, j - i));
                    int exponent = 0;
                    std::from_chars(line.data() + digits, line.data() + k, exponent);
                    double scale = 1;
                    for (int e = 0; e < exponent && e < 400; ++e)
                        scale *= 10;
                    push(Tok::Number, i, k - i, negative ? mantissa / scale : mantissa * scale);
                    i = k;
                    continue;
                }
            }
            push(Tok::Number, i, j - i, parseNumber(line.substr(i, j - i)));
            i = j;
            continue;
        }
        if (c == '"') {
            std::size_t j = i + 1;
            while (j < n && line[j] != '"')
                ++j;
            push(Tok::String, i + 1, j - i - 1);
            out.back().column = static_cast<int>(i) + 1;
            i = j < n ? j + 1 : j;
            continue;
        }
        const char next = i + 1 < n ? line[i + 1] : '\0';
        switch (c) {
        case '+':
            push(Tok::Plus, i, 1);
            break;
        case '-':
            push(Tok::Minus, i, 1);
            break;
        case '*':
            push(Tok::Star, i, 1);
            break;
        case '/':
            push(Tok::Slash, i, 1);
            break;
        case '(':
            push(Tok::LParen, i, 1);
            break;
        case ')':
            push(Tok::RParen, i, 1);
            break;
        case '[':
            push(Tok::LBracket, i, 1);
            break;
        case ']':
            push(Tok::RBracket, i, 1);
            break;
        case ',':
            push(Tok::Comma, i, 1);
            break;
        case ':':
            push(Tok::Colon, i, 1);
            break;
        case '=':
            if (next == '=') {
                push(Tok::Eq, i, 2);
                ++i;
            } else {
                push(Tok::Assign, i, 1);
            }
            break;
        case '<':
            if (next == '>') {
                push(Tok::Ne, i, 2);
                ++i;
            } else if (next == '=') {
                push(Tok::Le, i, 2);
                ++i;
            } else {
                push(Tok::Lt, i, 1);
            }
            break;
        case '>':
            if (next == '=') {
                push(Tok::Ge, i, 2);
                ++i;
            } else {
                push(Tok::Gt, i, 1);
            }
            break;
        case '.':
            if (next == '.' && i + 2 < n && line[i + 2] == '.') {
                push(Tok::Ellipsis, i, 3);
                i += 2;
                break;
            }
            push(Tok::Invalid, i, 1);
            break;
        default: {
            // One token per UTF-8 sequence, so a column points at the character.
            std::size_t len = 1;
            const auto u = static_cast<unsigned char>(c);
            if (u >= 0xC0)
                while (i + len < n && (static_cast<unsigned char>(line[i + len]) & 0xC0) == 0x80 && len < 4)
                    ++len;
            push(Tok::Invalid, i, len);
            i += len - 1;
            break;
        }
        }
        ++i;
    }
}

}  // namespace camwb::nc::sinumerik
