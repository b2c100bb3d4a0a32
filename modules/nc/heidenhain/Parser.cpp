// Block kinds of Klartext: the keyword decides the kind, then words, labels, FN operands or cycle
// parameters are parsed into the program's pools. Unknown keywords are errors; recognised but
// untraced functions (FK, TCH PROBE, ...) are warnings and skipped.
#include "nc/heidenhain/Parser.h"

namespace camwb::nc::heidenhain {

namespace {

class BlockParser {
public:
    BlockParser(Program& program, Reporter& reporter) : m_p(program), m_env{program, reporter, program.path} {}

    void parse(Block& b, Cursor& c)
    {
        m_b = &b;
        m_c = &c;
        if (c.atEnd()) {
            b.kind = b.comment.empty() ? BlockKind::Empty : BlockKind::Comment;
            return;
        }
        b.line = c.line();
        b.column = c.column();
        if (c.peek() == '*') {
            // Structure item ("* - ROUGHING"): a comment for the trace.
            c.advance();
            c.skipSpace();
            if (c.peek() == '-')
                c.advance();
            c.skipSpace();
            b.kind = BlockKind::Comment;
            const std::string_view text = c.rest();
            if (b.comment.empty())
                b.comment = text;
            return;
        }
        if (c.peek() == '.' && c.peek(1) == '.' && c.peek(2) == '.') {
            b.kind = BlockKind::Elision;
            m_env.reporter.report(Severity::Warning, m_env.file, b.line, b.column,
                                  "lines left out here ('...'): the listing is a fragment");
            return;
        }
        const Cursor::Mark start = c.mark();
        const std::string_view word = c.letters();
        if (word.empty()) {
            const int line = c.line(), column = c.column();
            fail(line, column, "unknown word '" + std::string(c.token()) + "'");
            return;
        }
        dispatch(word, start);
    }

private:
    void dispatch(std::string_view w, Cursor::Mark start)
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        auto is = [&](std::string_view k) { return equalsIgnoreCase(w, k); };
        if (is("L"))
            return motion(BlockKind::Line, kAxes | kComp | kFeed | kMisc);
        if (is("LP"))
            return motion(BlockKind::LinePolar, kAxes | kPolar | kComp | kFeed | kMisc);
        if (is("LN"))
            return skipped("LN (a line with surface normal and tool vectors) is not traced", BlockKind::LineVector);
        if (is("CC"))
            return motion(BlockKind::CircleCenter, kAxes | kPolar);
        if (is("C"))
            return motion(BlockKind::Circle, kAxes | kDir | kComp | kFeed | kMisc);
        if (is("CR"))
            return motion(BlockKind::CircleRadius, kAxes | kRadius | kDir | kComp | kFeed | kMisc);
        if (is("CT"))
            return motion(BlockKind::CircleTangent, kAxes | kComp | kFeed | kMisc);
        if (is("CP"))
            return motion(BlockKind::CirclePolar, kAxes | kPolar | kDir | kComp | kFeed | kMisc);
        if (is("RND"))
            return motion(BlockKind::Round, kRadius | kFeed | kMisc);
        if (is("CHF")) {
            b.kind = BlockKind::Chamfer;
            const int line = c.line(), column = c.column();
            c.skipSpace();
            const int e = parseValue(c, m_env);
            if (e < 0)
                return fail(line, column, "CHF needs the chamfer length");
            m_p.words.push_back({Key::Len, e, 0, line, column});
            const int first = static_cast<int>(m_p.words.size()) - 1;
            parseWords(c, m_env, b, kFeed | kMisc);
            b.firstWord = first;
            ++b.wordCount;
            return;
        }
        if (is("APPR") || is("DEP")) {
            b.flag = is("DEP");
            c.skipSpace();
            c.letters();  // LT, LN, CT, LCT ...
            return motion(BlockKind::Approach, kAxes | kPolar | kRadius | kComp | kFeed | kMisc | kLenAngle);
        }
        if (is("LBL"))
            return label();
        if (is("CALL"))
            return call();
        if (is("FN"))
            return fn();
        if (is("Q") || is("QL") || is("QR") || is("QS")) {
            c.reset(start);
            return assignment();
        }
        if (is("M")) {
            c.reset(start);
            return motion(BlockKind::MOnly, kMisc | kFeed);
        }
        if (is("CYCL"))
            return cycle();
        if (is("TOOL")) {
            if (c.keyword("CALL"))
                return toolCall();
            if (c.keyword("DEF"))
                return toolDef();
            return fail(c.line(), c.column(), "TOOL must be followed by CALL or DEF");
        }
        if (is("BEGIN") || is("END")) {
            const bool begin = is("BEGIN");
            if (!c.keyword("PGM"))
                return fail(c.line(), c.column(), std::string(begin ? "BEGIN" : "END") + " must be followed by PGM");
            b.kind = begin ? BlockKind::BeginPgm : BlockKind::EndPgm;
            b.name = c.token();
            const std::string_view unit = c.token();
            if (equalsIgnoreCase(unit, "INCH"))
                b.flag = true;
            else if (!unit.empty() && !equalsIgnoreCase(unit, "MM"))
                m_env.reporter.report(Severity::Warning, m_env.file, b.line, 0,
                                      "unit '" + std::string(unit) + "' is neither MM nor INCH: MM assumed");
            return;
        }
        if (is("BLK")) {
            b.kind = BlockKind::BlkForm;
            return;  // stock for the control's graphics only
        }
        if (is("STOP"))
            return motion(BlockKind::Stop, kMisc);
        if (is("PLANE")) {
            b.kind = BlockKind::Plane;
            b.flag = c.keyword("RESET");
            if (!b.flag)
                b.name = c.letters();
            return parsePlaneWords(c, m_env, b);
        }
        if (is("FUNCTION")) {
            b.kind = BlockKind::Function;
            b.flag = c.keyword("RESET");
            b.name = c.token();
            if (!b.flag && equalsIgnoreCase(b.name, "TCPM"))
                tcpmOptions();
            return;
        }
        if (is("TCH"))
            return skipped("touch probe cycles are not traced", BlockKind::Skipped);
        if (is("FL") || is("FLT") || is("FC") || is("FCT") || is("FPOL") || is("FSELECT") || is("FK"))
            return skipped("FK free contour programming is not traced", BlockKind::Skipped);
        if (is("SPL"))
            return skipped("SPL spline blocks are not traced", BlockKind::Skipped);
        if (is("SEL") || is("DECLARE") || is("PATTERN") || is("SEQUENCE") || is("WAIT") || is("SYSCALL"))
            return skipped(std::string(w) + " is not traced", BlockKind::Skipped);
        c.reset(start);
        const int line = c.line(), column = c.column();
        fail(line, column, "unknown word '" + std::string(c.token()) + "'");
    }

    // FUNCTION TCPM F TCP|CONT AXIS POS|SPAT PATHCTRL AXIS|VECTOR [REFPNT TIP-TIP|TIP-CENTER|
    // CENTER-CENTER] (iTNC 530 User's Manual, "FUNCTION TCPM"): the choices as TcpmOption bits in b.a.
    void tcpmOptions()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        struct Choice {
            std::string_view word, first, second;
            int secondBit;
        };
        static constexpr Choice kChoices[] = {
            {"F", "TCP", "CONT", kTcpmFeedCont},
            {"AXIS", "POS", "SPAT", kTcpmAxisSpat},
            {"PATHCTRL", "AXIS", "VECTOR", kTcpmPathVector},
        };
        while (!c.atEnd()) {
            const int line = c.line(), column = c.column();
            const std::string_view word = c.token();
            bool known = false;
            for (const Choice& choice : kChoices) {
                if (!equalsIgnoreCase(word, choice.word))
                    continue;
                known = true;
                const int valueLine = c.line(), valueColumn = c.column();
                const std::string_view value = c.token();
                if (equalsIgnoreCase(value, choice.second))
                    b.a |= choice.secondBit;
                else if (!equalsIgnoreCase(value, choice.first))
                    return fail(valueLine, valueColumn,
                                std::string(choice.word) + " of FUNCTION TCPM is " + std::string(choice.first) +
                                    " or " + std::string(choice.second) + ", not '" + std::string(value) + "'");
            }
            if (!known && equalsIgnoreCase(word, "REFPNT")) {
                known = true;
                const int valueLine = c.line(), valueColumn = c.column();
                const std::string_view value = c.token();
                if (equalsIgnoreCase(value, "TIP-CENTER") || equalsIgnoreCase(value, "CENTER-CENTER"))
                    b.a |= kTcpmRefCenter;
                else if (!equalsIgnoreCase(value, "TIP-TIP"))
                    return fail(valueLine, valueColumn,
                                "REFPNT of FUNCTION TCPM is TIP-TIP, TIP-CENTER or CENTER-CENTER, not '" +
                                    std::string(value) + "'");
            }
            if (!known)
                return fail(line, column, "unknown word '" + std::string(word) + "' in FUNCTION TCPM");
        }
    }

    void motion(BlockKind kind, unsigned groups)
    {
        m_b->kind = kind;
        parseWords(*m_c, m_env, *m_b, groups);
    }

    void skipped(std::string message, BlockKind kind)
    {
        m_b->kind = kind;
        m_env.reporter.report(Severity::Warning, m_env.file, m_b->line, m_b->column, std::move(message));
    }

    void fail(int line, int column, std::string message)
    {
        m_b->kind = BlockKind::Invalid;
        m_env.reporter.report(Severity::Error, m_env.file, line, column, std::move(message));
    }

    // A label reference: number, "name", or a bare name.
    bool labelRef(std::string_view& ref, bool& isName)
    {
        Cursor& c = *m_c;
        c.skipSpace();
        const int line = c.line(), column = c.column();
        bool closed = true;
        if (auto q = c.quoted(&closed)) {
            if (!closed)
                m_env.reporter.report(Severity::Error, m_env.file, line, column, "unterminated label name");
            else if (q->empty())
                m_env.reporter.report(Severity::Error, m_env.file, line, column, "empty label name");
            ref = *q;
            isName = true;
            return !ref.empty();
        }
        if (isDigit(c.peek())) {
            const Cursor::Mark mark = c.mark();
            const auto n = c.integer();
            if (!n || *n < 0 || *n > 65535) {
                m_env.reporter.report(Severity::Error, m_env.file, line, column,
                                      "label number out of range (0..65535)");
                return false;
            }
            const Cursor::Mark end = c.mark();
            c.reset(mark);
            ref = c.token().substr(0, end.pos - mark.pos);
            c.reset(end);
            isName = false;
            return true;
        }
        ref = c.letters();
        isName = true;
        if (ref.empty()) {
            m_env.reporter.report(Severity::Error, m_env.file, line, column, "label number or name expected");
            return false;
        }
        return true;
    }

    void label()
    {
        Block& b = *m_b;
        b.kind = BlockKind::Label;
        bool isName = false;
        if (!labelRef(b.name, isName)) {
            b.kind = BlockKind::Invalid;
            return;
        }
        b.flag = isName;
        const std::string key = labelKey(b.name, isName);
        if (!isName && key == "N0")
            return;  // LBL 0 ends a subprogram, it is no jump target
        const int index = static_cast<int>(&b - m_p.blocks.data());
        if (!m_p.labels.emplace(key, index).second)
            m_env.reporter.report(Severity::Error, m_env.file, b.line, b.column,
                                  "label " + std::string(b.name) + " defined twice");
        trailing();
    }

    void call()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        if (c.keyword("LBL")) {
            b.kind = BlockKind::CallLabel;
            if (!labelRef(b.labelRef, b.labelRefIsName)) {
                b.kind = BlockKind::Invalid;
                return;
            }
            b.firstWord = static_cast<int>(m_p.words.size());
            if (c.keyword("REP")) {
                const int line = c.line(), column = c.column();
                c.skipSpace();
                const auto n = c.integer();
                if (!n || *n < 0 || *n > 65534) {
                    fail(line, column, "REP needs a repeat count (0..65534)");
                    return;
                }
                m_p.words.push_back({Key::Rep, -1, static_cast<int>(*n), line, column});
                b.wordCount = 1;
                if (c.peek() == '/') {  // REP2/2: the remaining count the control shows
                    c.advance();
                    c.integer();
                }
            }
            trailing();
            return;
        }
        if (c.keyword("PGM")) {
            b.kind = BlockKind::CallPgm;
            c.skipSpace();
            bool closed = true;
            if (auto q = c.quoted(&closed))
                b.name = *q;
            else
                b.name = c.token();
            if (b.name.empty())
                fail(c.line(), c.column(), "CALL PGM needs a program name");
            return;
        }
        if (c.keyword("SELECTED"))
            return skipped("CALL SELECTED PGM is not traced", BlockKind::Skipped);
        fail(c.line(), c.column(), "CALL must be followed by LBL or PGM");
    }

    void trailing()
    {
        if (!m_c->atEnd()) {
            const int line = m_c->line(), column = m_c->column();
            m_env.reporter.report(Severity::Error, m_env.file, line, column,
                                  "unknown word '" + std::string(m_c->token()) + "'");
        }
    }

    // Target "Qn =" of an assignment; false after an error.
    bool target()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        c.skipSpace();
        const int line = c.line(), column = c.column();
        if (upper(c.peek()) == 'Q' && upper(c.peek(1)) == 'S') {
            skipped("string parameters (QS) are not traced", BlockKind::Skipped);
            return false;
        }
        const auto ref = parseParameter(c, m_env);
        if (!ref) {
            fail(line, column, "parameter (Q, QL, QR) expected");
            return false;
        }
        b.a = static_cast<int>(ref->op);
        b.b = ref->number;
        c.skipSpace();
        if (c.peek() != '=') {
            fail(c.line(), c.column(), "missing '=' before the expression");
            return false;
        }
        c.advance();
        return true;
    }

    void assignment()
    {
        Block& b = *m_b;
        b.kind = BlockKind::FnAssign;
        if (!target())
            return;
        b.exprA = parseExpression(*m_c, m_env);
        if (b.exprA < 0) {
            b.kind = BlockKind::Invalid;
            return;
        }
        trailing();
    }

    void fn()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        c.skipSpace();
        const int line = c.line(), column = c.column();
        const auto n = c.integer();
        if (!n)
            return fail(line, column, "FN needs a function number");
        c.skipSpace();
        if (c.peek() == ':')
            c.advance();
        const auto number = *n;
        if (number <= 8 || number == 13) {
            b.kind = BlockKind::FnAssign;
            if (!target())
                return;
            b.exprA = parseExpression(c, m_env);
            if (b.exprA < 0) {
                b.kind = BlockKind::Invalid;
                return;
            }
            return trailing();
        }
        if (number >= 9 && number <= 12) {
            b.kind = BlockKind::FnJump;
            if (!c.keyword("IF"))
                return fail(c.line(), c.column(), "FN " + std::to_string(number) + " needs IF");
            b.exprA = parseExpression(c, m_env);
            if (b.exprA < 0)
                return void(b.kind = BlockKind::Invalid);
            static constexpr std::string_view kOps[] = {"EQU", "NE", "GT", "LT"};
            const std::string_view expected = kOps[number - 9];
            if (!c.keyword(expected))
                return fail(c.line(), c.column(), "FN " + std::to_string(number) + " needs " + std::string(expected));
            b.b = static_cast<int>(number - 9);
            b.exprB = parseExpression(c, m_env);
            if (b.exprB < 0)
                return void(b.kind = BlockKind::Invalid);
            if (!c.keyword("GOTO") || !c.keyword("LBL"))
                return fail(c.line(), c.column(), "GOTO LBL expected");
            if (!labelRef(b.labelRef, b.labelRefIsName))
                return void(b.kind = BlockKind::Invalid);
            return trailing();
        }
        if (number == 14) {
            b.kind = BlockKind::FnError;
            c.keyword("ERROR");
            c.skipSpace();
            if (c.peek() == '=')
                c.advance();
            b.exprA = parseExpression(c, m_env);
            return;
        }
        skipped("FN " + std::to_string(number) + " is not traced", BlockKind::Skipped);
    }

    void cycle()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        if (c.keyword("CALL")) {
            if (c.keyword("POS")) {
                b.kind = BlockKind::CycleCallPos;
                parseWords(c, m_env, b, kAxes | kFeed | kMisc);
                return;
            }
            b.kind = BlockKind::CycleCall;
            parseWords(c, m_env, b, kFeed | kMisc);
            return;
        }
        if (!c.keyword("DEF"))
            return fail(c.line(), c.column(), "CYCL must be followed by DEF or CALL");
        b.kind = BlockKind::CycleDef;
        c.skipSpace();
        const int line = c.line(), column = c.column();
        const auto major = c.integer();
        if (!major || *major < 0 || *major > 9999)
            return fail(line, column, "cycle number expected");
        b.a = static_cast<int>(*major);
        if (c.peek() == '.') {
            c.advance();
            const auto minor = c.integer();
            b.b = minor ? static_cast<int>(std::min<std::int64_t>(*minor, 99)) : 0;
        }
        if (b.a == 7 || b.a == 19) {
            if (b.b == 0)
                return;  // 7.0 DATUM SHIFT / 19.0 WORKING PLANE: the title
            c.skipSpace();
            if (c.peek() == '#') {
                skipped("datum tables (CYCL DEF 7.1 #n) are not traced", BlockKind::Skipped);
                return;
            }
            parseWords(c, m_env, b, kAxes);
            return;
        }
        if (b.a == 10) {
            // 10.1 ROT+30 (absolute) or IROT+30 (added to the last rotation).
            if (b.b == 0)
                return;  // 10.0 ROTATION: the title
            c.skipSpace();
            const int l = c.line(), col = c.column();
            const bool incremental = c.keyword("IROT");
            if (!incremental && !c.keyword("ROT"))
                return fail(l, col, "CYCL DEF 10.1 takes ROT or IROT and an angle");
            c.skipSpace();
            const int e = parseValue(c, m_env);
            if (e < 0)
                return fail(c.line(), c.column(), "the rotation angle expected");
            m_p.words.push_back({Key::Angle, e, incremental ? 1 : 0, l, col});
            b.firstWord = static_cast<int>(m_p.words.size()) - 1;
            b.wordCount = 1;
            return;
        }
        if (b.a == 9) {
            // 9.1 DWELL 1.5 (the label depends on the control's language): the last number counts.
            b.firstWord = static_cast<int>(m_p.words.size());
            while (!c.atEnd()) {
                const int l = c.line(), col = c.column();
                if (valueStartsHere()) {
                    const int e = parseValue(c, m_env);
                    if (e >= 0) {
                        m_p.words.push_back({Key::Len, e, 0, l, col});
                        b.wordCount = 1;
                        b.firstWord = static_cast<int>(m_p.words.size()) - 1;
                        continue;
                    }
                }
                c.token();
            }
            return;
        }
        // Title words, then "Qnnn=value" parameters (iTNC 530 indented or TNC 640 with `~`).
        b.firstWord = static_cast<int>(m_p.words.size());
        bool inParameters = false;
        while (!c.atEnd()) {
            const int l = c.line(), col = c.column();
            if (upper(c.peek()) == 'Q' && isDigit(c.peek(1))) {
                const Cursor::Mark mark = c.mark();
                const auto ref = parseParameter(c, m_env);
                c.skipSpace();
                if (ref && c.peek() == '=') {
                    c.advance();
                    inParameters = true;
                    c.skipSpace();
                    int e = -1;
                    int special = 0;
                    if (c.keyword("FMAX"))
                        special = 1;
                    else if (c.keyword("FAUTO"))
                        special = 2;
                    else
                        e = parseExpression(c, m_env);
                    // expr -2 = FMAX, -3 = FAUTO (feed parameters such as Q206=FMAX).
                    if (e >= 0 || special)
                        m_p.words.push_back({Key::QSet, special ? -1 - special : e, ref->number, l, col});
                    continue;
                }
                c.reset(mark);
            }
            const std::string_view t = c.token();
            if (inParameters)
                m_env.reporter.report(Severity::Error, m_env.file, l, col, "unknown word '" + std::string(t) + "'");
            else if (b.name.empty())
                b.name = t;
        }
        b.wordCount = static_cast<int>(m_p.words.size()) - b.firstWord;
    }

    bool valueStartsHere() const
    {
        const char ch = m_c->peek();
        return isDigit(ch) || ch == '+' || ch == '-' || ch == '.' || upper(ch) == 'Q';
    }

    void toolCall()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        b.kind = BlockKind::ToolCall;
        c.skipSpace();
        const int line = c.line(), column = c.column();
        bool closed = true;
        if (auto q = c.quoted(&closed)) {
            b.name = *q;
            b.a = -1;
        } else if (isDigit(c.peek()) || upper(c.peek()) == 'Q') {
            b.exprA = parseValue(c, m_env);
            if (b.exprA < 0)
                return fail(line, column, "tool number expected");
        } else {
            b.a = -2;  // no tool: a speed or feed change only
        }
        parseWords(c, m_env, b, kTool | kFeed);
    }

    void toolDef()
    {
        Cursor& c = *m_c;
        Block& b = *m_b;
        b.kind = BlockKind::ToolDef;
        c.skipSpace();
        bool closed = true;
        if (auto q = c.quoted(&closed)) {
            b.name = *q;
            b.a = -1;
        } else {
            b.exprA = parseValue(c, m_env);
        }
        parseWords(c, m_env, b, kToolDef);
    }

    Program& m_p;
    ParseEnv m_env;
    Block* m_b = nullptr;
    Cursor* m_c = nullptr;
};

}  // namespace

void parseProgram(Program& program, std::string_view text, Reporter& reporter)
{
    const std::vector<RawBlock> raws = splitBlocks(text, program.segments);
    program.blocks.resize(raws.size());
    BlockParser parser(program, reporter);
    std::int64_t previous = -1;
    int previousLine = 0;
    for (std::size_t i = 0; i < raws.size(); ++i) {
        const RawBlock& raw = raws[i];
        Block& b = program.blocks[i];
        b.line = raw.line;
        b.number = raw.number;
        b.comment = raw.comment;
        b.commentLine = raw.commentLine;
        if (raw.numberTooLong)
            reporter.report(Severity::Warning, program.path, raw.line, raw.numberColumn, "block number too long");
        if (raw.number >= 0) {
            if (previous >= 0 && raw.number <= previous)
                reporter.report(Severity::Warning, program.path, raw.line, raw.numberColumn,
                                "block number " + std::to_string(raw.number) + " out of order (" +
                                    std::to_string(previous) + " on line " + std::to_string(previousLine) + ")");
            previous = raw.number;
            previousLine = raw.line;
        }
        Cursor cursor(program.segments.data() + raw.firstSegment, raw.segmentCount);
        parser.parse(b, cursor);
        if (b.kind == BlockKind::BeginPgm && i == 0)
            program.inch = b.flag;
    }
}

}  // namespace camwb::nc::heidenhain
