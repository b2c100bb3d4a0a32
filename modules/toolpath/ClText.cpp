#include "toolpath/ClText.h"

#include "base/NumberFormat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace camwb::toolpath {

std::vector<std::string_view> splitLines(std::string_view text)
{
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    if (text.substr(0, bom.size()) == bom)
        text.remove_prefix(bom.size());
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back(line);
        if (end == std::string_view::npos)
            break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

void PositionedText::append(std::string_view piece, int line, int firstColumn)
{
    for (std::size_t i = 0; i < piece.size(); ++i) {
        m_text.push_back(piece[i]);
        m_positions.push_back({line, firstColumn + static_cast<int>(i)});
    }
}

void PositionedText::appendBreak()
{
    const TextPos after = position(m_text.size());
    m_text.push_back(' ');
    m_positions.push_back(after);
}

TextPos PositionedText::position(std::size_t index) const
{
    if (index < m_positions.size())
        return m_positions[index];
    if (m_positions.empty())
        return {};
    const TextPos last = m_positions.back();
    return {last.line, last.column + 1};
}

PositionedText PositionedText::slice(std::size_t begin, std::size_t end) const
{
    PositionedText out;
    end = std::min(end, m_text.size());
    for (std::size_t i = begin; i < end; ++i) {
        out.m_text.push_back(m_text[i]);
        out.m_positions.push_back(m_positions[i]);
    }
    return out;
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
