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

namespace {

constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

}  // namespace

std::optional<double> parseDecimalPrefix(std::string_view text, std::size_t& length)
{
    // A mantissa below 2^53 and a power of ten up to 10^22 are exact doubles and IEEE division
    // rounds correctly, so the quotient is the double nearest the decimal: exactly what
    // std::from_chars gives (Clinger's fast path).
    std::size_t i = 0;
    const bool negative = !text.empty() && text[0] == '-';
    if (!text.empty() && (text[0] == '-' || text[0] == '+'))
        ++i;
    unsigned long long mantissa = 0;
    int digits = 0, decimals = 0;
    bool point = false;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c >= '0' && c <= '9') {
            if (++digits > 18)
                return std::nullopt;
            mantissa = mantissa * 10 + static_cast<unsigned long long>(c - '0');
            decimals += point ? 1 : 0;
        } else if (c == '.' && !point) {
            point = true;
        } else if (c == 'e' || c == 'E' || c == '.') {  // an exponent, a second point: the long way
            return std::nullopt;
        } else {
            break;
        }
    }
    if (digits == 0 || mantissa > (1ull << 53) || decimals > 22)
        return std::nullopt;
    length = i;
    const double value = static_cast<double>(mantissa) / kExactPowersOfTen[decimals];
    return negative ? -value : value;
}

std::optional<double> parseNumber(std::string_view token)
{
    std::size_t length = 0;
    if (const std::optional<double> simple = parseDecimalPrefix(token, length); simple && length == token.size())
        return simple;
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
