// Assignments of an ordinary SINUMERIK block: NAME=expr for addresses (X=AC(..), F=.., T="name",
// M=3), R parameters (Rn=, R[i]=) and DEF variables (v=, array[i]=).
#include "nc/sinumerik/ParserImpl.h"

#include <charconv>
#include <optional>

namespace camwb::nc::sinumerik {

bool Parser::parseAddressValue(Block& block, WordKind kind, std::uint8_t index, const Token& name, bool allowMode)
{
    Word w;
    w.kind = kind;
    w.index = index;
    w.pos = posOf(name);
    if (allowMode && peekIs(Tok::Name) && peekIs(Tok::LParen, 1)) {
        const std::string fn = upper(peek()->text);
        if (fn == "AC" || fn == "IC" || fn == "DC" || fn == "ACP" || fn == "ACN") {
            const bool rotary = kind == WordKind::Axis && index >= 3;
            w.mode = fn == "IC"              ? ValueMode::Incremental
                     : rotary && fn == "DC"  ? ValueMode::Shortest
                     : rotary && fn == "ACP" ? ValueMode::Positive
                     : rotary && fn == "ACN" ? ValueMode::Negative
                                             : ValueMode::Absolute;
            const Pos open = posOf(*peek(1));
            m_pos += 2;
            w.expr = parseExpr();
            if (w.expr < 0)
                return false;
            if (!peekIs(Tok::RParen))
                return error(atEnd() ? here() : posOf(*peek()),
                             "unbalanced parentheses: '(' at column " + std::to_string(open.column) + " is not closed");
            ++m_pos;
            addWord(block, kind, w.pos) = w;
            return true;
        }
    }
    if (atEnd())
        return error(here(), "a value is missing after " + std::string(name.text) + "=");
    w.expr = parseExpr();
    if (w.expr < 0)
        return false;
    addWord(block, kind, w.pos) = w;
    return true;
}

// NAME=expr: an address with an expression (X=AC(..), F=.., T="name", M=3) or an assignment to an
// R parameter or a DEF variable. At the name; `u` is its upper-case spelling.
bool Parser::parseAssignment(Block& block, const Token& t, const std::string& u)
{
    const Pos pos = posOf(t);
    const int axis = axisIndex(u);
    const int centre = centreIndex(u);
    m_pos += 2;
    if (axis >= 0)
        return parseAddressValue(block, WordKind::Axis, static_cast<std::uint8_t>(axis), t, true);
    if (centre >= 0)
        return parseAddressValue(block, WordKind::Centre, static_cast<std::uint8_t>(centre), t, true);
    if (u == "F")
        return parseAddressValue(block, WordKind::F, 0, t, false);
    if (u == "S" || (u.size() > 1 && u[0] == 'S' && u.find_first_not_of("0123456789", 1) == std::string::npos))
        return parseAddressValue(block, WordKind::S, 0, t, false);
    if (u == "D")
        return parseAddressValue(block, WordKind::D, 0, t, false);
    if (u == "T") {
        if (peekIs(Tok::String)) {
            Word& w = addWord(block, WordKind::TName, pos);
            w.code = addText(peek()->text);
            ++m_pos;
            return true;
        }
        return parseAddressValue(block, WordKind::T, 0, t, false);
    }
    if (u == "CR")
        return parseAddressValue(block, WordKind::Cr, 0, t, false);
    if (u == "AR")
        return parseAddressValue(block, WordKind::Ar, 0, t, false);
    if (u == "TURN")
        return parseAddressValue(block, WordKind::Turn, 0, t, false);
    if (u == "LIMS")
        return parseAddressValue(block, WordKind::Lims, 0, t, false);
    if (u[0] == 'M' && (u.size() == 1 || u.find_first_not_of("0123456789", 1) == std::string::npos)) {
        // M=3 or M1=3 (spindle 1): the code must be a constant.
        const std::int32_t e = parseExpr();
        if (e < 0)
            return false;
        if (m_p.exprs[e].op != Op::Const)
            return error(pos, "the M code must be a number");
        addWord(block, WordKind::M, pos).code = static_cast<std::int32_t>(m_p.exprs[e].value);
        return true;
    }
    if (u.size() > 1 && u[0] == 'R' && u.find_first_not_of("0123456789", 1) == std::string::npos)
        return parseRAssignment(block, t, u);
    if (const LocalVar* var = findLocal(u)) {
        if (var->size > 1)
            return error(pos, std::string(t.text) + " is an array: an element [i] is expected");
        Word w;
        w.kind = WordKind::Assign;
        w.target = AssignTarget::Local;
        w.code = var->slot;
        w.pos = pos;
        if (atEnd())
            return error(here(), "a value is missing after " + std::string(t.text) + "=");
        w.expr = parseExpr();
        if (w.expr < 0)
            return false;
        addWord(block, WordKind::Assign, pos) = w;
        return true;
    }
    if (u == "X1" || u == "Y1" || u == "Z1")
        return parseAddressValue(block, WordKind::MachineAxis, static_cast<std::uint8_t>(u[0] - 'X'), t, false);
    if (u == "A3" || u == "B3" || u == "C3")
        return parseAddressValue(block, WordKind::ToolVector, static_cast<std::uint8_t>(u[0] - 'A'), t, false);
    if (isPassiveKeyword(u) || u == "A2" || u == "B2" || u == "C2" || u == "LEAD" || u == "TILT" || u == "THETA" ||
        u == "SF" || u == "OVR" || u == "FP") {
        const std::int32_t e = parseExpr();
        if (e < 0)
            return false;
        addWord(block, WordKind::Passive, pos);
        return true;
    }
    return error(pos, "unknown address or variable " + std::string(t.text));
}

// Rn=expr, after the '='.
bool Parser::parseRAssignment(Block& block, const Token& t, const std::string& u)
{
    const Pos pos = posOf(t);
    int index = 0;
    std::from_chars(u.data() + 1, u.data() + u.size(), index);
    if (index > 999 || u.size() > 5)
        return error(pos, "R parameter " + u + " out of range (R0..R999)");
    if (atEnd())
        return error(here(), "a value is missing after " + std::string(t.text) + "=");
    Word w;
    w.kind = WordKind::Assign;
    w.target = AssignTarget::R;
    w.code = index;
    w.pos = pos;
    w.expr = parseExpr();
    if (w.expr < 0)
        return false;
    addWord(block, WordKind::Assign, pos) = w;
    return true;
}

// The "=expr" after an indexed target, and the word into the block.
bool Parser::finishIndexedAssignment(Block& block, Word& w)
{
    if (!peekIs(Tok::Assign))
        return error(here(), "'=' expected");
    ++m_pos;
    w.expr = parseExpr();
    if (w.expr < 0)
        return false;
    addWord(block, WordKind::Assign, w.pos) = w;
    return true;
}

// $TC_DPn[t, d]=expr: parameter n of cutting edge d of tool t (n = 6: the radius, 15: its wear).
bool Parser::parseToolDataAssignment(Block& block, const Token& t, const std::string& u)
{
    Word w;
    w.kind = WordKind::Assign;
    w.target = AssignTarget::ToolData;
    w.pos = posOf(t);
    std::from_chars(u.data() + 6, u.data() + u.size(), w.code);
    if (w.code < 1 || w.code > 25)
        return error(w.pos, u + ": tool offset parameters are $TC_DP1..$TC_DP25");
    m_pos += 2;
    w.expr2 = parseExpr();
    if (w.expr2 < 0)
        return false;
    if (!peekIs(Tok::Comma))
        return error(here(), "',' expected: " + u + "[tool, cutting edge]");
    ++m_pos;
    w.expr3 = parseExpr();
    if (w.expr3 < 0)
        return false;
    if (!peekIs(Tok::RBracket))
        return error(here(), "']' expected");
    ++m_pos;
    return finishIndexedAssignment(block, w);
}

// R[i]=expr, array[i]=expr and $TC_DPn[t,d]=expr; nullopt when the name is none of them.
std::optional<bool> Parser::parseIndexedAssignment(Block& block, const Token& t, const std::string& u)
{
    if (u.size() > 6 && u.compare(0, 6, "$TC_DP") == 0 && u.find_first_not_of("0123456789", 6) == std::string::npos)
        return parseToolDataAssignment(block, t, u);
    const LocalVar* var = findLocal(u);
    if (u != "R" && !var)
        return std::nullopt;
    ++m_pos;
    Word w;
    w.kind = WordKind::Assign;
    w.pos = posOf(t);
    if (var) {
        w.target = AssignTarget::Local;
        w.code = var->slot;
        w.arraySize = var->size;
        w.expr2 = parseElement(*var, 0);
    } else {
        w.target = AssignTarget::RIndirect;
        ++m_pos;
        w.expr2 = parseExpr();
        if (w.expr2 >= 0 && !peekIs(Tok::RBracket))
            return error(here(), "']' expected");
        ++m_pos;
    }
    if (w.expr2 < 0)
        return false;
    return finishIndexedAssignment(block, w);
}

}  // namespace camwb::nc::sinumerik
