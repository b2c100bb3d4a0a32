// Expression evaluation: angles in degrees, ROUNDUP as the 840D manual's examples have it
// (ROUNDUP(3.1)=4, ROUNDUP(-3.1)=-3: the ceiling), comparisons and logic as 1/0. Division by
// zero, square roots of negatives and results that are not finite are errors, never NaN.
#include "nc/sinumerik/Machine.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::sinumerik {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace

std::optional<double> Machine::eval(const Program& p, std::int32_t index)
{
    if (index < 0)
        return std::nullopt;
    const Expr& e = p.exprs[static_cast<std::size_t>(index)];
    auto fail = [&](const std::string& message) -> std::optional<double> {
        error(p, e.pos, message);
        m_evalFailed = true;
        return std::nullopt;
    };
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
            return fail("R parameter number out of range (R0..R999)");
        return m_r[static_cast<std::size_t>(*i)];
    }
    case Op::Local: {
        std::size_t slot = static_cast<std::size_t>(e.index);
        if (e.a >= 0) {
            const auto i = eval(p, e.a);
            if (!i)
                return std::nullopt;
            if (!(*i >= 0 && *i < e.arraySize))
                return fail("array index out of range");
            slot += static_cast<std::size_t>(*i);
        }
        return m_locals[m_stack.back().localsBase + slot];
    }
    case Op::Unknown:
    case Op::SysVar:
        return 0.0;
    default:
        break;
    }
    const auto a = eval(p, e.a);
    if (!a)
        return std::nullopt;
    double result = 0;
    if (e.op == Op::Neg) {
        result = -*a;
    } else if (e.op == Op::Not) {
        result = *a == 0 ? 1 : 0;
    } else if (e.op == Op::Call1) {
        const double x = *a;
        switch (e.fn) {
        case Fn::Sin:
            result = std::sin(x * kDeg);
            break;
        case Fn::Cos:
            result = std::cos(x * kDeg);
            break;
        case Fn::Tan:
            if (std::abs(std::cos(x * kDeg)) < 1e-15)
                return fail("TAN of " + std::to_string(x) + " degrees is infinite");
            result = std::tan(x * kDeg);
            break;
        case Fn::Asin:
            if (x < -1 || x > 1)
                return fail("ASIN of a value outside -1..1");
            result = std::asin(x) / kDeg;
            break;
        case Fn::Acos:
            if (x < -1 || x > 1)
                return fail("ACOS of a value outside -1..1");
            result = std::acos(x) / kDeg;
            break;
        case Fn::Sqrt:
            if (x < 0)
                return fail("square root of a negative value (SQRT)");
            result = std::sqrt(x);
            break;
        case Fn::Abs:
            result = std::abs(x);
            break;
        case Fn::Pot:
            result = x * x;
            break;
        case Fn::Round:
            result = std::round(x);
            break;
        case Fn::RoundUp:
            result = std::ceil(x);
            break;
        case Fn::Trunc:
            result = std::trunc(x);
            break;
        case Fn::Ln:
            if (x <= 0)
                return fail("LN of a value that is not positive");
            result = std::log(x);
            break;
        case Fn::Exp:
            result = std::exp(x);
            break;
        default:
            return fail("function needs two arguments");
        }
    } else {
        const auto b = eval(p, e.b);
        if (!b)
            return std::nullopt;
        const double x = *a, y = *b;
        switch (e.op) {
        case Op::Add:
            result = x + y;
            break;
        case Op::Sub:
            result = x - y;
            break;
        case Op::Mul:
            result = x * y;
            break;
        case Op::Div:
            if (y == 0)
                return fail("division by zero");
            result = x / y;
            break;
        case Op::IntDiv:
            if (std::trunc(y) == 0)
                return fail("division by zero (DIV)");
            result = std::trunc(std::trunc(x) / std::trunc(y));
            break;
        case Op::Mod:
            if (y == 0)
                return fail("division by zero (MOD)");
            result = std::fmod(x, y);
            break;
        case Op::Eq:
            result = x == y;
            break;
        case Op::Ne:
            result = x != y;
            break;
        case Op::Lt:
            result = x < y;
            break;
        case Op::Gt:
            result = x > y;
            break;
        case Op::Le:
            result = x <= y;
            break;
        case Op::Ge:
            result = x >= y;
            break;
        case Op::And:
            result = (x != 0) && (y != 0);
            break;
        case Op::Or:
            result = (x != 0) || (y != 0);
            break;
        case Op::Xor:
            result = (x != 0) != (y != 0);
            break;
        case Op::Call2:
            switch (e.fn) {
            case Fn::Atan2:
                if (x == 0 && y == 0)
                    return fail("ATAN2 of (0, 0) has no angle");
                result = std::atan2(x, y) / kDeg;
                break;
            case Fn::Pot:
                result = std::pow(x, y);
                break;
            case Fn::MinVal:
                result = std::min(x, y);
                break;
            case Fn::MaxVal:
                result = std::max(x, y);
                break;
            default:
                return fail("function takes one argument");
            }
            break;
        default:
            return fail("invalid expression");
        }
    }
    if (!std::isfinite(result))
        return fail("the value is not finite (overflow)");
    return result;
}

}  // namespace camwb::nc::sinumerik
