#include "toolpath/ClText.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace camwb::toolpath {

std::optional<ContentLine> nextContentLine(base::LineReader& lines)
{
    while (const std::optional<std::string_view> raw = lines.next()) {
        const std::size_t indent = leadingSpaces(*raw);
        const std::string_view text = trimRight(raw->substr(indent));
        if (!text.empty())
            return ContentLine{text, lines.lineNumber(), static_cast<int>(indent) + 1};
    }
    return std::nullopt;
}

void PositionedText::append(std::string_view piece, int line, int firstColumn)
{
    if (piece.empty())
        return;
    m_pieces.push_back({m_text.size(), {line, firstColumn}});
    m_text.append(piece);
}

void PositionedText::appendBreak()
{
    const TextPos after = position(m_text.size());
    m_pieces.push_back({m_text.size(), after});
    m_text.push_back(' ');
}

void PositionedText::clear()
{
    m_text.clear();
    m_pieces.clear();
}

TextPos PositionedText::position(std::size_t index) const
{
    if (m_text.empty())
        return {};
    const std::size_t at = std::min(index, m_text.size() - 1);
    auto piece = m_pieces.rbegin();
    while (piece->start > at)
        ++piece;
    // Past the end: the place just after the last character.
    const int past = index >= m_text.size() ? 1 : 0;
    return {piece->pos.line, piece->pos.column + static_cast<int>(at - piece->start) + past};
}

void PositionedText::slice(std::size_t begin, std::size_t end, PositionedText& out) const
{
    out.clear();
    end = std::min(end, m_text.size());
    for (std::size_t i = 0; i < m_pieces.size(); ++i) {
        const std::size_t pieceEnd = i + 1 < m_pieces.size() ? m_pieces[i + 1].start : m_text.size();
        const std::size_t from = std::max(begin, m_pieces[i].start);
        const std::size_t to = std::min(end, pieceEnd);
        if (from < to)
            out.append(std::string_view(m_text).substr(from, to - from), m_pieces[i].pos.line,
                       m_pieces[i].pos.column + static_cast<int>(from - m_pieces[i].start));
    }
}

std::optional<double> parseNumber(std::string_view token)
{
    // Checked by hand first: from_chars would also take "inf", "nan" and hex-like forms, and it
    // rejects the leading '+' that APT writers use.
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '+' || token[i] == '-'))
        ++i;
    const std::size_t mantissaStart = i;
    int digits = 0;
    while (i < token.size() && token[i] >= '0' && token[i] <= '9') {
        ++i;
        ++digits;
    }
    if (i < token.size() && token[i] == '.') {
        ++i;
        while (i < token.size() && token[i] >= '0' && token[i] <= '9') {
            ++i;
            ++digits;
        }
    }
    if (digits == 0)
        return std::nullopt;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        if (i < token.size() && (token[i] == '+' || token[i] == '-'))
            ++i;
        int exponentDigits = 0;
        while (i < token.size() && token[i] >= '0' && token[i] <= '9') {
            ++i;
            ++exponentDigits;
        }
        if (exponentDigits == 0)
            return std::nullopt;
    }
    if (i != token.size())
        return std::nullopt;

    const bool negative = token[0] == '-';
    const std::string_view body = token.substr(mantissaStart);
    double value = 0;
    const auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), value);
    if (error != std::errc() || end != body.data() + body.size() || !std::isfinite(value))
        return std::nullopt;
    return negative ? -value : value;
}

bool isSpace(char c) { return c == ' ' || c == '\t'; }

std::size_t leadingSpaces(std::string_view text)
{
    std::size_t n = 0;
    while (n < text.size() && isSpace(text[n]))
        ++n;
    return n;
}

std::string_view trim(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    return trimRight(text);
}

std::string_view trimRight(std::string_view text)
{
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return text;
}

std::string toUpper(std::string_view text)
{
    std::string out(text);
    for (char& c : out) {
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    }
    return out;
}

bool equalsNoCase(std::string_view a, std::string_view b) { return a.size() == b.size() && toUpper(a) == toUpper(b); }

bool startsWithNoCase(std::string_view text, std::string_view prefix)
{
    return text.size() >= prefix.size() && equalsNoCase(text.substr(0, prefix.size()), prefix);
}

std::string formatForMessage(double value)
{
    base::NumberFormat format;
    format.decimals = 4;
    format.trimTrailingZeros = true;
    return format.format(value);
}

}  // namespace camwb::toolpath
