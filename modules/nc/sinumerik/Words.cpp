// The words of an ordinary SINUMERIK block: G/M codes, axes and centres (X10, X=expr,
// X=IC(expr)), F S T D, CR AR TURN LIMS, assignments to R parameters and DEF variables, cycle
// and subprogram calls, keywords; plus DEF and PROC declarations.
#include "nc/sinumerik/ParserImpl.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace camwb::nc::sinumerik {

int axisIndex(std::string_view u)
{
    static constexpr std::string_view kAxes[] = {"X", "Y", "Z", "A", "B", "C"};
    for (int i = 0; i < 6; ++i)
        if (u == kAxes[i])
            return i;
    return -1;
}

int centreIndex(std::string_view u) { return u == "I" ? 0 : u == "J" ? 1 : u == "K" ? 2 : -1; }

bool isAddressLetter(std::string_view u)
{
    return u.size() == 1 && std::string_view("XYZABCIJKFSTDGMNHLP").find(u[0]) != std::string_view::npos;
}

// Words the trace recognises and leaves alone: path control, feed forward, compressors, display.
bool isPassiveKeyword(std::string_view u)
{
    static constexpr std::string_view kPassive[] = {
        "SOFT",    "BRISK",     "DRIVE",    "FFWON",   "FFWOF",   "CFC",      "CFTCP",     "CFIN",    "COMPON",
        "COMPOF",  "COMPCAD",   "COMPCURV", "ORIWKS",  "ORIMKS",  "ORIAXES",  "ORIVECT",   "UPATH",   "SPATH",
        "DISPLON", "DISPLOF",   "SBLON",    "SBLOF",   "WAITM",   "STOPFIFO", "STARTFIFO", "DIAM90",  "DIAMCYCOF",
        "CUT2D",   "CUT2DF",    "CUT3DC",   "CUT3DF",  "G_GROUP", "SPIF1",    "SPIF2",     "OFFN",    "NORM",
        "KONT",    "KONTC",     "KONTT",    "WALIMON", "WALIMOF", "PTP",      "CP",        "SPOS",    "SPOSA",
        "M19",     "FGROUP",    "FTOCON",   "FTOCOF",  "ACC",     "OVR",      "VELOLIM",   "JERKLIM", "CTAB",
        "DELT",    "WORKPIECE", "G_FNAME",  "FNORM",   "FLIN",    "FCUB",     "CPRECON",   "CPRECOF",
    };
    return std::find(std::begin(kPassive), std::end(kPassive), u) != std::end(kPassive);
}

bool isFrameKeyword(std::string_view u)
{
    return u == "TRANS" || u == "ATRANS" || u == "ROT" || u == "AROT" || u == "SCALE" || u == "ASCALE" ||
           u == "MIRROR" || u == "AMIRROR" || u == "ROTS" || u == "AROTS" || u == "CROTS";
}

double numberOf(std::string_view digits)
{
    double v = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec == std::errc::result_out_of_range)
        return 1e300;  // the range check reports it
    return v;
}

bool Parser::parseWords(Block& block)
{
    while (!atEnd() && !block.bad)
        if (!parseWord(block))
            return false;
    return !block.bad;
}

bool Parser::parseCallArgs(Block& block)
{
    // At '(' : arguments separated by commas, any of them empty.
    const Pos open = here();
    ++m_pos;
    block.firstArg = static_cast<std::int32_t>(m_p.args.size());
    block.argCount = 0;
    if (peekIs(Tok::RParen)) {
        ++m_pos;
        return true;
    }
    for (;;) {
        if (peekIs(Tok::Comma) || peekIs(Tok::RParen)) {
            m_p.args.push_back(-1);
        } else if (peekIs(Tok::String)) {
            m_p.args.push_back(-2);  // text arguments (CYCLE800's names): not used by the trace
            ++m_pos;
        } else {
            const std::int32_t e = parseExpr();
            if (e < 0)
                return false;
            m_p.args.push_back(e);
        }
        ++block.argCount;
        if (peekIs(Tok::Comma)) {
            ++m_pos;
            continue;
        }
        if (peekIs(Tok::RParen)) {
            ++m_pos;
            return true;
        }
        return error(atEnd() ? here() : posOf(*peek()),
                     "unbalanced parentheses: '(' at column " + std::to_string(open.column) + " is not closed");
    }
}

// Words written without spaces (G1X10Y20, as some posts and hand edits do): each a single
// address letter and its number; a last letter without a number takes a signed number after it.
bool Parser::parseGlued(Block& block, const Token& t, const std::string& u)
{
    static constexpr std::string_view kLetters = "GMXYZABCIJKFSTD";
    std::size_t i = 0;
    struct Piece {
        char letter;
        std::string_view digits;
    };
    std::vector<Piece> pieces;
    while (i < u.size()) {
        if (kLetters.find(u[i]) == std::string_view::npos)
            return false;
        std::size_t j = i + 1;
        while (j < u.size() && ((u[j] >= '0' && u[j] <= '9') || u[j] == '.'))
            ++j;
        if (j == i + 1 && j < u.size())
            return false;
        pieces.push_back({u[i], std::string_view(u).substr(i + 1, j - i - 1)});
        i = j;
    }
    if (pieces.size() < 2)
        return false;
    const bool trailingSign = pieces.back().digits.empty();
    if (trailingSign && !((peekIs(Tok::Minus, 1) || peekIs(Tok::Plus, 1)) && peekIs(Tok::Number, 2)))
        return false;
    const Pos pos = posOf(t);
    for (const Piece& piece : pieces) {
        const std::string_view letter(&piece.letter, 1);
        double value = numberOf(piece.digits);
        if (piece.digits.empty()) {
            value = peekIs(Tok::Minus, 1) ? -peek(2)->number : peek(2)->number;
            m_pos += 2;
        }
        if (piece.letter == 'G' || piece.letter == 'M') {
            // The range first: converting a double beyond int's range is undefined.
            if (!(value >= -9999 && value <= 9999) || value != std::trunc(value))
                return error(pos, "invalid " + std::string(letter) + " code in " + std::string(t.text));
            addWord(block, piece.letter == 'G' ? WordKind::G : WordKind::M, pos).code = static_cast<int>(value);
            if (piece.letter == 'M' && value == 6)
                m_p.hasM6 = true;
            continue;
        }
        const int ax = axisIndex(letter), ce = centreIndex(letter);
        Word& w = addWord(block,
                          ax >= 0               ? WordKind::Axis
                          : ce >= 0             ? WordKind::Centre
                          : piece.letter == 'F' ? WordKind::F
                          : piece.letter == 'S' ? WordKind::S
                          : piece.letter == 'T' ? WordKind::T
                                                : WordKind::D,
                          pos);
        w.index = static_cast<std::uint8_t>(ax >= 0 ? ax : ce >= 0 ? ce : 0);
        w.value = value;
    }
    ++m_pos;
    return true;
}

// A letter with its number after a sign or a space: X-10, X .5, G 1.
bool Parser::parseSpacedAddress(Block& block, const Token& t)
{
    const Pos pos = posOf(t);
    const std::string u = upper(t.text);
    const int axis = axisIndex(u);
    const int centre = centreIndex(u);
    if (!isAddressLetter(u) || u == "N" || u == "H" || u == "P" || u == "L")
        return error(pos, "unknown word " + std::string(t.text));
    ++m_pos;
    const bool minus = peekIs(Tok::Minus);
    if (!peekIs(Tok::Number))
        ++m_pos;
    const double v = minus ? -peek()->number : peek()->number;
    ++m_pos;
    if (u == "G" || u == "M") {
        if (v != static_cast<int>(v) || v < 0 || v > 9999)
            return error(pos, "invalid " + u + " code");
        addWord(block, u == "G" ? WordKind::G : WordKind::M, pos).code = static_cast<int>(v);
        if (u == "M" && v == 6)
            m_p.hasM6 = true;
        return true;
    }
    Word& w = addWord(block,
                      axis >= 0     ? WordKind::Axis
                      : centre >= 0 ? WordKind::Centre
                      : u == "F"    ? WordKind::F
                      : u == "S"    ? WordKind::S
                      : u == "T"    ? WordKind::T
                                    : WordKind::D,
                      pos);
    w.index = static_cast<std::uint8_t>(axis >= 0 ? axis : centre >= 0 ? centre : 0);
    w.value = v;
    return true;
}

bool Parser::badToken(const Token& t)
{
    const Pos pos = posOf(t);
    if (t.kind == Tok::RParen)
        return error(pos, "unbalanced parentheses: ')' without '('");
    if (t.kind == Tok::Number) {
        // X1.2.3 lexes as X1.2 and .3: one malformed number, not a stray one.
        const Token* before = m_pos > 0 ? &m_tokens[m_pos - 1] : nullptr;
        if (before && !t.spaceBefore && before->line == t.line &&
            (before->kind == Tok::Number || before->kind == Tok::Name))
            return error(posOf(*before), "malformed number " + std::string(before->text) + std::string(t.text));
        return error(pos, "a number without an address letter");
    }
    if (t.kind == Tok::Invalid)
        return error(pos, "unexpected character '" + std::string(t.text) + "'");
    return error(pos, "unexpected '" + std::string(t.text) + "'");
}

// The common case: one address letter and a number (X10.5, G1, M3), nothing after it that makes
// it an assignment, call or array. nullopt: not such a word.
std::optional<bool> Parser::parseNumberWord(Block& block, const Token& t)
{
    if (t.text.size() < 2 || !(t.text[1] == '.' || (t.text[1] >= '0' && t.text[1] <= '9')) || peekIs(Tok::Assign, 1) ||
        peekIs(Tok::LParen, 1) || peekIs(Tok::LBracket, 1))
        return std::nullopt;
    const Pos pos = posOf(t);
    char letter = t.text[0];
    if (letter >= 'a' && letter <= 'z')
        letter = static_cast<char>(letter - 'a' + 'A');
    const std::string_view digits = t.text.substr(1);
    const bool number = digits.find_first_not_of("0123456789.") == std::string_view::npos &&
                        std::count(digits.begin(), digits.end(), '.') <= 1 && digits != ".";
    const int ax = axisIndex(std::string_view(&letter, 1));
    const int ce = centreIndex(std::string_view(&letter, 1));
    if (number && (ax >= 0 || ce >= 0 || letter == 'F' || letter == 'S')) {
        ++m_pos;
        Word& w = addWord(block,
                          ax >= 0         ? WordKind::Axis
                          : ce >= 0       ? WordKind::Centre
                          : letter == 'F' ? WordKind::F
                                          : WordKind::S,
                          pos);
        w.index = static_cast<std::uint8_t>(ax >= 0 ? ax : ce >= 0 ? ce : 0);
        w.value = numberOf(digits);
        return true;
    }
    if (number && (letter == 'G' || letter == 'M') && digits.size() <= 4 &&
        digits.find('.') == std::string_view::npos) {
        ++m_pos;
        int code = 0;
        std::from_chars(digits.data(), digits.data() + digits.size(), code);
        addWord(block, letter == 'G' ? WordKind::G : WordKind::M, pos).code = code;
        if (letter == 'M' && code == 6)
            m_p.hasM6 = true;
        return true;
    }
    return std::nullopt;
}

// NAME( : cycles, MSG, keywords with arguments, subprogram calls with arguments.
bool Parser::parseCallWord(Block& block, const Token& t, const std::string& u)
{
    const Pos pos = posOf(t);
    ++m_pos;
    if (axisIndex(u) >= 0 || centreIndex(u) >= 0 || isAddressLetter(u))
        return error(posOf(*peek()), "'=' missing before the expression of " + std::string(t.text) + " (write " +
                                         std::string(t.text) + "=(...))");
    if (u == "MSG")
        return parseMsg(block, pos);
    const bool cycle =
        u.size() > 5 && u.compare(0, 5, "CYCLE") == 0 && u.find_first_not_of("0123456789", 5) == std::string::npos;
    if (block.callWord >= 0)
        return error(pos, "one cycle or subprogram call per block");
    block.callWord = static_cast<std::int32_t>(m_p.words.size());
    Word& w = addWord(block, WordKind::Call, pos);
    w.code = addText(u);
    if (cycle) {
        int number = 0;
        std::from_chars(u.data() + 5, u.data() + u.size(), number);
        w.kind = number == 800 ? WordKind::Keyword : WordKind::Cycle;
        w.code = number == 800 ? static_cast<std::int32_t>(Keyword::Cycle800) : number;
    } else if (u == "SETAL") {
        w.kind = WordKind::Keyword;
        w.code = static_cast<std::int32_t>(Keyword::SetAl);
    } else if (u == "TRAORI" || u == "TRAFOOF" || isPassiveKeyword(u) || u == "ORIRESET" || u == "TRANSMIT" ||
               u == "TRACYL") {
        w.kind = u == "TRAORI" ? WordKind::Keyword : WordKind::Passive;
        w.code = static_cast<std::int32_t>(Keyword::TraOri);
        block.callWord = -1;
    } else {
        block.text = w.code;
    }
    const WordKind kind = w.kind;
    if (!parseCallArgs(block))
        return false;
    if (kind == WordKind::Call && peekIs(Tok::Name))  // NAME(args) P3: repetitions
        parseRepetitions(block);
    return true;
}

// MSG("text") / MSG(): at '('.
bool Parser::parseMsg(Block& block, Pos pos)
{
    const Pos open = here();
    ++m_pos;
    Word& w = addWord(block, WordKind::Msg, pos);
    w.code = -1;
    if (peekIs(Tok::String)) {
        w.code = addText(peek()->text);
        ++m_pos;
    }
    if (!peekIs(Tok::RParen))
        return error(atEnd() ? here() : posOf(*peek()),
                     "MSG takes one text: '(' at column " + std::to_string(open.column) + " is not closed");
    ++m_pos;
    return true;
}

// P<n> after a call; false (nothing taken) when the next token is not one.
bool Parser::parseRepetitions(Block& block)
{
    const std::string p = upper(peek()->text);
    std::string_view l, d;
    if (!splitAddress(p, l, d) || l != "P" || d.find('.') != std::string_view::npos)
        return false;
    block.expr2 = constant(numberOf(d), posOf(*peek()));
    ++m_pos;
    return true;
}

// Keywords on their own (DIAMON, RET, ...), frames and passive words; nullopt: not a keyword.
std::optional<bool> Parser::parseKeyword(Block& block, const Token& t, const std::string& u)
{
    const Pos pos = posOf(t);
    if (u == "DIAMON" || u == "DIAMOF" || u == "TRAORI" || u == "TRAFOOF" || u == "RET" || u == "STOPRE" ||
        u == "SUPA") {
        const Keyword k = u == "DIAMON"    ? Keyword::DiamOn
                          : u == "DIAMOF"  ? Keyword::DiamOf
                          : u == "TRAORI"  ? Keyword::TraOri
                          : u == "TRAFOOF" ? Keyword::TraFoof
                          : u == "RET"     ? Keyword::Ret
                          : u == "SUPA"    ? Keyword::Supa
                                           : Keyword::Stopre;
        addWord(block, WordKind::Keyword, pos).code = static_cast<std::int32_t>(k);
        ++m_pos;
        return true;
    }
    if (isFrameKeyword(u)) {
        // Programmable frames: kept as pass-through text with a warning (the trace stays in the
        // programmed frame, as the CL the post wrote it from).
        const Token& last = m_tokens[m_end - 1];
        Word& w = addWord(block, WordKind::Keyword, pos);
        w.code = static_cast<std::int32_t>(Keyword::Frame);
        if (last.line == t.line)
            block.text = addText(std::string_view(t.text.data(), last.text.data() + last.text.size() - t.text.data()));
        else
            block.text = addText(t.text);
        m_pos = m_end;
        return true;
    }
    if (isPassiveKeyword(u)) {
        addWord(block, WordKind::Passive, pos);
        ++m_pos;
        return true;
    }
    return std::nullopt;
}

// Letters and a number in one name (T3, D1, H2, N20, L123 ...); nullopt: a name to be called.
std::optional<bool> Parser::parseAddress(Block& block, const Token& t, const std::string& u, std::string_view letters,
                                         std::string_view digits)
{
    const Pos pos = posOf(t);
    const int ax = axisIndex(letters);
    const int ce = centreIndex(letters);
    const bool integral = digits.find('.') == std::string_view::npos;
    if (letters == "G" || letters == "M") {
        ++m_pos;
        if (!integral || digits.size() > 4)
            return error(pos, "invalid " + std::string(letters) + " code " + std::string(t.text));
        int code = 0;
        std::from_chars(digits.data(), digits.data() + digits.size(), code);
        addWord(block, letters == "G" ? WordKind::G : WordKind::M, pos).code = code;
        if (letters == "M" && code == 6)
            m_p.hasM6 = true;
        return true;
    }
    WordKind kind = WordKind::Passive;
    std::uint8_t index = 0;
    if (ax >= 0) {
        kind = WordKind::Axis;
        index = static_cast<std::uint8_t>(ax);
    } else if (ce >= 0) {
        kind = WordKind::Centre;
        index = static_cast<std::uint8_t>(ce);
    } else if (letters == "F") {
        kind = WordKind::F;
    } else if (letters == "S") {
        kind = WordKind::S;
    } else if (letters == "T") {
        kind = WordKind::T;
    } else if (letters == "D") {
        kind = WordKind::D;
    } else if (letters == "H") {
        kind = WordKind::Passive;
    } else if (letters == "N") {
        ++m_pos;
        return true;  // a block number inside the block: ignored
    } else if (letters == "R") {
        ++m_pos;
        return error(pos, u + " needs '=' (" + u + "=value)");
    } else if (letters == "P" && integral) {
        ++m_pos;
        return error(pos, "P (repetitions) belongs after a subprogram name");
    } else {
        return std::nullopt;  // L123 or a name with digits: a subprogram call
    }
    ++m_pos;
    Word& w = addWord(block, kind, pos);
    w.index = index;
    w.value = numberOf(digits);
    return true;
}

// A name on its own (optionally with P repetitions) calls a subprogram.
bool Parser::parseNameCall(Block& block, const Token& t, const std::string& u)
{
    const Pos pos = posOf(t);
    if (block.wordCount == 0 && block.callWord < 0 && u.size() <= 31 &&
        (m_pos + 1 == m_end || (m_pos + 2 <= m_end && peek(1)->kind == Tok::Name && peek(1)->text.size() > 1 &&
                                (peek(1)->text[0] == 'P' || peek(1)->text[0] == 'p')))) {
        block.callWord = static_cast<std::int32_t>(m_p.words.size());
        Word& w = addWord(block, WordKind::Call, pos);
        w.code = addText(u);
        block.text = w.code;
        ++m_pos;
        if (!atEnd() && !parseRepetitions(block))
            return error(posOf(*peek()), "unexpected " + std::string(peek()->text) + " after the call");
        return true;
    }
    if (isAddressLetter(u) && u != "L" && u != "P")
        return error(pos, std::string(t.text) + " needs a value (" + std::string(t.text) + "10 or " +
                              std::string(t.text) + "=expression)");
    std::string message = "unknown word " + std::string(t.text);
    if (u.size() >= 2 && u[0] == 'G' && u.find_first_not_of("O", 1) == std::string::npos)
        message += " (the letter O where G0 has a zero?)";
    return error(pos, message);
}

bool Parser::parseWord(Block& block)
{
    const Token& t = *peek();
    if (t.kind != Tok::Name)
        return badToken(t);
    if (const auto done = parseNumberWord(block, t))
        return *done;
    if (t.text.size() == 1 &&
        (peekIs(Tok::Number, 1) || ((peekIs(Tok::Minus, 1) || peekIs(Tok::Plus, 1)) && peekIs(Tok::Number, 2))))
        return parseSpacedAddress(block, t);
    const std::string u = upper(t.text);
    if (peekIs(Tok::Assign, 1))
        return parseAssignment(block, t, u);
    if (peekIs(Tok::LBracket, 1))
        if (const auto done = parseIndexedAssignment(block, t, u))
            return *done;
    if (peekIs(Tok::LParen, 1))
        return parseCallWord(block, t, u);
    if (const auto done = parseKeyword(block, t, u))
        return *done;
    std::string_view letters, digits;
    if (splitAddress(u, letters, digits)) {
        if (const auto done = parseAddress(block, t, u, letters, digits))
            return *done;
    } else if (parseGlued(block, t, u)) {
        return true;
    }
    return parseNameCall(block, t, u);
}

}  // namespace camwb::nc::sinumerik
