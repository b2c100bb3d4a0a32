// Klartext arithmetic: Q/QL/QR parameters, word values (`X+Q1`, `F+Q602`), formulas
// (`Q5 = SIN(Q1) * 2 ^ 3`) and the FN operators DIV, LEN and ANG. Parsed into the program's
// expression pool with bounded depth and size; evaluated in degrees with range checks.
#pragma once

#include "nc/heidenhain/Lexer.h"
#include "nc/heidenhain/Program.h"

#include <optional>
#include <string>
#include <vector>

namespace camwb::nc::heidenhain {

inline constexpr int kQCount = 2000;  // Q0..Q1999
inline constexpr int kQLCount = 500;  // QL0..QL499
inline constexpr int kQRCount = 500;  // QR0..QR499
inline constexpr int kMaxExprDepth = 32;
inline constexpr int kMaxExprNodes = 256;

struct ParseEnv {
    Program& program;
    Reporter& reporter;
    const std::string& file;
};

// A full expression; -1 (after an error) when there is none.
int parseExpression(Cursor& cursor, ParseEnv& env);
// A word value: [+|-] (number | Q/QL/QR parameter | '(' expression ')'); -1 when none is there
// (nothing reported: the caller decides whether a value was required) or after an error in it
// (reported; `reported` is then set when given).
int parseValue(Cursor& cursor, ParseEnv& env, bool* reported = nullptr);
// A parameter reference "Q12", "QL3", "QR7" at the cursor: op and number; nullopt when none.
struct ParamRef {
    ExprOp op = ExprOp::Q;
    int number = 0;
};
std::optional<ParamRef> parseParameter(Cursor& cursor, ParseEnv& env);
int constantExpr(Program& program, double value, int line, int column);

struct Parameters {
    std::vector<double> q = std::vector<double>(kQCount, 0.0);
    std::vector<double> ql = std::vector<double>(kQLCount, 0.0);
    std::vector<double> qr = std::vector<double>(kQRCount, 0.0);
    double& at(ExprOp op, int number);
};

// Evaluates with range checks (division by zero, roots of negatives, non-finite results): nullopt
// after an error, reported at the operator's position.
std::optional<double> evaluate(const Program& program, int expr, Parameters& params, Reporter& reporter,
                               const std::string& file);

}  // namespace camwb::nc::heidenhain
