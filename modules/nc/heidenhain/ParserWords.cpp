// Address words of Klartext blocks (`X+10`, `IPA-90`, `DR+`, `R0`, `RL`, `FMAX`, `F AUTO`, `M3`,
// `S(VC=200)`, `DL+0.1`), each with its own column, in the groups the block kind allows.
#include "nc/heidenhain/Parser.h"

namespace camwb::nc::heidenhain {

namespace {

struct AxisName {
    std::string_view name;
    Key key;
};
constexpr AxisName kAxisNames[] = {
    {"X", Key::X},   {"Y", Key::Y},   {"Z", Key::Z},   {"A", Key::A},   {"B", Key::B},   {"C", Key::C},
    {"U", Key::U},   {"V", Key::V},   {"W", Key::W},   {"IX", Key::IX}, {"IY", Key::IY}, {"IZ", Key::IZ},
    {"IA", Key::IA}, {"IB", Key::IB}, {"IC", Key::IC}, {"IU", Key::IU}, {"IV", Key::IV}, {"IW", Key::IW},
};
constexpr AxisName kPolarNames[] = {{"PR", Key::PR}, {"PA", Key::PA}, {"IPR", Key::IPR}, {"IPA", Key::IPA}};

bool valueStarts(char c) { return isDigit(c) || c == '+' || c == '-' || c == '.' || c == '(' || upper(c) == 'Q'; }

class WordParser {
public:
    WordParser(Cursor& cursor, ParseEnv& env, Block& block, unsigned groups) :
        m_c(cursor),
        m_env(env),
        m_block(block),
        m_groups(groups)
    {
    }

    void run()
    {
        m_block.firstWord = static_cast<int>(m_env.program.words.size());
        while (!m_c.atEnd()) {
            const int line = m_c.line(), column = m_c.column();
            const Cursor::Mark start = m_c.mark();
            const std::string_view name = m_c.letters();
            if (name.empty() || !(word(name, line, column) || parameterValued(name, start, line, column))) {
                m_c.reset(start);
                const std::string_view bad = m_c.token();
                error(line, column, "unknown word '" + std::string(bad) + "'");
            }
        }
        m_block.wordCount = static_cast<int>(m_env.program.words.size()) - m_block.firstWord;
        // A block with a word the control cannot read is not run at all: no axis moves on a guess.
        if (m_failed)
            m_block.kind = BlockKind::Invalid;
    }

private:
    bool has(unsigned group) const { return (m_groups & group) != 0; }

    void error(int line, int column, std::string message)
    {
        m_failed = true;
        m_env.reporter.report(Severity::Error, m_env.file, line, column, std::move(message));
    }

    void add(Key key, int expr, int param, int line, int column)
    {
        m_env.program.words.push_back({key, expr, param, line, column});
    }

    // A value right after the address; reports a missing or malformed one (X+ZZ, X1.2.3, X+-3).
    bool valued(Key key, std::string_view name, int line, int column, int param = 0)
    {
        const Cursor::Mark start = m_c.mark();
        const int valueColumn = m_c.column();
        bool reported = false;
        const int e = parseValue(m_c, m_env, &reported);
        const char next = m_c.peek();
        if (e >= 0 && !isDigit(next) && next != '.') {
            add(key, e, param, line, column);
            return true;
        }
        m_failed = true;
        if (!reported) {
            m_c.reset(start);
            const std::string_view text = m_c.token();
            if (text.empty() || !valueStarts(text.front()))
                error(line, column, "missing value after '" + std::string(name) + "'");
            else
                error(line, valueColumn,
                      "malformed number '" + std::string(text) + "' after '" + std::string(name) + "'");
        }
        skipToken();
        return true;
    }

    // An address run into its parameter without a sign, as the control writes FQ601 (= F+Q601):
    // the letters before Q, QL or QR are the address and the parameter is its value.
    bool parameterValued(std::string_view name, Cursor::Mark start, int line, int column)
    {
        for (std::string_view kind : {"QL", "QR", "Q"}) {
            if (name.size() <= kind.size() || !equalsIgnoreCase(name.substr(name.size() - kind.size()), kind))
                continue;
            const std::string_view address = name.substr(0, name.size() - kind.size());
            m_c.reset(start);
            m_c.advance(static_cast<int>(address.size()));
            if (word(address, line, column))
                return true;
        }
        return false;
    }

    void skipToken()
    {
        while (m_c.peek() != '\0' && m_c.peek() != ' ' && m_c.peek() != '\t')
            m_c.advance();
    }

    bool word(std::string_view name, int line, int column)
    {
        if (has(kAxes)) {
            for (const AxisName& a : kAxisNames) {
                if (equalsIgnoreCase(name, a.name)) {
                    if (has(kTool) && name.size() == 1 && !valueStarts(m_c.peek()))
                        break;  // tool axis of TOOL CALL
                    return valued(a.key, name, line, column);
                }
            }
        }
        if (has(kPolar)) {
            for (const AxisName& a : kPolarNames) {
                if (equalsIgnoreCase(name, a.name))
                    return valued(a.key, name, line, column);
            }
        }
        if (has(kComp) && (equalsIgnoreCase(name, "RL") || equalsIgnoreCase(name, "RR"))) {
            add(Key::Comp, -1, upper(name[1]) == 'L' ? 1 : 2, line, column);
            return true;
        }
        if (equalsIgnoreCase(name, "R")) {
            if (has(kComp) && m_c.peek() == '0' && !isDigit(m_c.peek(1)) && m_c.peek(1) != '.' && m_c.peek(1) != ',') {
                m_c.advance();
                add(Key::Comp, -1, 0, line, column);
                return true;
            }
            if (has(kRadius) || has(kToolDef))
                return valued(Key::Radius, name, line, column);
            return false;
        }
        if (equalsIgnoreCase(name, "DR")) {
            const char sign = m_c.peek();
            if (has(kDir) && (sign == '+' || sign == '-') && !valueStarts(m_c.peek(1))) {
                m_c.advance();
                add(Key::Direction, -1, sign == '+' ? 1 : -1, line, column);
                return true;
            }
            if (has(kTool)) {
                if (m_c.peek() == '2') {
                    m_c.advance();
                    return valued(Key::DeltaRadius2, "DR2", line, column);
                }
                return valued(Key::DeltaRadius, name, line, column);
            }
            if (has(kDir)) {
                error(line, column, "DR must be followed by + or -");
                skipToken();
                return true;
            }
            return false;
        }
        if (has(kFeed)) {
            if (equalsIgnoreCase(name, "F")) {
                if (valueStarts(m_c.peek()))
                    return valued(Key::Feed, name, line, column);
                const Cursor::Mark mark = m_c.mark();
                if (m_c.keyword("AUTO")) {
                    add(Key::FeedAuto, -1, 0, line, column);
                    return true;
                }
                m_c.reset(mark);
                if (m_c.keyword("MAX")) {
                    add(Key::FeedMax, -1, 0, line, column);
                    return true;
                }
                m_c.reset(mark);
                error(line, column, "missing value after 'F'");
                return true;
            }
            if (equalsIgnoreCase(name, "FMAX")) {
                add(Key::FeedMax, -1, 0, line, column);
                return true;
            }
            if (equalsIgnoreCase(name, "FAUTO")) {
                add(Key::FeedAuto, -1, 0, line, column);
                return true;
            }
            if (equalsIgnoreCase(name, "FU"))
                return valued(Key::FeedRev, name, line, column);
            if (equalsIgnoreCase(name, "FZ"))
                return valued(Key::FeedTooth, name, line, column);
            if (equalsIgnoreCase(name, "FT") || equalsIgnoreCase(name, "FMAXT")) {
                m_env.reporter.report(Severity::Warning, m_env.file, line, column,
                                      std::string(name) + " (feed as a time) is not traced: the modal feed is kept");
                if (valueStarts(m_c.peek()))
                    parseValue(m_c, m_env);
                return true;
            }
        }
        if (has(kMisc) && equalsIgnoreCase(name, "M")) {
            const auto n = m_c.integer();
            if (!n || *n < 0 || *n > 9999) {
                error(line, column, "M must be followed by a number");
                skipToken();
                return true;
            }
            add(Key::M, -1, static_cast<int>(*n), line, column);
            return true;
        }
        if (has(kMisc) && equalsIgnoreCase(name, "MB")) {
            if (m_c.keyword("MAX")) {
                add(Key::Mb, -1, 1, line, column);
                return true;
            }
            return valued(Key::Mb, name, line, column);
        }
        if (has(kTool)) {
            if (name.size() == 1 && (upper(name[0]) == 'X' || upper(name[0]) == 'Y' || upper(name[0]) == 'Z')) {
                add(Key::ToolAxis, -1, upper(name[0]), line, column);
                return true;
            }
            if (equalsIgnoreCase(name, "S")) {
                if (m_c.peek() == '(') {
                    // S(VC=200): cutting speed in m/min.
                    m_c.advance();
                    if (!m_c.keyword("VC")) {
                        error(line, column, "S( must hold VC=");
                        return true;
                    }
                    m_c.skipSpace();
                    if (m_c.peek() == '=')
                        m_c.advance();
                    m_c.skipSpace();
                    bool reported = false;
                    const int e = parseValue(m_c, m_env, &reported);
                    m_failed = m_failed || reported;
                    m_c.skipSpace();
                    if (m_c.peek() == ')')
                        m_c.advance();
                    else
                        error(line, column, "unbalanced parentheses: '(' is not closed");
                    if (e >= 0)
                        add(Key::SurfaceSpeed, e, 0, line, column);
                    return true;
                }
                return valued(Key::Speed, name, line, column);
            }
            if (equalsIgnoreCase(name, "DL"))
                return valued(Key::DeltaLength, name, line, column);
        }
        if (has(kToolDef) && equalsIgnoreCase(name, "L"))
            return valued(Key::Length, name, line, column);
        if (has(kLenAngle) && equalsIgnoreCase(name, "LEN"))
            return valued(Key::Len, name, line, column);
        if (has(kLenAngle) && equalsIgnoreCase(name, "CCA"))
            return valued(Key::Angle, name, line, column);
        return false;
    }

    Cursor& m_c;
    ParseEnv& m_env;
    Block& m_block;
    unsigned m_groups;
    bool m_failed = false;
};

}  // namespace

void parseWords(Cursor& cursor, ParseEnv& env, Block& block, unsigned groups)
{
    WordParser(cursor, env, block, groups).run();
}

}  // namespace camwb::nc::heidenhain
