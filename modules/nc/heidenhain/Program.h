// The parsed form of a Klartext program: blocks with their source positions, words and
// expressions kept in flat pools (indices, no per-token allocation), parsed once and then run by
// the interpreter with a program counter.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace camwb::nc::heidenhain {

// One physical line's code (comment and continuation mark removed) inside a block.
struct Segment {
    std::string_view code;
    int line = 0;    // 1-based
    int column = 1;  // 1-based column of code[0]
};

enum class ExprOp : std::uint8_t {
    Const,
    Q,   // value = parameter number
    QL,  // local parameter
    QR,  // remanent parameter
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Len,  // FN 8: sqrt(a^2 + b^2)
    Ang,  // FN 13: angle of (a, b)
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Sq,
    Abs,
    Int,
    Frac,
    Sgn,
    Ln,
    Log,
    Exp,
};

struct Expr {
    ExprOp op = ExprOp::Const;
    double value = 0;
    int a = -1;
    int b = -1;
    int line = 0;
    int column = 0;
};

// Address words. The axes come first, absolute X..W then incremental IX..IW, in the order of
// BlockWords::axes (X = 0, IX = 9).
enum class Key : std::uint8_t {
    X,
    Y,
    Z,
    A,
    B,
    C,
    U,
    V,
    W,
    IX,
    IY,
    IZ,
    IA,
    IB,
    IC,
    IU,
    IV,
    IW,
    // Polar radius and angle about CC.
    PR,
    PA,
    IPR,
    IPA,
    Radius,     // R of CR and RND, R of TOOL DEF
    Direction,  // DR+ / DR-: param +1 / -1
    Comp,       // R0 / RL / RR: param 0 / 1 / 2
    Feed,
    FeedMax,
    FeedAuto,
    FeedRev,    // FU: feed per revolution
    FeedTooth,  // FZ: feed per tooth
    M,          // param = the M number
    Speed,
    SurfaceSpeed,  // S(VC=...)
    DeltaLength,
    DeltaRadius,
    DeltaRadius2,
    Length,      // L of TOOL DEF
    ToolAxis,    // param = 'X' / 'Y' / 'Z'
    Rep,         // REP n of CALL LBL
    QSet,        // Qn = expr inside CYCL DEF (param = n)
    Len,         // LEN of APPR/DEP, length of CHF, value of an old cycle line (9.1 DWELL 1.5)
    Angle,       // CCA of APPR/DEP
    Mb,          // MB of M140 and PLANE (param 1 = MAX)
    PlaneValue,  // a PLANE value: param = PlaneWord
};

// The values a PLANE block gives (Word::param of Key::PlaneValue).
enum PlaneWord : int {
    kPlaneSpa,
    kPlaneSpb,
    kPlaneSpc,
    kPlaneBx,
    kPlaneBy,
    kPlaneBz,
    kPlaneNx,
    kPlaneNy,
    kPlaneNz,
    kPlaneAxisA,  // PLANE AXIAL A B C: the machine's axis angles
    kPlaneAxisB,
    kPlaneAxisC,
    kPlaneWordCount,
};

// How a PLANE block positions the rotary axes (Block::a): not said, MOVE, TURN or STAY.
enum PlanePositioning : int { kPlaneNoPositioning, kPlaneMove, kPlaneTurn, kPlaneStay };

struct Word {
    Key key = Key::X;
    int expr = -1;  // index into Program::exprs, -1 = no value
    int param = 0;
    int line = 0;
    int column = 0;
};

enum class BlockKind : std::uint8_t {
    Empty,
    Comment,
    BeginPgm,
    EndPgm,
    BlkForm,
    ToolDef,
    ToolCall,
    Line,           // L
    LinePolar,      // LP
    LineVector,     // LN (five-axis)
    CircleCenter,   // CC
    Circle,         // C
    CircleRadius,   // CR
    CircleTangent,  // CT
    CirclePolar,    // CP
    Round,          // RND
    Chamfer,        // CHF
    Approach,       // APPR / DEP (approximated)
    Label,
    CallLabel,
    CallPgm,
    FnAssign,  // FN 0..8, 13 and Qn = expr
    FnJump,    // FN 9..12
    FnError,   // FN 14
    CycleDef,
    CycleCall,
    CycleCallPos,
    Plane,
    Function,
    Stop,
    MOnly,
    Elision,  // "..." in a listing fragment: lines left out
    Skipped,  // recognised but not traced (warned when parsed)
    Invalid,  // errors reported when parsed
};

// The choices of FUNCTION TCPM (Block::a); the iTNC's defaults F TCP, AXIS POS, PATHCTRL AXIS and
// REFPNT TIP-TIP are 0.
enum TcpmOption : int {
    kTcpmFeedCont = 1,    // F CONT: the feed along the programmed path of the axes
    kTcpmAxisSpat = 2,    // AXIS SPAT: A, B, C are spatial angles, not axis positions
    kTcpmPathVector = 4,  // PATHCTRL VECTOR: the tool vector turns in the plane of start and end
    kTcpmRefCenter = 8,   // REFPNT TIP-CENTER / CENTER-CENTER: X Y Z give the tool's centre
};

enum class Condition : std::uint8_t { Equal, NotEqual, Greater, Less };

struct Block {
    BlockKind kind = BlockKind::Empty;
    int line = 0;              // first physical line
    int column = 1;            // column of the keyword
    std::int64_t number = -1;  // block number, -1 = none
    int firstWord = 0;
    int wordCount = 0;
    int a = 0;       // kind-specific: cycle number, FN number, target parameter kind, PLANE positioning ...
    int b = 0;       // cycle sub-number, target parameter number, condition, PLANE's SEQ sign ...
    int exprA = -1;  // kind-specific expressions (FN assign value, FN jump operands)
    int exprB = -1;
    bool flag = false;          // MM/INCH (true = inch), PLANE RESET, label is a name, FUNCTION RESET ...
    std::string_view name;      // program / label / cycle name
    std::string_view labelRef;  // jump target of FN 9..12 / CALL LBL
    bool labelRefIsName = false;
    std::string_view comment;
    int commentLine = 0;
};

// A program's text parsed into blocks. `text` owns the text of called programs (string_views
// point into it); the main program's views point into the caller's text.
struct Program {
    std::string text;
    std::string path;  // as given (diagnostics)
    int fileIndex = 0;
    std::vector<Segment> segments;
    std::vector<Expr> exprs;
    std::vector<Word> words;
    std::vector<Block> blocks;
    std::unordered_map<std::string, int> labels;  // "N<number>" or the name -> block index
    bool inch = false;
};

// Map key of a label: numbers without leading zeros ("N7"), names as written ("S" + name).
inline std::string labelKey(std::string_view ref, bool isName)
{
    if (!isName) {
        while (ref.size() > 1 && ref.front() == '0')
            ref.remove_prefix(1);
    }
    std::string key(isName ? "S" : "N");
    key += ref;
    return key;
}

}  // namespace camwb::nc::heidenhain
