// Expression evaluation: angles in degrees, ROUNDUP as the 840D manual's examples have it
// (ROUNDUP(3.1)=4, ROUNDUP(-3.1)=-3: the ceiling), comparisons and logic as 1/0. Division by
// zero, square roots of negatives and results that are not finite are errors, never NaN.
#include "nc/sinumerik/Machine.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::sinumerik {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// One-argument functions; false with `problem` set when the value has none.
bool applyFunction(Fn fn, double x, double& result, const char*& problem)
{
    switch (fn) {
    case Fn::Sin:
        result = std::sin(x * kDeg);
        return true;
    case Fn::Cos:
        result = std::cos(x * kDeg);
        return true;
    case Fn::Tan:
        if (std::abs(std::cos(x * kDeg)) < 1e-15)
            return false;  // the caller names the angle
        result = std::tan(x * kDeg);
        return true;
    case Fn::Asin:
        if (x < -1 || x > 1)
            return problem = "ASIN of a value outside -1..1", false;
        result = std::asin(x) / kDeg;
        return true;
    case Fn::Acos:
        if (x < -1 || x > 1)
            return problem = "ACOS of a value outside -1..1", false;
        result = std::acos(x) / kDeg;
        return true;
    case Fn::Sqrt:
        if (x < 0)
            return problem = "square root of a negative value (SQRT)", false;
        result = std::sqrt(x);
        return true;
    case Fn::Abs:
        result = std::abs(x);
        return true;
    case Fn::Pot:
        result = x * x;
        return true;
    case Fn::Round:
        result = std::round(x);
        return true;
    case Fn::RoundUp:
        result = std::ceil(x);
        return true;
    case Fn::Trunc:
        result = std::trunc(x);
        return true;
    case Fn::Ln:
        if (x <= 0)
            return problem = "LN of a value that is not positive", false;
        result = std::log(x);
        return true;
    case Fn::Exp:
        result = std::exp(x);
        return true;
    default:
        return problem = "function needs two arguments", false;
    }
}

// Two-argument functions (ATAN2, POT, MINVAL, MAXVAL).
bool applyFunction2(Fn fn, double x, double y, double& result, const char*& problem)
{
    switch (fn) {
    case Fn::Atan2:
        if (x == 0 && y == 0)
            return problem = "ATAN2 of (0, 0) has no angle", false;
        result = std::atan2(x, y) / kDeg;
        return true;
    case Fn::Pot:
        result = std::pow(x, y);
        return true;
    case Fn::MinVal:
        result = std::min(x, y);
        return true;
    case Fn::MaxVal:
        result = std::max(x, y);
        return true;
    default:
        return problem = "function takes one argument", false;
    }
}

// Arithmetic, comparisons (1/0) and logic of two operands.
bool applyOperator(const Expr& e, double x, double y, double& result, const char*& problem)
{
    switch (e.op) {
    case Op::Add:
        result = x + y;
        return true;
    case Op::Sub:
        result = x - y;
        return true;
    case Op::Mul:
        result = x * y;
        return true;
    case Op::Div:
        if (y == 0)
            return problem = "division by zero", false;
        result = x / y;
        return true;
    case Op::IntDiv:
        if (std::trunc(y) == 0)
            return problem = "division by zero (DIV)", false;
        result = std::trunc(std::trunc(x) / std::trunc(y));
        return true;
    case Op::Mod:
        if (y == 0)
            return problem = "division by zero (MOD)", false;
        result = std::fmod(x, y);
        return true;
    case Op::Eq:
        result = x == y;
        return true;
    case Op::Ne:
        result = x != y;
        return true;
    case Op::Lt:
        result = x < y;
        return true;
    case Op::Gt:
        result = x > y;
        return true;
    case Op::Le:
        result = x <= y;
        return true;
    case Op::Ge:
        result = x >= y;
        return true;
    case Op::And:
        result = (x != 0) && (y != 0);
        return true;
    case Op::Or:
        result = (x != 0) || (y != 0);
        return true;
    case Op::Xor:
        result = (x != 0) != (y != 0);
        return true;
    case Op::Call2:
        return applyFunction2(e.fn, x, y, result, problem);
    default:
        return problem = "invalid expression", false;
    }
}

}  // namespace

std::optional<double> Machine::evalFailure(const Program& p, const Expr& e, const std::string& message)
{
    error(p, e.pos, message);
    m_evalFailed = true;
    return std::nullopt;
}

// Leaves: constants, R parameters (direct or indirect), DEF variables and array elements.
std::optional<double> Machine::evalOperand(const Program& p, const Expr& e)
{
    switch (e.op) {
    case Op::Const:
        return e.value;
    case Op::RParam:
        return m_r[static_cast<std::size_t>(e.index)];
    case Op::RIndirect: {
        const auto i = eval(p, e.a);
        if (!i)
            return std::nullopt;
        if (!(*i >= 0 && *i < 1000))
            return evalFailure(p, e, "R parameter number out of range (R0..R999)");
        return m_r[static_cast<std::size_t>(*i)];
    }
    case Op::Local: {
        std::size_t slot = static_cast<std::size_t>(e.index);
        if (e.a >= 0) {
            const auto i = eval(p, e.a);
            if (!i)
                return std::nullopt;
            if (!(*i >= 0 && *i < e.arraySize))
                return evalFailure(p, e, "array index out of range");
            slot += static_cast<std::size_t>(*i);
        }
        return m_locals[m_stack.back().localsBase + slot];
    }
    default:  // Unknown, SysVar: reported by the parser
        return 0.0;
    }
}

std::optional<double> Machine::eval(const Program& p, std::int32_t index)
{
    if (index < 0)
        return std::nullopt;
    const Expr& e = p.exprs[static_cast<std::size_t>(index)];
    if (e.op <= Op::SysVar)
        return evalOperand(p, e);
    const auto a = eval(p, e.a);
    if (!a)
        return std::nullopt;
    double result = 0;
    const char* problem = nullptr;
    bool ok = true;
    if (e.op == Op::Neg) {
        result = -*a;
    } else if (e.op == Op::Not) {
        result = *a == 0 ? 1 : 0;
    } else if (e.op == Op::Call1) {
        ok = applyFunction(e.fn, *a, result, problem);
        if (!ok && !problem)
            return evalFailure(p, e, "TAN of " + std::to_string(*a) + " degrees is infinite");
    } else {
        const auto b = eval(p, e.b);
        if (!b)
            return std::nullopt;
        ok = applyOperator(e, *a, *b, result, problem);
    }
    if (!ok)
        return evalFailure(p, e, problem);
    if (!std::isfinite(result))
        return evalFailure(p, e, "the value is not finite (overflow)");
    return result;
}

}  // namespace camwb::nc::sinumerik
