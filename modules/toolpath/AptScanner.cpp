#include "toolpath/AptScanner.h"

namespace camwb::toolpath {

namespace {

// Statements whose argument is free text: it is taken as it stands, `$` and `,` included.
constexpr std::string_view kTextKeywords[] = {"PPRINT", "PARTNO", "INSERT", "REMARK", "TPRINT"};

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordChar(char c) { return isLetter(c) || isDigit(c) || c == '_' || c == '-' || c == '.'; }
void fillRemark(AptUnit& unit, std::string_view afterMarker, int line, int column)
{
    unit.kind = AptUnit::Kind::Remark;
    unit.line = line;
    unit.start = {line, column - 2};
    unit.text.clear();
    unit.keyword.clear();
    unit.body.assign(trim(afterMarker));
    unit.bodyPos = {line, column + static_cast<int>(leadingSpaces(afterMarker))};
}

AptUnit remark(std::string_view afterMarker, int line, int column)
{
    AptUnit unit;
    fillRemark(unit, afterMarker, line, column);
    return unit;
}

// Recursive descent over the positioned argument text.
class ArgumentParser {
public:
    ArgumentParser(const PositionedText& args, const ClBuilder& out) : m_text(args.text()), m_args(args), m_out(out) {}

    base::Status list(bool nested, TextPos openParen, std::vector<AptItem>& items)
    {
        items.clear();
        skipSpaces();
        if (atEnd() && !nested)
            return {};
        if (nested && !atEnd() && m_text[m_i] == ')')
            return {};
        while (true) {
            if (auto status = item(items.emplace_back()); !status)
                return status;
            skipSpaces();
            if (atEnd()) {
                if (nested)
                    return m_out.error("'(' without ')'", openParen);
                return {};
            }
            const char c = m_text[m_i];
            if (c == ',') {
                ++m_i;
                continue;
            }
            if (c == ')') {
                if (nested)
                    return {};
                return m_out.error("')' without '('", here());
            }
            return m_out.error("expected ',' between values, found '" + std::string(1, c) + "'", here());
        }
    }

private:
    base::Status item(AptItem& out)
    {
        skipSpaces();
        if (atEnd() || m_text[m_i] == ',' || m_text[m_i] == ')')
            return m_out.error("missing value", here());
        const char c = m_text[m_i];
        out.pos = here();
        if (c == '(') {
            const TextPos open = here();
            ++m_i;
            skipSpaces();
            if (atEnd() || !isLetter(m_text[m_i]))
                return m_out.error("expected a geometry word such as CIRCLE after '('", here());
            out.kind = AptItem::Kind::Group;
            out.pos = here();
            out.word = word();
            skipSpaces();
            if (atEnd() || m_text[m_i] != '/')
                return m_out.error("expected '/' after " + out.word, here());
            ++m_i;
            if (auto inner = list(true, open, out.items); !inner)
                return inner;
            ++m_i;  // the ')' that list() stopped at
            return {};
        }
        if (isDigit(c) || c == '.' || c == '+' || c == '-') {
            const std::size_t start = m_i;
            while (!atEnd() && (isWordChar(m_text[m_i]) || m_text[m_i] == '+'))
                ++m_i;
            const std::string_view token = std::string_view(m_text).substr(start, m_i - start);
            const auto number = parseNumber(token);
            if (!number)
                return m_out.error("malformed number '" + std::string(token) + "'", out.pos);
            out.kind = AptItem::Kind::Number;
            out.number = *number;
            return {};
        }
        if (isLetter(c)) {
            out.kind = AptItem::Kind::Word;
            out.word = word();
            return {};
        }
        return m_out.error("unexpected character '" + std::string(1, c) + "'", here());
    }

    std::string word()
    {
        const std::size_t start = m_i;
        while (!atEnd() && isWordChar(m_text[m_i]))
            ++m_i;
        return toUpper(std::string_view(m_text).substr(start, m_i - start));
    }

    void skipSpaces()
    {
        while (!atEnd() && isSpace(m_text[m_i]))
            ++m_i;
    }
    bool atEnd() const { return m_i >= m_text.size(); }
    TextPos here() const { return m_args.position(m_i); }

    const std::string& m_text;
    const PositionedText& m_args;
    const ClBuilder& m_out;
    std::size_t m_i = 0;
};

}  // namespace

base::Result<std::optional<TextPos>> AptScanner::skipToEnd()
{
    std::optional<TextPos> first;
    while (const std::optional<std::string_view> line = m_lines.next()) {
        if (!first && !trim(*line).empty())
            first = TextPos{m_lines.lineNumber(), static_cast<int>(leadingSpaces(*line)) + 1};
    }
    if (m_lines.readError())
        return *m_lines.readError();
    return first;
}

base::Result<bool> AptScanner::next(AptUnit& unit)
{
    if (m_queuedNext < m_queued.size()) {
        unit = std::move(m_queued[m_queuedNext++]);
        if (m_queuedNext == m_queued.size()) {
            m_queued.clear();
            m_queuedNext = 0;
        }
        return true;
    }
    if (const std::optional<ContentLine> content = nextContentLine(m_lines)) {
        const auto [line, lineNumber, column] = *content;
        if (line.substr(0, 2) == "$$") {
            fillRemark(unit, line.substr(2), lineNumber, column + 2);
            return true;
        }
        for (const std::string_view keyword : kTextKeywords) {
            if (!startsWithNoCase(line, keyword))
                continue;
            if (line.size() > keyword.size() && line[keyword.size()] != '/' && !isSpace(line[keyword.size()]))
                continue;
            // "PPRINT/text", "PPRINT text" and Creo's "PARTNO / text" all carry just the text.
            std::string_view rest = line.substr(keyword.size());
            int bodyColumn = column + static_cast<int>(keyword.size());
            const std::size_t blanks = leadingSpaces(rest);
            if (blanks < rest.size() && rest[blanks] == '/') {
                rest.remove_prefix(blanks + 1);
                bodyColumn += static_cast<int>(blanks) + 1;
            }
            unit.kind = AptUnit::Kind::Text;
            unit.line = lineNumber;
            unit.start = {lineNumber, column};
            unit.text.clear();
            unit.keyword.assign(keyword);
            unit.body.assign(trim(rest));
            unit.bodyPos = {lineNumber, bodyColumn + static_cast<int>(leadingSpaces(rest))};
            return true;
        }
        if (auto status = statement(line, lineNumber, column, unit); !status)
            return status.error();
        return true;
    }
    if (m_lines.readError())
        return *m_lines.readError();
    return false;
}

base::Status AptScanner::statement(std::string_view line, int lineNumber, int firstColumn, AptUnit& unit)
{
    unit.kind = AptUnit::Kind::Statement;
    unit.line = lineNumber;
    unit.start = {lineNumber, firstColumn};
    unit.text.clear();
    unit.keyword.clear();
    unit.body.clear();
    std::string_view segment = line;
    int segmentLine = lineNumber;
    int segmentColumn = firstColumn;
    TextPos continuedAt;
    bool withDollar = false;
    while (true) {
        bool continues = false;
        while (true) {
            const std::size_t dollar = segment.find('$');
            if (dollar == std::string_view::npos) {
                unit.text.append(segment, segmentLine, segmentColumn);
                break;
            }
            unit.text.append(segment.substr(0, dollar), segmentLine, segmentColumn);
            if (dollar + 1 < segment.size() && segment[dollar + 1] == '$') {
                AptUnit trailing =
                    remark(segment.substr(dollar + 2), segmentLine, segmentColumn + static_cast<int>(dollar) + 2);
                if (!trailing.body.empty())
                    m_queued.push_back(std::move(trailing));
                break;
            }
            continuedAt = {segmentLine, segmentColumn + static_cast<int>(dollar)};
            withDollar = true;
            const std::string_view rest = segment.substr(dollar + 1);
            const std::string_view restTrimmed = trim(rest);
            if (restTrimmed.empty()) {
                continues = true;
                break;
            }
            if (restTrimmed.substr(0, 2) == "$$") {
                // "CIRCLE/...,$ $$ 1ST ORBIT" (Creo): continued, with a remark on the line.
                const std::size_t marker = dollar + 1 + rest.find("$$");
                AptUnit trailing =
                    remark(segment.substr(marker + 2), segmentLine, segmentColumn + static_cast<int>(marker) + 2);
                if (!trailing.body.empty())
                    m_queued.push_back(std::move(trailing));
                continues = true;
                break;
            }
            // Card-image APT ignores what follows a single '$'; listings reflowed for print (the
            // CATIA example in seed-004) put the next line there, and CAM output never writes
            // remarks after '$', so the text is kept and the reader is told.
            m_out.warn("text after '$' is read as the continuation of the statement (APT would ignore it)",
                       continuedAt);
            unit.text.appendBreak();
            segmentColumn += static_cast<int>(dollar) + 1;
            segment = rest;
        }
        if (!continues) {
            // No statement ends with a separator: the line break lost its '$' (printed listings).
            const std::string_view sofar = trimRight(unit.text.text());
            if (!sofar.empty() && sofar.back() == ',') {
                continuedAt = unit.text.position(sofar.size() - 1);
                withDollar = false;
                m_out.warn("the statement ends with ',' and continues on the next line without '$'", continuedAt);
                continues = true;
            }
        }
        if (!continues)
            break;
        bool found = false;
        while (const std::optional<ContentLine> content = nextContentLine(m_lines)) {
            if (content->text.substr(0, 2) == "$$") {
                AptUnit inner = remark(content->text.substr(2), content->number, content->column + 2);
                if (!inner.body.empty())
                    m_queued.push_back(std::move(inner));
                continue;
            }
            segment = content->text;
            segmentLine = content->number;
            segmentColumn = content->column;
            found = true;
            break;
        }
        if (!found)
            return m_out.error(withDollar ? "the statement is continued with '$' but the file ends"
                                          : "the statement ends with ',' but the file ends",
                               continuedAt);
        unit.text.appendBreak();
    }
    return {};
}

base::Status splitStatement(const AptUnit& unit, const ClBuilder& out, AptStatement& s)
{
    const std::string& t = unit.text.text();
    const std::size_t slash = t.find('/');
    const std::size_t majorEnd = slash == std::string::npos ? t.size() : slash;
    s.line = unit.line;
    s.words.clear();
    s.wordPos = {};
    s.hasSlash = false;
    s.argsPos = {};
    s.args.clear();
    s.pointLine = false;
    s.junkPos.reset();
    std::size_t i = 0;
    auto skipSpaces = [&] {
        while (i < majorEnd && isSpace(t[i]))
            ++i;
    };
    skipSpaces();
    if (i < t.size() && (isDigit(t[i]) || t[i] == '.' || t[i] == '+' || t[i] == '-')) {
        // More points of the GOTO before it (Creo writes "x, y, z" lines after a GOTO).
        s.pointLine = true;
        s.wordPos = unit.text.position(i);
        s.argsPos = s.wordPos;
        s.args = unit.text;
        return {};
    }
    while (true) {
        skipSpaces();
        if (i >= majorEnd || !isLetter(t[i])) {
            if (!s.words.empty() && slash == std::string::npos && i < majorEnd) {
                s.junkPos = unit.text.position(i);
                return {};
            }
            return out.error(s.words.empty() ? "expected a statement word" : "expected a word after ','",
                             unit.text.position(i));
        }
        if (s.words.empty())
            s.wordPos = unit.text.position(i);
        std::string word;
        while (i < majorEnd) {
            if (isWordChar(t[i])) {
                word.push_back(t[i++]);
                continue;
            }
            // "TOOL PATH": words separated by blanks form one major word.
            std::size_t j = i;
            while (j < majorEnd && isSpace(t[j]))
                ++j;
            if (j > i && j < majorEnd && isLetter(t[j])) {
                word.push_back(' ');
                i = j;
                continue;
            }
            break;
        }
        s.words.push_back(toUpper(word));
        skipSpaces();
        if (i >= majorEnd)
            break;
        if (t[i] == ',') {
            ++i;
            continue;
        }
        if (slash == std::string::npos) {
            s.junkPos = unit.text.position(i);
            return {};
        }
        return out.error("unexpected '" + std::string(1, t[i]) + "' before '/'", unit.text.position(i));
    }
    s.hasSlash = slash != std::string::npos;
    if (s.hasSlash) {
        s.argsPos = unit.text.position(slash + 1);
        unit.text.slice(slash + 1, t.size(), s.args);
    } else {
        s.argsPos = unit.text.position(t.size());
    }
    return {};
}

std::string describeItem(const AptItem& item)
{
    return item.kind == AptItem::Kind::Group ? "(" + item.word + "/...)" : item.word;
}

base::Status tokenizeArguments(const PositionedText& args, const ClBuilder& out, std::vector<AptItem>& items)
{
    ArgumentParser parser(args, out);
    return parser.list(false, {}, items);
}

}  // namespace camwb::toolpath
