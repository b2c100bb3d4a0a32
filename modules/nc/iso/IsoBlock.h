// One ISO block as read from its line: the words by letter (with their columns for diagnostics),
// the G and M codes in the order written, comments, parameter assignments and an O-word. Reused
// from line to line, so reading a block allocates nothing once its vectors have grown.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc::iso {

inline constexpr int kMaxCodesPerBlock = 16;

// O-word keywords (LinuxCNC "O Codes").
enum class OKeyword {
    None,
    Sub,
    EndSub,
    Call,
    Return,
    Do,
    While,
    EndWhile,
    If,
    ElseIf,
    Else,
    EndIf,
    Repeat,
    EndRepeat,
    Break,
    Continue
};

struct Code {
    int code10 = 0;  // G or M number times ten: G59.1 = 591, G1 = 10
    int column = 0;
};

struct Assignment {
    int index = -1;    // numbered parameter, or -1 for `name`
    std::string name;  // normalised
    double value = 0;
    int column = 0;
};

struct Block {
    std::uint32_t present = 0;  // one bit per letter A..Z (not G, M, N, O)
    double value[26] = {};
    int column[26] = {};
    Code g[kMaxCodesPerBlock];
    Code m[kMaxCodesPerBlock];
    int gCount = 0;
    int mCount = 0;
    bool blockDelete = false;
    bool error = false;  // a diagnostic made the block unsafe to execute
    std::vector<std::string_view> comments;
    std::vector<Assignment> assignments;
    int assignmentCount = 0;  // entries of `assignments` in use (their strings keep capacity)

    OKeyword oKeyword = OKeyword::None;
    std::string oLabel;  // normalised: "100" for o100, "name" for o<name>
    int oColumn = 0;
    std::vector<double> oArguments;  // condition, repeat count, call arguments, return value

    void clear()
    {
        present = 0;
        gCount = 0;
        mCount = 0;
        blockDelete = false;
        error = false;
        comments.clear();
        assignmentCount = 0;
        oKeyword = OKeyword::None;
        oArguments.clear();
    }
    bool has(char letter) const { return (present >> (letter - 'A')) & 1u; }
    double get(char letter) const { return value[letter - 'A']; }
    int col(char letter) const { return column[letter - 'A']; }
    bool empty() const
    {
        return present == 0 && gCount == 0 && mCount == 0 && comments.empty() && assignmentCount == 0 &&
               oKeyword == OKeyword::None;
    }
};

}  // namespace camwb::nc::iso
