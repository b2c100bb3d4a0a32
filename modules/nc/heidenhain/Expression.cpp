// Recursive-descent parser and evaluator of Klartext expressions (see Expression.h): depth and
// node count bounded so that hostile input cannot exhaust the stack.
#include "nc/heidenhain/Expression.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct FunctionName {
    std::string_view name;
    ExprOp op;
};
constexpr FunctionName kFunctions[] = {
    {"SIN", ExprOp::Sin},   {"COS", ExprOp::Cos},   {"TAN", ExprOp::Tan},   {"ASIN", ExprOp::Asin},
    {"ACOS", ExprOp::Acos}, {"ATAN", ExprOp::Atan}, {"SQRT", ExprOp::Sqrt}, {"SQ", ExprOp::Sq},
    {"ABS", ExprOp::Abs},   {"INT", ExprOp::Int},   {"FRAC", ExprOp::Frac}, {"SGN", ExprOp::Sgn},
    {"LN", ExprOp::Ln},     {"LOG", ExprOp::Log},   {"EXP", ExprOp::Exp},
};

class ExprParser {
public:
    ExprParser(Cursor& cursor, ParseEnv& env) : m_c(cursor), m_env(env) {}

    int expression()
    {
        int left = term();
        while (left >= 0) {
            m_c.skipSpace();
            const char ch = m_c.peek();
            if (ch != '+' && ch != '-')
                break;
            const int line = m_c.line(), column = m_c.column();
            m_c.advance();
            const int right = term();
            if (right < 0)
                return -1;
            left = node(ch == '+' ? ExprOp::Add : ExprOp::Sub, 0, left, right, line, column);
        }
        return left;
    }

    int value()
    {
        m_c.skipSpace();
        const int line = m_c.line(), column = m_c.column();
        const char ch = m_c.peek();
        bool negative = false;
        if (ch == '+' || ch == '-') {
            negative = ch == '-';
            const char next = m_c.peek(1);
            if (!isDigit(next) && next != '.' && upper(next) != 'Q' && next != '(')
                return -1;
            if (isDigit(next) || next == '.')
                return number(line, column);
            m_c.advance();
        }
        int v = -1;
        if (m_c.peek() == '(') {
            v = parenthesised();
        } else if (upper(m_c.peek()) == 'Q') {
            v = parameter();
        } else if (isDigit(m_c.peek()) || m_c.peek() == '.') {
            v = number(line, column);
        } else {
            return -1;
        }
        if (v >= 0 && negative)
            v = node(ExprOp::Neg, 0, v, -1, line, column);
        return v;
    }

    bool failed = false;

private:
    int term()
    {
        int left = power();
        while (left >= 0) {
            m_c.skipSpace();
            const int line = m_c.line(), column = m_c.column();
            const char ch = m_c.peek();
            ExprOp op;
            if (ch == '*' || ch == '/') {
                op = ch == '*' ? ExprOp::Mul : ExprOp::Div;
                m_c.advance();
            } else if (m_c.keyword("DIV")) {
                op = ExprOp::Div;
            } else if (m_c.keyword("LEN")) {
                op = ExprOp::Len;
            } else if (m_c.keyword("ANG")) {
                op = ExprOp::Ang;
            } else {
                break;
            }
            const int right = power();
            if (right < 0)
                return -1;
            left = node(op, 0, left, right, line, column);
        }
        return left;
    }

    int power()
    {
        const int base = unary();
        if (base < 0)
            return -1;
        m_c.skipSpace();
        if (m_c.peek() != '^')
            return base;
        const int line = m_c.line(), column = m_c.column();
        m_c.advance();
        if (!enter())
            return -1;
        const int exponent = power();  // right associative
        --m_depth;
        if (exponent < 0)
            return -1;
        return node(ExprOp::Pow, 0, base, exponent, line, column);
    }

    int unary()
    {
        m_c.skipSpace();
        const int line = m_c.line(), column = m_c.column();
        const char ch = m_c.peek();
        if (ch == '+' || ch == '-') {
            if (isDigit(m_c.peek(1)) || m_c.peek(1) == '.')
                return number(line, column);
            m_c.advance();
            if (!enter())
                return -1;
            const int operand = unary();
            --m_depth;
            if (operand < 0)
                return -1;
            return ch == '-' ? node(ExprOp::Neg, 0, operand, -1, line, column) : operand;
        }
        return primary();
    }

    int primary()
    {
        m_c.skipSpace();
        const int line = m_c.line(), column = m_c.column();
        const char ch = m_c.peek();
        if (ch == '(')
            return parenthesised();
        if (isDigit(ch) || ch == '.')
            return number(line, column);
        if (upper(ch) == 'Q' && (isDigit(m_c.peek(1)) || upper(m_c.peek(1)) == 'L' || upper(m_c.peek(1)) == 'R'))
            return parameter();
        if (isLetter(ch)) {
            const Cursor::Mark mark = m_c.mark();
            const std::string_view name = m_c.letters();
            if (equalsIgnoreCase(name, "PI"))
                return node(ExprOp::Const, std::numbers::pi, -1, -1, line, column);
            for (const FunctionName& f : kFunctions) {
                if (equalsIgnoreCase(name, f.name)) {
                    if (!enter())
                        return -1;
                    const int operand = unary();
                    --m_depth;
                    if (operand < 0) {
                        if (!failed)
                            error(m_c.line(), m_c.column(), "missing operand of " + std::string(f.name));
                        return -1;
                    }
                    return node(f.op, 0, operand, -1, line, column);
                }
            }
            m_c.reset(mark);
            error(line, column, "unknown word '" + std::string(name) + "' in an expression");
            return -1;
        }
        if (ch == '\0')
            error(line, column, "missing operand at the end of the expression");
        else
            error(line, column, std::string("unexpected '") + ch + "' in an expression");
        return -1;
    }

    int parenthesised()
    {
        const int line = m_c.line(), column = m_c.column();
        m_c.advance();  // '('
        if (!enter())
            return -1;
        const int inner = expression();
        --m_depth;
        if (inner < 0)
            return -1;
        m_c.skipSpace();
        if (m_c.peek() != ')') {
            error(line, column, "unbalanced parentheses: '(' is not closed");
            return -1;
        }
        m_c.advance();
        return inner;
    }

    int parameter()
    {
        const int line = m_c.line(), column = m_c.column();
        auto ref = parseParameter(m_c, m_env);
        if (!ref) {
            failed = true;
            return -1;
        }
        return node(ref->op, ref->number, -1, -1, line, column);
    }

    int number(int line, int column)
    {
        bool comma = false, range = false;
        auto v = m_c.number(&comma, &range);
        if (!v) {
            error(line, column, "number expected");
            return -1;
        }
        if (range)
            error(line, column, "number out of range");
        if (comma)
            m_env.reporter.report(Severity::Warning, m_env.file, line, column, "decimal comma read as a decimal point");
        return node(ExprOp::Const, *v, -1, -1, line, column);
    }

    bool enter()
    {
        if (++m_depth > kMaxExprDepth) {
            error(m_c.line(), m_c.column(), "expression nested too deeply");
            return false;
        }
        return true;
    }

    int node(ExprOp op, double value, int a, int b, int line, int column)
    {
        if (++m_nodes > kMaxExprNodes) {
            error(line, column, "expression too long");
            return -1;
        }
        m_env.program.exprs.push_back({op, value, a, b, line, column});
        return static_cast<int>(m_env.program.exprs.size()) - 1;
    }

    void error(int line, int column, std::string message)
    {
        if (failed)
            return;
        failed = true;
        m_env.reporter.report(Severity::Error, m_env.file, line, column, std::move(message));
    }

    Cursor& m_c;
    ParseEnv& m_env;
    int m_depth = 0;
    int m_nodes = 0;
};

}  // namespace

std::optional<ParamRef> parseParameter(Cursor& cursor, ParseEnv& env)
{
    const int line = cursor.line(), column = cursor.column();
    if (upper(cursor.peek()) != 'Q')
        return std::nullopt;
    ParamRef ref;
    int limit = kQCount;
    int skip = 1;
    if (upper(cursor.peek(1)) == 'L') {
        ref.op = ExprOp::QL;
        limit = kQLCount;
        skip = 2;
    } else if (upper(cursor.peek(1)) == 'R') {
        ref.op = ExprOp::QR;
        limit = kQRCount;
        skip = 2;
    }
    if (!isDigit(cursor.peek(skip)))
        return std::nullopt;
    cursor.advance(skip);
    const auto n = cursor.integer();
    if (!n || *n < 0 || *n >= limit) {
        env.reporter.report(Severity::Error, env.file, line, column,
                            "parameter number out of range (0.." + std::to_string(limit - 1) + ")");
        return std::nullopt;
    }
    ref.number = static_cast<int>(*n);
    return ref;
}

int parseExpression(Cursor& cursor, ParseEnv& env)
{
    ExprParser parser(cursor, env);
    const int e = parser.expression();
    return parser.failed ? -1 : e;
}

int parseValue(Cursor& cursor, ParseEnv& env, bool* reported)
{
    ExprParser parser(cursor, env);
    const int e = parser.value();
    if (reported)
        *reported = parser.failed;
    return parser.failed ? -1 : e;
}

int constantExpr(Program& program, double value, int line, int column)
{
    program.exprs.push_back({ExprOp::Const, value, -1, -1, line, column});
    return static_cast<int>(program.exprs.size()) - 1;
}

double& Parameters::at(ExprOp op, int number)
{
    if (op == ExprOp::QL)
        return ql[static_cast<std::size_t>(number)];
    if (op == ExprOp::QR)
        return qr[static_cast<std::size_t>(number)];
    return q[static_cast<std::size_t>(number)];
}

namespace {

class Evaluator {
public:
    Evaluator(const Program& program, Parameters& params, Reporter& reporter, const std::string& file) :
        m_p(program),
        m_params(params),
        m_r(reporter),
        m_file(file)
    {
    }

    double eval(int index)
    {
        if (m_failed || index < 0 || index >= static_cast<int>(m_p.exprs.size()))
            return fail(0, 0, "internal: bad expression");
        const Expr& e = m_p.exprs[static_cast<std::size_t>(index)];
        switch (e.op) {
        case ExprOp::Const:
            return e.value;
        case ExprOp::Q:
        case ExprOp::QL:
        case ExprOp::QR:
            return m_params.at(e.op, static_cast<int>(e.value));
        case ExprOp::Neg:
            return -eval(e.a);
        default:
            break;
        }
        const double a = eval(e.a);
        if (m_failed)
            return 0;
        double r = 0;
        switch (e.op) {
        case ExprOp::Add:
            r = a + eval(e.b);
            break;
        case ExprOp::Sub:
            r = a - eval(e.b);
            break;
        case ExprOp::Mul:
            r = a * eval(e.b);
            break;
        case ExprOp::Div: {
            const double b = eval(e.b);
            if (!m_failed && b == 0)
                return fail(e.line, e.column, "division by zero");
            r = a / b;
            break;
        }
        case ExprOp::Pow: {
            const double b = eval(e.b);
            if (!m_failed && a < 0 && b != std::floor(b))
                return fail(e.line, e.column, "negative base with a fractional exponent");
            r = std::pow(a, b);
            break;
        }
        case ExprOp::Len:
            r = std::hypot(a, eval(e.b));
            break;
        case ExprOp::Ang: {
            const double b = eval(e.b);
            r = std::atan2(b, a) / kDeg;
            if (r < 0)
                r += 360;
            break;
        }
        case ExprOp::Sin:
            r = std::sin(a * kDeg);
            break;
        case ExprOp::Cos:
            r = std::cos(a * kDeg);
            break;
        case ExprOp::Tan:
            if (std::abs(std::cos(a * kDeg)) < 1e-12)
                return fail(e.line, e.column, "TAN of an odd multiple of 90 degrees");
            r = std::tan(a * kDeg);
            break;
        case ExprOp::Asin:
        case ExprOp::Acos:
            if (a < -1 - 1e-12 || a > 1 + 1e-12)
                return fail(e.line, e.column, "ASIN/ACOS argument outside -1..1");
            r = (e.op == ExprOp::Asin ? std::asin(std::clamp(a, -1.0, 1.0)) : std::acos(std::clamp(a, -1.0, 1.0))) /
                kDeg;
            break;
        case ExprOp::Atan:
            r = std::atan(a) / kDeg;
            break;
        case ExprOp::Sqrt:
            if (a < 0)
                return fail(e.line, e.column, "square root of a negative value");
            r = std::sqrt(a);
            break;
        case ExprOp::Sq:
            r = a * a;
            break;
        case ExprOp::Abs:
            r = std::abs(a);
            break;
        case ExprOp::Int:
            r = std::trunc(a);
            break;
        case ExprOp::Frac:
            r = a - std::trunc(a);
            break;
        case ExprOp::Sgn:
            r = a > 0 ? 1 : (a < 0 ? -1 : 0);
            break;
        case ExprOp::Ln:
        case ExprOp::Log:
            if (a <= 0)
                return fail(e.line, e.column, "logarithm of a value <= 0");
            r = e.op == ExprOp::Ln ? std::log(a) : std::log10(a);
            break;
        case ExprOp::Exp:
            r = std::exp(a);
            break;
        default:
            return fail(e.line, e.column, "internal: unknown operator");
        }
        if (m_failed)
            return 0;
        if (!std::isfinite(r))
            return fail(e.line, e.column, "value out of range (not finite)");
        return r;
    }

    bool failed() const { return m_failed; }

private:
    double fail(int line, int column, const char* message)
    {
        if (!m_failed)
            m_r.report(Severity::Error, m_file, line, column, message);
        m_failed = true;
        return 0;
    }

    const Program& m_p;
    Parameters& m_params;
    Reporter& m_r;
    const std::string& m_file;
    bool m_failed = false;
};

}  // namespace

std::optional<double> evaluate(const Program& program, int expr, Parameters& params, Reporter& reporter,
                               const std::string& file)
{
    Evaluator ev(program, params, reporter, file);
    const double v = ev.eval(expr);
    if (ev.failed())
        return std::nullopt;
    return v;
}

}  // namespace camwb::nc::heidenhain
