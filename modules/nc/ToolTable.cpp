#include "nc/ToolTable.h"

#include "base/AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace camwb::nc {

namespace {

constexpr std::string_view kLetters = "TPXYZABCUVWDIJQ";

struct LineReader {
    std::string_view line;
    std::size_t at = 0;
    const std::string& file;
    int lineNumber;

    base::Error error(std::size_t column, std::string message) const
    {
        return base::makeError(std::move(message), file, lineNumber, static_cast<int>(column) + 1);
    }
    void skipSpace()
    {
        while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r'))
            ++at;
    }
};

// The number after a letter: digits, an optional sign and one decimal point, nothing glued on.
std::optional<double> readNumber(LineReader& r)
{
    const std::size_t start = r.at;
    std::size_t end = start;
    if (end < r.line.size() && (r.line[end] == '+' || r.line[end] == '-'))
        ++end;
    while (end < r.line.size() && (std::isdigit(static_cast<unsigned char>(r.line[end])) || r.line[end] == '.'))
        ++end;
    // A word ends at a space, a comment or the end of the line.
    if (end < r.line.size() && r.line[end] != ' ' && r.line[end] != '\t' && r.line[end] != '\r' && r.line[end] != ';')
        return std::nullopt;
    std::string_view digits = r.line.substr(start, end - start);
    if (!digits.empty() && digits.front() == '+')
        digits.remove_prefix(1);
    double value = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || ec != std::errc() || ptr != digits.data() + digits.size() || !std::isfinite(value))
        return std::nullopt;
    r.at = end;
    return value;
}

base::Status parseLine(LineReader& r, ToolTable& table, std::map<int, int>& lineOfTool)
{
    ToolTableEntry entry;
    bool seen[26] = {};
    for (;;) {
        r.skipSpace();
        if (r.at >= r.line.size() || r.line[r.at] == ';')
            break;
        const std::size_t column = r.at;
        const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(r.line[r.at])));
        if (kLetters.find(letter) == std::string_view::npos)
            return r.error(column, "unknown word '" + std::string(1, r.line[r.at]) +
                                       "' (a tool table line holds T P X Y Z A B C U V W D I J Q)");
        if (seen[letter - 'A'])
            return r.error(column, std::string(1, letter) + " given twice on one line");
        seen[letter - 'A'] = true;
        ++r.at;
        const auto value = readNumber(r);
        if (!value)
            return r.error(r.at, std::string("malformed number after ") + letter);
        if (letter == 'T' || letter == 'P' || letter == 'Q') {
            if (*value < 0 || *value != std::floor(*value) || *value > 1e9)
                return r.error(column + 1, std::string(1, letter) + " must be a whole number >= 0");
        }
        if (letter == 'T')
            entry.number = static_cast<int>(*value);
        else if (letter == 'P')
            entry.pocket = static_cast<int>(*value);
        else if (letter == 'D') {
            if (*value < 0)
                return r.error(column + 1, "negative diameter (compensation on the other side) is not supported");
            entry.diameterMm = *value;
        } else if (letter == 'Z')
            entry.lengthMm = *value;
    }
    if (r.at < r.line.size() && r.line[r.at] == ';') {
        std::string_view comment = r.line.substr(r.at + 1);
        while (!comment.empty() && (comment.back() == '\r' || comment.back() == ' '))
            comment.remove_suffix(1);
        entry.comment = std::string(comment);
    }
    bool any = false;
    for (bool s : seen)
        any = any || s;
    if (!any)
        return {};  // empty or comment-only line
    if (!seen['T' - 'A'])
        return r.error(0, "tool table line without a tool number T");
    if (auto [it, added] = lineOfTool.emplace(entry.number, r.lineNumber); !added)
        return r.error(0, "tool " + std::to_string(entry.number) + " is already given on line " +
                              std::to_string(it->second));
    table.set(entry);
    return {};
}

}  // namespace

const ToolTableEntry* ToolTable::find(int number) const
{
    const auto it = m_tools.find(number);
    return it == m_tools.end() ? nullptr : &it->second;
}

std::optional<double> ToolTable::radiusOf(int number) const
{
    const ToolTableEntry* entry = find(number);
    return entry ? std::optional<double>(entry->diameterMm / 2) : std::nullopt;
}

base::Result<ToolTable> parseToolTable(std::string_view text, const std::string& fileName)
{
    ToolTable table;
    std::map<int, int> lineOfTool;
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        ++lineNumber;
        LineReader reader{text.substr(start, end - start), 0, fileName, lineNumber};
        if (auto status = parseLine(reader, table, lineOfTool); !status)
            return status.error();
        if (end == text.size())
            break;
        start = end + 1;
    }
    return table;
}

base::Result<ToolTable> readToolTable(const std::string& path)
{
    auto text = base::readPlainTextFile(path);
    if (!text)
        return text.error();
    return parseToolTable(text.value(), path);
}

}  // namespace camwb::nc
