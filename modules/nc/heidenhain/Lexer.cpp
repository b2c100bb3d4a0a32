// Block splitting and the character cursor of the Klartext reader (see Lexer.h).
#include "nc/heidenhain/Lexer.h"

#include <charconv>
#include <cmath>

namespace camwb::nc::heidenhain {

void Reporter::report(Severity severity, const std::string& file, int line, int column, std::string message)
{
    if (quiet)
        return;
    if (severity == Severity::Error)
        errorSeen = true;
    if (m_out.size() >= m_limit) {
        ++m_dropped;
        return;
    }
    m_out.push_back({severity, file.empty() ? std::string("<input>") : file, line, column, std::move(message)});
}

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
bool equalsIgnoreCase(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (upper(a[i]) != upper(b[i]))
            return false;
    }
    return true;
}

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

std::string_view trimRight(std::string_view s)
{
    while (!s.empty() && isSpace(s.back()))
        s.remove_suffix(1);
    return s;
}

// Position of the `;` that starts the comment (outside quotes), npos when none.
std::size_t commentStart(std::string_view s)
{
    bool inQuote = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '"')
            inQuote = !inQuote;
        else if (s[i] == ';' && !inQuote)
            return i;
    }
    return std::string_view::npos;
}

bool startsWithCycleDef(std::string_view code)
{
    std::size_t i = 0;
    while (i < code.size() && isSpace(code[i]))
        ++i;
    return code.size() - i >= 4 && equalsIgnoreCase(code.substr(i, 4), "CYCL");
}

// An iTNC 530 cycle parameter line: indented, no block number, "Q<digits>" first.
bool isIndentedParameter(std::string_view line)
{
    if (line.empty() || !isSpace(line[0]))
        return false;
    std::size_t i = 0;
    while (i < line.size() && isSpace(line[i]))
        ++i;
    return i + 1 < line.size() && upper(line[i]) == 'Q' && isDigit(line[i + 1]);
}

}  // namespace

std::vector<RawBlock> splitBlocks(std::string_view text, std::vector<Segment>& segments)
{
    std::vector<RawBlock> blocks;
    bool continues = false;  // the previous line ended with `~`
    bool inCycleDef = false;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = pos;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r')
            ++end;
        std::string_view line = text.substr(pos, end - pos);
        if (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n')
            pos = end + 2;
        else
            pos = end < text.size() ? end + 1 : end;
        ++lineNo;

        std::string_view code = line;
        std::string_view comment;
        const std::size_t semi = commentStart(line);
        if (semi != std::string_view::npos) {
            code = line.substr(0, semi);
            comment = line.substr(semi + 1);
        }
        bool tilde = false;
        if (!comment.empty()) {
            std::string_view c = trimRight(comment);
            if (!c.empty() && c.back() == '~') {
                tilde = true;
                c.remove_suffix(1);
            }
            comment = trimRight(c);
        } else {
            std::string_view c = trimRight(code);
            if (!c.empty() && c.back() == '~') {
                tilde = true;
                c.remove_suffix(1);
            }
            code = c;
        }
        if (semi != std::string_view::npos && !tilde) {
            // `~` written before the comment (TNC 640 writes it at the very end, after the comment).
            std::string_view c = trimRight(code);
            if (!c.empty() && c.back() == '~') {
                tilde = true;
                c.remove_suffix(1);
                code = c;
            }
        }

        const bool continuation = !blocks.empty() && (continues || (inCycleDef && isIndentedParameter(line)));
        if (continuation) {
            segments.push_back({code, lineNo, 1});
            ++blocks.back().segmentCount;
            continues = tilde;
            continue;
        }

        RawBlock block;
        block.line = lineNo;
        block.comment = comment;
        block.commentLine = lineNo;
        // Block number: leading digits followed by white space or the end of the code.
        std::size_t i = 0;
        while (i < code.size() && isSpace(code[i]))
            ++i;
        std::size_t digits = i;
        while (digits < code.size() && isDigit(code[digits]))
            ++digits;
        if (digits > i && (digits == code.size() || isSpace(code[digits]))) {
            block.numberColumn = static_cast<int>(i) + 1;
            if (digits - i > 15) {
                block.numberTooLong = true;
            } else {
                std::int64_t n = 0;
                std::from_chars(code.data() + i, code.data() + digits, n);
                block.number = n;
            }
            segments.push_back({code.substr(digits), lineNo, static_cast<int>(digits) + 1});
        } else {
            segments.push_back({code, lineNo, 1});
        }
        block.firstSegment = static_cast<int>(segments.size()) - 1;
        block.segmentCount = 1;
        inCycleDef = startsWithCycleDef(segments.back().code);
        blocks.push_back(block);
        continues = tilde;
    }
    return blocks;
}

void Cursor::skipSpace()
{
    while (m_index < m_count) {
        const std::string_view code = m_seg[m_index].code;
        while (m_pos < code.size() && isSpace(code[m_pos]))
            ++m_pos;
        if (m_pos < code.size())
            return;
        ++m_index;
        m_pos = 0;
    }
}

bool Cursor::atEnd()
{
    skipSpace();
    return m_index >= m_count;
}

char Cursor::peek(int ahead) const
{
    if (m_index >= m_count)
        return '\0';
    const std::string_view code = m_seg[m_index].code;
    const std::size_t at = m_pos + static_cast<std::size_t>(ahead);
    return at < code.size() ? code[at] : '\0';
}

void Cursor::advance(int n)
{
    if (m_index >= m_count)
        return;
    m_pos = std::min(m_pos + static_cast<std::size_t>(n), m_seg[m_index].code.size());
}

int Cursor::line() const
{
    if (m_count == 0)
        return 0;
    return m_seg[m_index < m_count ? m_index : m_count - 1].line;
}

int Cursor::column() const
{
    if (m_count == 0)
        return 1;
    if (m_index >= m_count) {
        const Segment& last = m_seg[m_count - 1];
        return last.column + static_cast<int>(last.code.size());
    }
    return m_seg[m_index].column + static_cast<int>(m_pos);
}

bool Cursor::keyword(std::string_view word)
{
    skipSpace();
    if (m_index >= m_count)
        return false;
    const std::string_view code = m_seg[m_index].code;
    if (code.size() - m_pos < word.size() || !equalsIgnoreCase(code.substr(m_pos, word.size()), word))
        return false;
    const std::size_t after = m_pos + word.size();
    if (after < code.size() && isLetter(code[after]) && isLetter(word.back()))
        return false;
    m_pos = after;
    return true;
}

std::string_view Cursor::letters()
{
    if (m_index >= m_count)
        return {};
    const std::string_view code = m_seg[m_index].code;
    const std::size_t start = m_pos;
    while (m_pos < code.size() && isLetter(code[m_pos]))
        ++m_pos;
    return code.substr(start, m_pos - start);
}

std::string_view Cursor::token()
{
    skipSpace();
    if (m_index >= m_count)
        return {};
    const std::string_view code = m_seg[m_index].code;
    const std::size_t start = m_pos;
    while (m_pos < code.size() && !isSpace(code[m_pos]))
        ++m_pos;
    return code.substr(start, m_pos - start);
}

std::string_view Cursor::rest()
{
    skipSpace();
    if (m_index >= m_count)
        return {};
    const std::string_view code = m_seg[m_index].code;
    const std::string_view out = trimRight(code.substr(m_pos));
    m_pos = code.size();
    return out;
}

std::optional<std::int64_t> Cursor::integer()
{
    if (m_index >= m_count)
        return std::nullopt;
    const std::string_view code = m_seg[m_index].code;
    std::size_t end = m_pos;
    while (end < code.size() && isDigit(code[end]))
        ++end;
    if (end == m_pos)
        return std::nullopt;
    std::int64_t value = 0;
    const auto [ptr, ec] = std::from_chars(code.data() + m_pos, code.data() + end, value);
    m_pos = end;
    if (ec != std::errc())
        return std::int64_t{-1};  // too long: callers see an out-of-range value
    return value;
}

std::optional<double> Cursor::number(bool* decimalComma, bool* outOfRange)
{
    if (m_index >= m_count)
        return std::nullopt;
    const std::string_view code = m_seg[m_index].code;
    std::size_t i = m_pos;
    bool negative = false;
    if (i < code.size() && (code[i] == '+' || code[i] == '-')) {
        negative = code[i] == '-';
        ++i;
    }
    // Copy digits into a small buffer so that a decimal comma can become a point.
    char buffer[64];
    std::size_t n = 0;
    bool digits = false;
    bool tooLong = false;
    auto put = [&](char c) {
        if (n < sizeof buffer)
            buffer[n++] = c;
        else
            tooLong = true;
    };
    while (i < code.size() && isDigit(code[i])) {
        put(code[i++]);
        digits = true;
    }
    if (i < code.size() && (code[i] == '.' || (code[i] == ',' && i + 1 < code.size() && isDigit(code[i + 1])))) {
        if (code[i] == ',' && decimalComma)
            *decimalComma = true;
        put('.');
        ++i;
        while (i < code.size() && isDigit(code[i])) {
            put(code[i++]);
            digits = true;
        }
    }
    if (!digits)
        return std::nullopt;
    m_pos = i;
    double value = 0;
    const auto [ptr, ec] = std::from_chars(buffer, buffer + n, value);
    if (tooLong || ec != std::errc() || !std::isfinite(value)) {
        if (outOfRange)
            *outOfRange = true;
        return 0.0;
    }
    return negative ? -value : value;
}

std::optional<std::string_view> Cursor::quoted(bool* closed)
{
    if (peek() != '"')
        return std::nullopt;
    const std::string_view code = m_seg[m_index].code;
    const std::size_t start = m_pos + 1;
    std::size_t end = start;
    while (end < code.size() && code[end] != '"')
        ++end;
    *closed = end < code.size();
    m_pos = *closed ? end + 1 : end;
    return code.substr(start, end - start);
}

}  // namespace camwb::nc::heidenhain
