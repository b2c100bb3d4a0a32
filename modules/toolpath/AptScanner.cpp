#include "toolpath/AptScanner.h"

namespace camwb::toolpath {

namespace {

// Statements whose argument is free text: it is taken as it stands, `$` and `,` included.
constexpr std::string_view kTextKeywords[] = {"PPRINT", "PARTNO", "INSERT", "REMARK", "TPRINT"};

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordChar(char c) { return isLetter(c) || isDigit(c) || c == '_' || c == '-' || c == '.'; }
AptUnit remark(std::string_view afterMarker, int line, int column)
{
    AptUnit unit;
    unit.kind = AptUnit::Kind::Remark;
    unit.line = line;
    unit.start = {line, column - 2};
    unit.body = std::string(trim(afterMarker));
    unit.bodyPos = {line, column + static_cast<int>(leadingSpaces(afterMarker))};
    return unit;
}

// Recursive descent over the positioned argument text.
class ArgumentParser {
public:
    ArgumentParser(const PositionedText& args, const ClBuilder& out) : m_text(args.text()), m_args(args), m_out(out) {}

    base::Result<std::vector<AptItem>> list(bool nested, TextPos openParen)
    {
        std::vector<AptItem> items;
        skipSpaces();
        if (atEnd() && !nested)
            return items;
        if (nested && !atEnd() && m_text[m_i] == ')')
            return items;
        while (true) {
            auto item = this->item();
            if (!item)
                return item.error();
            items.push_back(std::move(item).value());
            skipSpaces();
            if (atEnd()) {
                if (nested)
                    return m_out.error("'(' without ')'", openParen);
                return items;
            }
            const char c = m_text[m_i];
            if (c == ',') {
                ++m_i;
                continue;
            }
            if (c == ')') {
                if (nested)
                    return items;
                return m_out.error("')' without '('", here());
            }
            return m_out.error("expected ',' between values, found '" + std::string(1, c) + "'", here());
        }
    }

private:
    base::Result<AptItem> item()
    {
        skipSpaces();
        if (atEnd() || m_text[m_i] == ',' || m_text[m_i] == ')')
            return m_out.error("missing value", here());
        const char c = m_text[m_i];
        AptItem out;
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
            auto inner = list(true, open);
            if (!inner)
                return inner.error();
            out.items = std::move(inner).value();
            ++m_i;  // the ')' that list() stopped at
            return out;
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
            return out;
        }
        if (isLetter(c)) {
            out.kind = AptItem::Kind::Word;
            out.word = word();
            return out;
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

AptScanner::AptScanner(std::string_view text, ClBuilder& out) : m_lines(splitLines(text)), m_out(out) {}

std::optional<TextPos> AptScanner::nextText() const
{
    for (std::size_t i = m_next; i < m_lines.size(); ++i) {
        if (!trim(m_lines[i]).empty())
            return TextPos{static_cast<int>(i + 1), static_cast<int>(leadingSpaces(m_lines[i])) + 1};
    }
    return std::nullopt;
}

base::Result<std::optional<AptUnit>> AptScanner::next()
{
    if (!m_queued.empty()) {
        AptUnit unit = std::move(m_queued.front());
        m_queued.erase(m_queued.begin());
        return std::optional<AptUnit>(std::move(unit));
    }
    while (m_next < m_lines.size()) {
        const std::string_view raw = m_lines[m_next];
        const int lineNumber = static_cast<int>(++m_next);
        const std::size_t indent = leadingSpaces(raw);
        const std::string_view line = trimRight(raw.substr(indent));
        if (line.empty())
            continue;
        const int column = static_cast<int>(indent) + 1;
        if (line.substr(0, 2) == "$$")
            return std::optional<AptUnit>(remark(line.substr(2), lineNumber, column + 2));
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
            AptUnit unit;
            unit.kind = AptUnit::Kind::Text;
            unit.line = lineNumber;
            unit.start = {lineNumber, column};
            unit.keyword = std::string(keyword);
            unit.body = std::string(trim(rest));
            unit.bodyPos = {lineNumber, bodyColumn + static_cast<int>(leadingSpaces(rest))};
            return std::optional<AptUnit>(std::move(unit));
        }
        return statement(line, lineNumber, column);
    }
    return std::optional<AptUnit>();
}

base::Result<std::optional<AptUnit>> AptScanner::statement(std::string_view line, int lineNumber, int firstColumn)
{
    AptUnit unit;
    unit.line = lineNumber;
    unit.start = {lineNumber, firstColumn};
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
        while (m_next < m_lines.size()) {
            const std::string_view raw = m_lines[m_next];
            const int next = static_cast<int>(++m_next);
            const std::size_t indent = leadingSpaces(raw);
            const std::string_view content = trimRight(raw.substr(indent));
            if (content.empty())
                continue;
            if (content.substr(0, 2) == "$$") {
                AptUnit inner = remark(content.substr(2), next, static_cast<int>(indent) + 3);
                if (!inner.body.empty())
                    m_queued.push_back(std::move(inner));
                continue;
            }
            segment = content;
            segmentLine = next;
            segmentColumn = static_cast<int>(indent) + 1;
            found = true;
            break;
        }
        if (!found)
            return m_out.error(withDollar ? "the statement is continued with '$' but the file ends"
                                          : "the statement ends with ',' but the file ends",
                               continuedAt);
        unit.text.appendBreak();
    }
    return std::optional<AptUnit>(std::move(unit));
}

base::Result<AptStatement> splitStatement(const AptUnit& unit, const ClBuilder& out)
{
    const std::string& t = unit.text.text();
    const std::size_t slash = t.find('/');
    const std::size_t majorEnd = slash == std::string::npos ? t.size() : slash;
    AptStatement s;
    s.line = unit.line;
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
        return s;
    }
    while (true) {
        skipSpaces();
        if (i >= majorEnd || !isLetter(t[i])) {
            if (!s.words.empty() && slash == std::string::npos && i < majorEnd) {
                s.junkPos = unit.text.position(i);
                return s;
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
            return s;
        }
        return out.error("unexpected '" + std::string(1, t[i]) + "' before '/'", unit.text.position(i));
    }
    s.hasSlash = slash != std::string::npos;
    if (s.hasSlash) {
        s.argsPos = unit.text.position(slash + 1);
        s.args = unit.text.slice(slash + 1, t.size());
    } else {
        s.argsPos = unit.text.position(t.size());
    }
    return s;
}

std::string describeItem(const AptItem& item)
{
    return item.kind == AptItem::Kind::Group ? "(" + item.word + "/...)" : item.word;
}

base::Result<std::vector<AptItem>> tokenizeArguments(const PositionedText& args, const ClBuilder& out)
{
    ArgumentParser parser(args, out);
    return parser.list(false, {});
}

}  // namespace camwb::toolpath
