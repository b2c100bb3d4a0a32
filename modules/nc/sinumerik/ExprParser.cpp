// Expressions of SINUMERIK blocks with the control's operator priorities (Programming Manual Job
// Planning, "Priority of operators"): NOT; * / DIV MOD; + -; AND; XOR; OR; then the comparisons
// == <> < > <= >= lowest, which is why conditions are written (a>b) AND (c<d).
#include "nc/sinumerik/ParserImpl.h"

#include <algorithm>
#include <charconv>

namespace camwb::nc::sinumerik {

namespace {

constexpr int kMaxDepth = 400;       // parser recursion (about 50 levels of parentheses)
constexpr int kMaxTreeDepth = 2000;  // operators chained in one expression

struct FnInfo {
    std::string_view name;
    Fn fn;
    int args;
};
constexpr FnInfo kFunctions[] = {
    {"SIN", Fn::Sin, 1},   {"COS", Fn::Cos, 1},     {"TAN", Fn::Tan, 1},         {"ASIN", Fn::Asin, 1},
    {"ACOS", Fn::Acos, 1}, {"ATAN2", Fn::Atan2, 2}, {"SQRT", Fn::Sqrt, 1},       {"ABS", Fn::Abs, 1},
    {"POT", Fn::Pot, 1},   {"ROUND", Fn::Round, 1}, {"ROUNDUP", Fn::RoundUp, 1}, {"TRUNC", Fn::Trunc, 1},
    {"LN", Fn::Ln, 1},     {"EXP", Fn::Exp, 1},     {"MINVAL", Fn::MinVal, 2},   {"MAXVAL", Fn::MaxVal, 2},
};

}  // namespace

std::int32_t Parser::node(Op op, Pos pos, std::int32_t a, std::int32_t b)
{
    Expr e;
    e.op = op;
    e.a = a;
    e.b = b;
    e.pos = pos;
    if (a >= 0)
        e.depth = m_p.exprs[a].depth + 1;
    if (b >= 0)
        e.depth = std::max(e.depth, m_p.exprs[b].depth + 1);
    m_p.exprs.push_back(e);
    return static_cast<std::int32_t>(m_p.exprs.size() - 1);
}

std::int32_t Parser::constant(double value, Pos pos)
{
    const std::int32_t i = node(Op::Const, pos);
    m_p.exprs[i].value = value;
    return i;
}

std::int32_t Parser::parseExpr(int depth) { return parseLevel(0, depth); }

// Levels: 0 comparisons, 1 OR, 2 XOR, 3 AND, 4 + -, 5 * / DIV MOD.
std::int32_t Parser::parseLevel(int level, int depth)
{
    if (depth > kMaxDepth) {
        error(here(), "expression nested too deeply");
        return -1;
    }
    if (level > 5)
        return parseUnary(depth + 1);
    std::int32_t left = parseLevel(level + 1, depth + 1);
    if (left < 0)
        return -1;
    for (;;) {
        const Token* t = peek();
        if (!t)
            return left;
        Op op = Op::Const;
        switch (level) {
        case 0:
            switch (t->kind) {
            case Tok::Eq:
                op = Op::Eq;
                break;
            case Tok::Ne:
                op = Op::Ne;
                break;
            case Tok::Lt:
                op = Op::Lt;
                break;
            case Tok::Gt:
                op = Op::Gt;
                break;
            case Tok::Le:
                op = Op::Le;
                break;
            case Tok::Ge:
                op = Op::Ge;
                break;
            default:
                break;
            }
            break;
        case 1:
            if (peekName("OR"))
                op = Op::Or;
            break;
        case 2:
            if (peekName("XOR"))
                op = Op::Xor;
            break;
        case 3:
            if (peekName("AND"))
                op = Op::And;
            break;
        case 4:
            if (t->kind == Tok::Plus)
                op = Op::Add;
            else if (t->kind == Tok::Minus)
                op = Op::Sub;
            break;
        case 5:
            if (t->kind == Tok::Star)
                op = Op::Mul;
            else if (t->kind == Tok::Slash)
                op = Op::Div;
            else if (peekName("DIV"))
                op = Op::IntDiv;
            else if (peekName("MOD"))
                op = Op::Mod;
            break;
        default:
            break;
        }
        if (op == Op::Const)
            return left;
        const Pos pos = posOf(*t);
        ++m_pos;
        if (atEnd())
            return error(pos, "the expression ends after '" + std::string(t->text) + "'"), -1;
        const std::int32_t right = parseLevel(level + 1, depth + 1);
        if (right < 0)
            return -1;
        left = node(op, pos, left, right);
        if (m_p.exprs[left].depth > kMaxTreeDepth)
            return error(pos, "expression too long"), -1;
    }
}

std::int32_t Parser::parseUnary(int depth)
{
    const Token* t = peek();
    if (!t) {
        error(here(), "an expression is missing");
        return -1;
    }
    // Before any recursion: a run of signs ("----1") recurses once per sign.
    if (depth > kMaxDepth) {
        error(posOf(*t), "expression nested too deeply");
        return -1;
    }
    if (t->kind == Tok::Minus || t->kind == Tok::Plus) {
        const bool minus = t->kind == Tok::Minus;
        const Pos pos = posOf(*t);
        ++m_pos;
        const std::int32_t operand = parseUnary(depth + 1);
        if (operand < 0)
            return -1;
        if (!minus)
            return operand;
        if (m_p.exprs[operand].op == Op::Const) {  // -10 stays a constant: the fast path for X-10
            m_p.exprs[operand].value = -m_p.exprs[operand].value;
            return operand;
        }
        return node(Op::Neg, pos, operand);
    }
    if (peekName("NOT")) {
        const Pos pos = posOf(*t);
        ++m_pos;
        const std::int32_t operand = parseUnary(depth + 1);
        return operand < 0 ? -1 : node(Op::Not, pos, operand);
    }
    return parsePrimary(depth + 1);
}

std::int32_t Parser::parsePrimary(int depth)
{
    const Token* t = peek();
    if (!t) {
        error(here(), "an expression is missing");
        return -1;
    }
    const Pos pos = posOf(*t);
    switch (t->kind) {
    case Tok::Number:
        ++m_pos;
        return constant(t->number, pos);
    case Tok::LParen: {
        ++m_pos;
        const std::int32_t inner = parseExpr(depth + 1);
        if (inner < 0)
            return -1;
        if (!peekIs(Tok::RParen)) {
            error(peek() ? posOf(*peek()) : here(),
                  "unbalanced parentheses: '(' at column " + std::to_string(pos.column) + " is not closed");
            return -1;
        }
        ++m_pos;
        return inner;
    }
    case Tok::Name:
        ++m_pos;
        return parseNameOperand(*t, depth);
    case Tok::RParen:
        error(pos, "unbalanced parentheses: ')' without '('");
        return -1;
    case Tok::String:
        error(pos, "a string is not a number");
        return -1;
    default:
        error(pos, "an expression is missing before '" + std::string(t->text) + "'");
        return -1;
    }
}

std::int32_t Parser::parseNameOperand(const Token& name, int depth)
{
    const Pos pos = posOf(name);
    std::string u = upper(name.text);
    if (u.size() > 1 && u[0] == '$') {
        // System variables ($AA_IW[X], $P_...): the trace has no machine state to read them from.
        if (peekIs(Tok::LBracket)) {
            int nesting = 0;
            while (!atEnd()) {
                const Tok k = peek()->kind;
                ++m_pos;
                if (k == Tok::LBracket)
                    ++nesting;
                if (k == Tok::RBracket && --nesting == 0)
                    break;
            }
        }
        warning(pos, "system variable " + std::string(name.text) + " is not known to the trace: read as 0");
        return node(Op::SysVar, pos);
    }
    if (u == "TRUE")
        return constant(1, pos);
    if (u == "FALSE")
        return constant(0, pos);
    if (u == "R" && peekIs(Tok::LBracket)) {
        ++m_pos;
        const std::int32_t index = parseExpr(depth + 1);
        if (index < 0)
            return -1;
        if (!peekIs(Tok::RBracket))
            return error(here(), "']' expected after the R parameter number"), -1;
        ++m_pos;
        return node(Op::RIndirect, pos, index);
    }
    if (const LocalVar* var = findLocal(u)) {
        if (var->size > 1 || peekIs(Tok::LBracket)) {
            const std::int32_t element = parseElement(*var, depth);
            if (element < 0)
                return -1;
            const std::int32_t n = node(Op::Local, pos, element);
            m_p.exprs[n].index = var->slot;
            m_p.exprs[n].arraySize = var->size;
            return n;
        }
        const std::int32_t n = node(Op::Local, pos);
        m_p.exprs[n].index = var->slot;
        return n;
    }
    if (u.size() > 1 && u[0] == 'R' && u.find_first_not_of("0123456789", 1) == std::string::npos) {
        int index = 0;
        std::from_chars(u.data() + 1, u.data() + u.size(), index);
        if (index > 999 || u.size() > 5)
            return error(pos, "R parameter " + u + " out of range (R0..R999)"), -1;
        const std::int32_t n = node(Op::RParam, pos);
        m_p.exprs[n].index = index;
        return n;
    }
    for (const FnInfo& f : kFunctions) {
        if (f.name != u)
            continue;
        if (!peekIs(Tok::LParen))
            return error(pos, "'(' expected after " + u), -1;
        const Pos open = posOf(*peek());
        ++m_pos;
        std::int32_t a = parseExpr(depth + 1);
        if (a < 0)
            return -1;
        std::int32_t b = -1;
        int args = 1;
        if (peekIs(Tok::Comma)) {
            ++m_pos;
            b = parseExpr(depth + 1);
            if (b < 0)
                return -1;
            ++args;
        }
        if (!peekIs(Tok::RParen))
            return error(peek() ? posOf(*peek()) : here(),
                         "unbalanced parentheses: '(' at column " + std::to_string(open.column) + " is not closed"),
                   -1;
        ++m_pos;
        const bool potPower = f.fn == Fn::Pot && args == 2;
        if (args != f.args && !potPower)
            return error(pos, u + " takes " + std::to_string(f.args) + " argument" + (f.args > 1 ? "s" : "")), -1;
        const std::int32_t n = node(args == 2 ? Op::Call2 : Op::Call1, pos, a, b);
        m_p.exprs[n].fn = f.fn;
        return n;
    }
    if (peekIs(Tok::Assign))
        return error(pos, "unknown variable " + std::string(name.text)), -1;
    return error(pos, "unknown name " + std::string(name.text) + " in an expression"), -1;
}

std::int32_t Parser::parseElement(const LocalVar& var, int depth)
{
    if (!peekIs(Tok::LBracket))
        return error(here(), "'[' expected: the variable is an array"), -1;
    ++m_pos;
    std::int32_t first = parseExpr(depth + 1);
    if (first < 0)
        return -1;
    if (var.dim2 > 0) {
        if (!peekIs(Tok::Comma))
            return error(here(), "two indices expected"), -1;
        ++m_pos;
        const std::int32_t second = parseExpr(depth + 1);
        if (second < 0)
            return -1;
        const std::int32_t scaled = node(Op::Mul, m_p.exprs[first].pos, first, constant(var.dim2, Pos{}));
        first = node(Op::Add, m_p.exprs[first].pos, scaled, second);
    }
    if (!peekIs(Tok::RBracket))
        return error(here(), "']' expected"), -1;
    ++m_pos;
    return first;
}

const LocalVar* Parser::findLocal(std::string_view upperName) const
{
    if (m_locals.empty())
        return nullptr;
    const auto it = m_locals.find(std::string(upperName));
    return it == m_locals.end() ? nullptr : &it->second;
}

}  // namespace camwb::nc::sinumerik
