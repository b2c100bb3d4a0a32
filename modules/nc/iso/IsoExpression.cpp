// Values and [expressions] of RS274NGC (LinuxCNC "Numbers, Parameters, and Expressions"):
// binary operators by precedence ** > * / MOD > + - > EQ NE GT GE LT LE > AND OR XOR, left to right
// within a level; functions in degrees. Every recursion passes through readValue, which bounds
// the nesting, so no input can overflow the stack.
#include "nc/iso/IsoNumber.h"
#include "nc/iso/IsoScanner.h"

#include <cmath>
#include <cstring>
#include <numbers>

namespace camwb::nc::iso {

namespace {

constexpr int kMaxDepth = 200;
constexpr double kDegree = std::numbers::pi / 180.0;

enum Op { None, Power, Times, Divide, Mod, Plus, Minus, Eq, Ne, Gt, Ge, Lt, Le, And, Or, Xor };

struct OpName {
    const char* text;
    Op op;
    int precedence;
};
constexpr OpName kWordOps[] = {{"mod", Mod, 3}, {"eq", Eq, 1}, {"ne", Ne, 1},   {"gt", Gt, 1}, {"ge", Ge, 1},
                               {"lt", Lt, 1},   {"le", Le, 1}, {"and", And, 0}, {"or", Or, 0}, {"xor", Xor, 0}};

// Letters from p (blanks skipped) into `word`, lower case; false when more than fit.
bool readLetters(const char*& p, const char* end, char (&word)[8])
{
    int n = 0;
    while (p < end && (isLetter(*p) || isBlank(*p))) {
        if (!isBlank(*p)) {
            if (n == 7)
                return false;
            word[n++] = static_cast<char>(*p | 0x20);
        }
        ++p;
    }
    word[n] = 0;
    return n > 0;
}

}  // namespace

bool LineScanner::readValue(double& out)
{
    if (++m_depth > kMaxDepth) {
        fail(m_p, "expression nested too deeply");
        return false;
    }
    struct Leave {
        int& depth;
        ~Leave() { --depth; }
    } leave{m_depth};
    skipBlanks();
    if (m_p >= m_end) {
        fail(m_p - (m_p > m_begin ? 1 : 0), "missing value at the end of the line");
        return false;
    }
    const char c = *m_p;
    if (isDigit(c) || c == '.') {
        const char* start = m_p;
        const NumberStatus status = scanUnsigned(m_p, m_end, out);
        if (status != NumberStatus::Ok) {
            fail(start, status == NumberStatus::TooLong ? "number too long" : "a number needs a digit");
            return false;
        }
        return true;
    }
    if (c == '-' || c == '+') {
        ++m_p;
        if (!readValue(out))
            return false;
        if (c == '-')
            out = -out;
        return true;
    }
    if (c == '[')
        return readBracketed(out);
    if (c == '#') {
        ++m_p;
        return readParameter(out);
    }
    if (isLetter(c))
        return readFunction(out);
    fail(m_p, c == ']' ? "']' without '['" : "expected a value");
    return false;
}

bool LineScanner::readBracketed(double& out)
{
    skipBlanks();
    const char* open = m_p;
    if (m_p >= m_end || *m_p != '[') {
        fail(m_p < m_end ? m_p : open - 1, "expected '['");
        return false;
    }
    ++m_p;
    if (!readExpression(out, 0))
        return false;
    skipBlanks();
    if (m_p >= m_end || *m_p != ']') {
        fail(open, "unbalanced brackets: '[' without ']'");
        return false;
    }
    ++m_p;
    return true;
}

int LineScanner::readOperator(int& precedence)
{
    skipBlanks();
    if (m_p >= m_end)
        return None;
    const char c = *m_p;
    switch (c) {
    case '*': {
        const char* q = m_p + 1;
        while (q < m_end && isBlank(*q))
            ++q;
        if (q < m_end && *q == '*') {
            m_p = q + 1;
            precedence = 4;
            return Power;
        }
        ++m_p;
        precedence = 3;
        return Times;
    }
    case '/':
        ++m_p;
        precedence = 3;
        return Divide;
    case '+':
        ++m_p;
        precedence = 2;
        return Plus;
    case '-':
        ++m_p;
        precedence = 2;
        return Minus;
    default:
        break;
    }
    if (!isLetter(c))
        return None;
    const char* start = m_p;
    char word[8];
    if (readLetters(m_p, m_end, word)) {
        for (const OpName& name : kWordOps) {
            if (std::strcmp(name.text, word) == 0) {
                precedence = name.precedence;
                return name.op;
            }
        }
    }
    m_p = start;
    return None;
}

bool LineScanner::readExpression(double& out, int minPrecedence)
{
    if (!readValue(out))
        return false;
    for (;;) {
        const char* save = m_p;
        int precedence = 0;
        const int op = readOperator(precedence);
        if (op == None)
            return true;
        if (precedence < minPrecedence) {
            m_p = save;
            return true;
        }
        const char* opAt = save;
        while (opAt < m_p && isBlank(*opAt))
            ++opAt;
        double rhs = 0;
        if (!readExpression(rhs, precedence + 1))
            return false;
        switch (op) {
        case Power:
            if (out < 0 && rhs != std::floor(rhs)) {
                fail(opAt, "negative number to a non-integer power");
                return false;
            }
            out = std::pow(out, rhs);
            break;
        case Times:
            out *= rhs;
            break;
        case Divide:
        case Mod:
            if (rhs == 0) {
                fail(opAt, "division by zero");
                return false;
            }
            if (op == Divide) {
                out /= rhs;
            } else {
                out = std::fmod(out, rhs);
                if (out < 0)
                    out += std::abs(rhs);  // RS274NGC: the result takes the sign of the divisor's size
            }
            break;
        case Plus:
            out += rhs;
            break;
        case Minus:
            out -= rhs;
            break;
        case Eq:
            out = out == rhs;
            break;
        case Ne:
            out = out != rhs;
            break;
        case Gt:
            out = out > rhs;
            break;
        case Ge:
            out = out >= rhs;
            break;
        case Lt:
            out = out < rhs;
            break;
        case Le:
            out = out <= rhs;
            break;
        case And:
            out = (out != 0) && (rhs != 0);
            break;
        case Or:
            out = (out != 0) || (rhs != 0);
            break;
        case Xor:
            out = (out != 0) != (rhs != 0);
            break;
        default:
            break;
        }
        if (!std::isfinite(out)) {
            fail(opAt, "the result is not a finite number");
            return false;
        }
    }
}

bool LineScanner::readParameterIndex(int& index, std::string& name)
{
    name.clear();
    skipBlanks();
    const char* at = m_p;
    if (m_p < m_end && *m_p == '<') {
        ++m_p;
        const char* start = m_p;
        while (m_p < m_end && *m_p != '>')
            ++m_p;
        if (m_p >= m_end) {
            fail(at, "parameter name without '>'");
            return false;
        }
        name = normaliseName(std::string_view(start, static_cast<std::size_t>(m_p - start)));
        ++m_p;
        if (name.empty()) {
            fail(at, "empty parameter name");
            return false;
        }
        return true;
    }
    double v = 0;
    if (!readValue(v))
        return false;
    const double rounded = std::round(v);
    if (std::abs(v - rounded) > 1e-4 || rounded < 0 || rounded >= kParameterCount) {
        fail(at, "parameter number out of range (0..5399)");
        return false;
    }
    index = static_cast<int>(rounded);
    return true;
}

bool LineScanner::readParameter(double& out)
{
    const char* at = m_p - 1;
    int index = 0;
    std::string name;
    if (!readParameterIndex(index, name))
        return false;
    if (name.empty()) {
        out = m_parameters.numbered(index);
        return true;
    }
    const auto value = m_parameters.named(name);
    if (!value) {
        fail(at, "parameter #<" + name + "> is not defined");
        return false;
    }
    out = *value;
    return true;
}

bool LineScanner::readFunction(double& out)
{
    const char* at = m_p;
    char word[8];
    if (!readLetters(m_p, m_end, word)) {
        fail(at, "unknown function");
        return false;
    }
    if (std::strcmp(word, "exists") == 0) {
        skipBlanks();
        if (m_p >= m_end || *m_p != '[') {
            fail(at, "EXISTS needs [#<name>]");
            return false;
        }
        ++m_p;
        skipBlanks();
        if (m_p >= m_end || *m_p != '#') {
            fail(at, "EXISTS needs [#<name>]");
            return false;
        }
        ++m_p;
        int index = 0;
        std::string name;
        if (!readParameterIndex(index, name))
            return false;
        skipBlanks();
        if (m_p >= m_end || *m_p != ']') {
            fail(at, "unbalanced brackets: '[' without ']'");
            return false;
        }
        ++m_p;
        out = name.empty() ? 1.0 : (m_parameters.exists(name) ? 1.0 : 0.0);
        return true;
    }
    if (std::strcmp(word, "atan") == 0) {
        double a = 0, b = 0;
        if (!readBracketed(a))
            return false;
        skipBlanks();
        if (m_p >= m_end || *m_p != '/') {
            fail(at, "ATAN needs [y]/[x]");
            return false;
        }
        ++m_p;
        if (!readBracketed(b))
            return false;
        out = std::atan2(a, b) / kDegree;
        return true;
    }
    static constexpr const char* kNames[] = {"abs", "acos",  "asin", "cos", "exp",  "fix",
                                             "fup", "round", "ln",   "sin", "sqrt", "tan"};
    int which = -1;
    for (int i = 0; i < static_cast<int>(std::size(kNames)); ++i) {
        if (std::strcmp(kNames[i], word) == 0)
            which = i;
    }
    if (which < 0) {
        fail(at, "unknown function or word: " + std::string(word));
        return false;
    }
    double x = 0;
    if (!readBracketed(x))
        return false;
    switch (which) {
    case 0:
        out = std::abs(x);
        break;
    case 1:
    case 2:
        if (x < -1 || x > 1) {
            fail(at, std::string(which == 1 ? "ACOS" : "ASIN") + " of a value outside -1..1");
            return false;
        }
        out = (which == 1 ? std::acos(x) : std::asin(x)) / kDegree;
        break;
    case 3:
        out = std::cos(x * kDegree);
        break;
    case 4:
        out = std::exp(x);
        break;
    case 5:
        out = std::floor(x);
        break;
    case 6:
        out = std::ceil(x);
        break;
    case 7:
        out = x < 0 ? std::ceil(x - 0.5) : std::floor(x + 0.5);
        break;  // halves away from zero
    case 8:
        if (x <= 0) {
            fail(at, "LN of a value that is not positive");
            return false;
        }
        out = std::log(x);
        break;
    case 9:
        out = std::sin(x * kDegree);
        break;
    case 10:
        if (x < 0) {
            fail(at, "SQRT of a negative value");
            return false;
        }
        out = std::sqrt(x);
        break;
    case 11:
        out = std::tan(x * kDegree);
        break;
    default:
        break;
    }
    if (!std::isfinite(out)) {
        fail(at, "the result is not a finite number");
        return false;
    }
    return true;
}

}  // namespace camwb::nc::iso
