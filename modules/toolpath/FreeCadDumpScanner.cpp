#include "toolpath/FreeCadDumpScanner.h"

namespace camwb::toolpath {

namespace {

bool startsCommand(std::string_view line)
{
    return line.substr(0, 7) == "Command" && (line.size() == 7 || isSpace(line[7]) || line[7] == '[');
}

// A line that starts an entry of its own, so it cannot continue a wrapped one.
bool startsEntry(std::string_view trimmed) { return startsCommand(trimmed) || (!trimmed.empty() && trimmed[0] == '('); }

void appendPiece(std::string& text, std::string_view piece)
{
    piece = trim(piece);
    if (!text.empty() && !piece.empty())
        text += ' ';
    text += piece;
}

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

}  // namespace

void DumpEntry::clearParameters()
{
    for (const DumpParameter& p : parameters)
        m_index[static_cast<std::size_t>(p.key - 'A')] = -1;
    parameters.clear();
}

base::Result<bool> FreeCadDumpScanner::next(DumpEntry& entry)
{
    if (const std::optional<ContentLine> content = nextContentLine(m_lines)) {
        const auto [line, lineNumber, column] = *content;
        base::Status status = startsCommand(line) ? command(line, lineNumber, column, entry)
                              : line[0] == '('
                                  ? note(line, lineNumber, column, entry)
                                  : base::Status(m_out.error("expected a 'Command' or a '(' line", lineNumber, column));
        if (!status)
            return status.error();
        return true;
    }
    if (m_lines.readError())
        return *m_lines.readError();
    return false;
}

// "(text)", possibly wrapped: the text runs to the last ')' of the first line that has one.
base::Status FreeCadDumpScanner::note(std::string_view line, int lineNumber, int column, DumpEntry& entry)
{
    entry.kind = DumpEntry::Kind::Note;
    entry.line = lineNumber;
    entry.namePos = {lineNumber, column + 1};
    entry.name.clear();
    entry.clearParameters();
    std::string_view rest = line.substr(1);
    while (true) {
        const std::size_t close = rest.rfind(')');
        if (close != std::string_view::npos) {
            appendPiece(entry.name, rest.substr(0, close));
            return {};
        }
        appendPiece(entry.name, rest);
        // A wrapped note goes on with plain text; a new Command or note means it never closed.
        const std::optional<std::string_view> following = m_lines.peek();
        if (!following || startsEntry(trim(*following)))
            return m_out.error("'(' without ')'", lineNumber, column);
        rest = trim(*m_lines.next());
    }
}

base::Status FreeCadDumpScanner::command(std::string_view line, int lineNumber, int column, DumpEntry& entry)
{
    entry.kind = DumpEntry::Kind::Command;
    entry.line = lineNumber;
    entry.clearParameters();
    std::size_t p = 7;
    while (p < line.size() && isSpace(line[p]))
        ++p;
    auto at = [&](std::size_t index) { return TextPos{lineNumber, column + static_cast<int>(index)}; };
    entry.namePos = at(p);
    if (p < line.size() && line[p] == '(') {
        // A comment command: its text ends at the ')' that is followed by the '['.
        std::size_t close = p;
        while (true) {
            close = line.find(')', close + 1);
            if (close == std::string_view::npos)
                return m_out.error("'(' without ')'", entry.namePos);
            std::size_t q = close + 1;
            while (q < line.size() && isSpace(line[q]))
                ++q;
            if (q >= line.size() || line[q] == '[')
                break;
        }
        entry.name.assign(line.substr(p, close + 1 - p));
        p = close + 1;
    } else {
        const std::size_t start = p;
        while (p < line.size() && !isSpace(line[p]) && line[p] != '[')
            ++p;
        entry.name.assign(line.substr(start, p - start));
    }
    while (p < line.size() && isSpace(line[p]))
        ++p;
    if (p >= line.size() || line[p] != '[')
        return m_out.error("expected '[' after the command name", at(p));
    const TextPos open = at(p);

    std::string_view rest = line.substr(p + 1);
    int restLine = lineNumber;
    int restColumn = column + static_cast<int>(p) + 1;
    if (const std::size_t close = rest.find(']'); close != std::string_view::npos) {
        // On one line, as nearly every command is: read the parameters where they stand.
        const std::string_view after = rest.substr(close + 1);
        if (!trim(after).empty())
            return m_out.error("unexpected text after ']'", restLine,
                               restColumn + static_cast<int>(close + 1 + leadingSpaces(after)));
        return parameters(rest.substr(0, close), {nullptr, restLine, restColumn}, entry);
    }
    m_parameters.clear();
    while (true) {
        const std::size_t close = rest.find(']');
        if (close != std::string_view::npos) {
            m_parameters.append(rest.substr(0, close), restLine, restColumn);
            const std::string_view after = rest.substr(close + 1);
            if (!trim(after).empty())
                return m_out.error("unexpected text after ']'", restLine,
                                   restColumn + static_cast<int>(close + 1 + leadingSpaces(after)));
            break;
        }
        m_parameters.append(rest, restLine, restColumn);
        m_parameters.appendBreak();
        // The parameters wrap onto the next line, unless that line starts something new.
        const std::optional<std::string_view> following = m_lines.peek();
        if (!following || startsEntry(trim(*following)))
            return m_out.error("'[' without ']'", open);
        const std::string_view raw = *m_lines.next();
        const std::size_t indent = leadingSpaces(raw);
        restLine = m_lines.lineNumber();
        restColumn = static_cast<int>(indent) + 1;
        rest = trimRight(raw.substr(indent));
    }
    return parameters(m_parameters.text(), {&m_parameters, 0, 0}, entry);
}

base::Status FreeCadDumpScanner::parameters(std::string_view t, Where where, DumpEntry& entry)
{
    const std::size_t n = t.size();
    std::size_t i = 0;
    while (true) {
        while (i < n && isSpace(t[i]))
            ++i;
        if (i >= n)
            return {};
        const std::size_t start = i;
        auto token = [&] {
            std::size_t end = start;
            while (end < n && !isSpace(t[end]))
                ++end;
            return t.substr(start, end - start);
        };
        const char key = t[start];
        const bool letter = (key >= 'A' && key <= 'Z') || (key >= 'a' && key <= 'z');
        if (!letter || start + 1 >= n || t[start + 1] != ':')
            return m_out.error("malformed parameter '" + std::string(token()) +
                                   "' (expected a letter, ':' and a number)",
                               where(start));
        // The number as it is read, up to the blank after it; anything unusual the long way.
        std::size_t length = 0;
        std::optional<double> value = parseDecimalPrefix(t.substr(start + 2), length);
        i = start + 2 + length;
        if (!value || (i < n && !isSpace(t[i]))) {
            const std::string_view whole = token();
            i = start + whole.size();
            value = parseNumber(whole.substr(2));
            if (!value)
                return m_out.error("malformed number '" + std::string(whole.substr(2)) + "'", where(start + 2));
        }
        const DumpParameter parameter{upper(key), *value, where(start)};
        if (entry.find(parameter.key))
            return m_out.error(std::string("parameter ") + parameter.key + " given twice", parameter.pos);
        entry.add(parameter);
    }
}

}  // namespace camwb::toolpath
