#include "toolpath/FreeCadDumpScanner.h"

namespace camwb::toolpath {

namespace {

bool startsCommand(std::string_view line)
{
    return line.substr(0, 7) == "Command" && (line.size() == 7 || isSpace(line[7]) || line[7] == '[');
}

class Scanner {
public:
    Scanner(const std::vector<std::string_view>& lines, const ClBuilder& out) : m_lines(lines), m_out(out) {}

    base::Result<std::vector<DumpEntry>> run()
    {
        std::vector<DumpEntry> entries;
        while (m_next < m_lines.size()) {
            const std::string_view raw = m_lines[m_next];
            const int lineNumber = static_cast<int>(++m_next);
            const std::size_t indent = leadingSpaces(raw);
            const std::string_view line = trimRight(raw.substr(indent));
            if (line.empty())
                continue;
            const int column = static_cast<int>(indent) + 1;
            base::Result<DumpEntry> entry =
                startsCommand(line) ? command(line, lineNumber, column)
                : line[0] == '('
                    ? note(line, lineNumber, column)
                    : base::Result<DumpEntry>(m_out.error("expected a 'Command' or a '(' line", lineNumber, column));
            if (!entry)
                return entry.error();
            entries.push_back(std::move(entry).value());
        }
        return entries;
    }

private:
    // "(text)", possibly wrapped: the text runs to the last ')' of the first line that has one.
    base::Result<DumpEntry> note(std::string_view line, int lineNumber, int column)
    {
        DumpEntry entry;
        entry.kind = DumpEntry::Kind::Note;
        entry.line = lineNumber;
        entry.namePos = {lineNumber, column + 1};
        std::string_view rest = line.substr(1);
        while (true) {
            const std::size_t close = rest.rfind(')');
            if (close != std::string_view::npos) {
                appendPiece(entry.name, rest.substr(0, close));
                return entry;
            }
            appendPiece(entry.name, rest);
            // A wrapped note goes on with plain text; a new Command or note means it never closed.
            if (m_next >= m_lines.size())
                return m_out.error("'(' without ')'", lineNumber, column);
            rest = trim(m_lines[m_next]);
            if (startsCommand(rest) || (!rest.empty() && rest[0] == '('))
                return m_out.error("'(' without ')'", lineNumber, column);
            ++m_next;
        }
    }

    static void appendPiece(std::string& text, std::string_view piece)
    {
        piece = trim(piece);
        if (!text.empty() && !piece.empty())
            text += ' ';
        text += piece;
    }

    base::Result<DumpEntry> command(std::string_view line, int lineNumber, int column)
    {
        DumpEntry entry;
        entry.line = lineNumber;
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
            entry.name = std::string(line.substr(p, close + 1 - p));
            p = close + 1;
        } else {
            const std::size_t start = p;
            while (p < line.size() && !isSpace(line[p]) && line[p] != '[')
                ++p;
            entry.name = std::string(line.substr(start, p - start));
        }
        while (p < line.size() && isSpace(line[p]))
            ++p;
        if (p >= line.size() || line[p] != '[')
            return m_out.error("expected '[' after the command name", at(p));
        const TextPos open = at(p);

        PositionedText parameters;
        std::string_view rest = line.substr(p + 1);
        int restLine = lineNumber;
        int restColumn = column + static_cast<int>(p) + 1;
        while (true) {
            const std::size_t close = rest.find(']');
            if (close != std::string_view::npos) {
                parameters.append(rest.substr(0, close), restLine, restColumn);
                const std::string_view after = rest.substr(close + 1);
                if (!trim(after).empty())
                    return m_out.error("unexpected text after ']'", restLine,
                                       restColumn + static_cast<int>(close + 1 + leadingSpaces(after)));
                break;
            }
            parameters.append(rest, restLine, restColumn);
            parameters.appendBreak();
            // The parameters wrap onto the next line, unless that line starts something new.
            if (m_next >= m_lines.size())
                return m_out.error("'[' without ']'", open);
            const std::string_view raw = m_lines[m_next];
            const std::size_t indent = leadingSpaces(raw);
            const std::string_view next = trimRight(raw.substr(indent));
            if (startsCommand(next) || (!next.empty() && next[0] == '('))
                return m_out.error("'[' without ']'", open);
            restLine = static_cast<int>(++m_next);
            restColumn = static_cast<int>(indent) + 1;
            rest = next;
        }
        auto parsed = this->parameters(parameters);
        if (!parsed)
            return parsed.error();
        entry.parameters = std::move(parsed).value();
        return entry;
    }

    base::Result<std::vector<DumpParameter>> parameters(const PositionedText& text)
    {
        std::vector<DumpParameter> out;
        const std::string& t = text.text();
        std::size_t i = 0;
        while (true) {
            while (i < t.size() && isSpace(t[i]))
                ++i;
            if (i >= t.size())
                return out;
            const std::size_t start = i;
            while (i < t.size() && !isSpace(t[i]))
                ++i;
            const std::string_view token = std::string_view(t).substr(start, i - start);
            const std::size_t colon = token.find(':');
            const char key = token.empty() ? 0 : token[0];
            const bool letter = (key >= 'A' && key <= 'Z') || (key >= 'a' && key <= 'z');
            if (colon != 1 || !letter)
                return m_out.error("malformed parameter '" + std::string(token) +
                                       "' (expected a letter, ':' and a number)",
                                   text.position(start));
            const auto value = parseNumber(token.substr(2));
            if (!value)
                return m_out.error("malformed number '" + std::string(token.substr(2)) + "'", text.position(start + 2));
            DumpParameter parameter{toUpper(std::string_view(&key, 1))[0], *value, text.position(start)};
            for (const DumpParameter& other : out) {
                if (other.key == parameter.key)
                    return m_out.error(std::string("parameter ") + parameter.key + " given twice", parameter.pos);
            }
            out.push_back(parameter);
        }
    }

    const std::vector<std::string_view>& m_lines;
    const ClBuilder& m_out;
    std::size_t m_next = 0;
};

}  // namespace

const DumpParameter* DumpEntry::find(char key) const
{
    for (const DumpParameter& p : parameters) {
        if (p.key == key)
            return &p;
    }
    return nullptr;
}

base::Result<std::vector<DumpEntry>> scanFreeCadDump(const std::vector<std::string_view>& lines, const ClBuilder& out)
{
    return Scanner(lines, out).run();
}

}  // namespace camwb::toolpath
