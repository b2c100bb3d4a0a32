// A SINUMERIK program parsed once into a flat block list: expressions in one node array, words in
// one word array, control flow (IF/WHILE/REPEAT/FOR/LOOP) matched to jump targets, labels and
// block numbers indexed for GOTO. The interpreter runs a program counter over it, so a loop that
// runs a million times costs no parsing and no allocation.
#pragma once

#include "nc/Diagnostic.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace camwb::nc::sinumerik {

// Source position of a token or node: 1-based line and column in its file.
struct Pos {
    int line = 0;
    int column = 0;
};

enum class Fn : std::uint8_t {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan2,
    Sqrt,
    Abs,
    Pot,
    Round,
    RoundUp,
    Trunc,
    Ln,
    Exp,
    MinVal,
    MaxVal,
};

enum class Op : std::uint8_t {
    // Operands first, up to SysVar (Machine::evalOperand), then operators.
    Const,
    RParam,     // R<index> with a constant index (in `index`)
    RIndirect,  // R[a]
    Local,      // DEF variable: slot in `index`, arrays: a = flat element index expression
    Unknown,    // a name no one declared: evaluates to 0 with an error
    SysVar,     // $... system variables: 0 with a warning
    Neg,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    IntDiv,
    Mod,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    And,
    Or,
    Xor,
    Call1,
    Call2,  // function `fn` of a (and b)
};

struct Expr {
    Op op = Op::Const;
    Fn fn = Fn::Sin;
    std::int32_t a = -1, b = -1;
    std::int32_t index = 0;      // R index, local slot
    std::int32_t arraySize = 0;  // Local arrays: number of elements (for the bounds check)
    std::int32_t depth = 1;      // of the tree below: evaluation recursion stays bounded
    double value = 0;
    Pos pos;
};

enum class WordKind : std::uint8_t {
    G,       // code in `code`
    M,       // code in `code` (M=expr not supported: constant codes only)
    Axis,    // index 0..5 = X Y Z A B C
    Centre,  // index 0..2 = I J K
    F,
    S,
    T,
    D,
    Cr,
    Ar,
    Turn,
    Lims,
    TName,        // T="name": text in the block's text
    Assign,       // target: R (index, or indirect expr2), local slot (+ element expr2)
    Keyword,      // code = Keyword enum value
    Cycle,        // CYCLE8x(args): code = cycle number, args in the block's argument list
    Call,         // subprogram by name (block name), args in the argument list
    Msg,          // MSG("text") / MSG()
    Passive,      // recognised, no effect on the trace (G64, SOFT, CYCLE832(...), ...)
    ToolVector,   // A3= B3= C3= (index 0..2): the tool's direction under TRAORI
    MachineAxis,  // X1= Y1= Z1= (index 0..2): a machine axis G74/G75 sends home (the value is ignored)
};

// X=AC(..) / X=IC(..); a rotary axis also B=DC(..) (the shorter way), ACP(..) / ACN(..) (turning in
// the positive / negative sense only).
enum class ValueMode : std::uint8_t { Modal, Absolute, Incremental, Shortest, Positive, Negative };

enum class Keyword : std::uint8_t { DiamOn, DiamOf, TraOri, TraFoof, Cycle800, Frame, Ret, SetAl, Stopre, Supa };

// ToolData: $TC_DPn[t, d] (code = n, expr2 = t, expr3 = d), the tool offsets a program sets.
enum class AssignTarget : std::uint8_t { R, RIndirect, Local, ToolData };

struct Word {
    WordKind kind = WordKind::G;
    std::uint8_t index = 0;
    ValueMode mode = ValueMode::Modal;
    AssignTarget target = AssignTarget::R;
    std::int32_t code = 0;    // G/M code, R index, local slot, keyword, cycle number
    std::int32_t expr = -1;   // value
    std::int32_t expr2 = -1;  // array element / indirect R index / tool number of $TC_DP
    std::int32_t expr3 = -1;  // cutting edge of $TC_DP
    std::int32_t arraySize = 0;
    Pos pos;
    double value = 0;
};

enum class BlockKind : std::uint8_t {
    Normal,
    Empty,
    If,
    Else,
    EndIf,
    While,
    EndWhile,
    Repeat,
    Until,
    For,
    EndFor,
    Loop,
    EndLoop,
    Goto,   // GOTOF/GOTOB/GOTO/GOTOC, with IF: conditional (expr = condition, -1 none)
    Proc,   // PROC header (parameters declared as locals)
    MCall,  // MCALL [CYCLE8x(...)]: cycle number in `code` (0 = cancel)
    Bad,    // parse error: skipped when reached
};

enum class GotoDir : std::uint8_t { Forward, Backward, Both, BothNoAlarm };

struct Block {
    BlockKind kind = BlockKind::Empty;
    GotoDir gotoDir = GotoDir::Forward;
    std::int32_t line = 0;
    std::int32_t firstWord = 0, wordCount = 0;
    std::int32_t firstArg = 0, argCount = 0;  // cycle/call arguments (-1 = empty argument)
    std::int32_t expr = -1;                   // IF/WHILE/UNTIL condition, FOR start, MCALL repeat
    std::int32_t expr2 = -1;                  // FOR end, call repeat count P
    std::int32_t jump = -1;                   // matched block (IF: ELSE/ENDIF, ELSE: ENDIF, WHILE: ENDWHILE, ...)
    std::int32_t forSlot = -1;                // FOR variable: R index (forIsR) or local slot
    bool forIsR = false;
    std::int32_t code = 0;       // MCALL cycle number
    std::int32_t comment = -1;   // index into Program::texts
    std::int32_t text = -1;      // label target / subprogram name / MSG text / T name (Program::texts)
    std::int32_t callWord = -1;  // word index of the cycle/call word in the block, -1 none
    bool bad = false;            // a statement with a broken condition: IF/WHILE false, UNTIL true
};

// Parse diagnostics kept per file; more are counted (a binary file read as NC has one per line).
inline constexpr std::size_t kMaxParseDiagnostics = 10000;

struct Program {
    std::string path;      // for diagnostics
    std::string source;    // the text, owned: tokens and texts point into it
    std::string procName;  // PROC header name (upper case), empty when none
    Pos procPos;
    std::vector<Block> blocks;
    std::vector<Word> words;
    std::vector<Expr> exprs;
    std::vector<std::int32_t> args;
    std::vector<std::string> texts;                                     // comments, names, messages
    std::unordered_map<std::string, std::vector<std::int32_t>> labels;  // upper-case label -> block indices
    // (N, block index) in block order; sorted by N at the end of parsing for GOTO N...
    std::vector<std::pair<std::int64_t, std::int32_t>> blockNumbers;
    std::int32_t localSlots = 0;           // DEF variables (array elements included)
    std::vector<std::uint8_t> slotType;    // per local slot: 0 REAL, 1 INT (rounded), 2 BOOL (0/1)
    std::vector<std::int32_t> procParams;  // local slots of the PROC parameters, in order
    bool hasM6 = false;
    std::vector<Diagnostic> diagnostics;  // parse diagnostics, the first kMaxParseDiagnostics
    std::size_t diagnosticsDropped = 0;
};

// Parses `source` (kept in the program) into blocks; diagnostics name `path`.
Program parseProgram(std::string path, std::string source);

// Upper-case copy of an ASCII name.
std::string upper(std::string_view s);

}  // namespace camwb::nc::sinumerik
