// Block numbers of NC programs per dialect, as CIMCO's NC tools handle them: which number a line
// carries, find a block by its number, renumber (start, step, which lines, GOTO targets remapped)
// and remove numbers. Qt-free; the editor's Renumber / Remove numbers / Go to block actions call it.
#pragma once

#include "nc/Dialect.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc {

enum class LineKind {
    Empty,        // only blanks
    CommentOnly,  // a comment and nothing else (besides a block number)
    Block,        // NC words
    Header,       // never numbered: '%' lines, ISO O-number lines, Heidenhain continuation lines
};

// One line (without its line end) as the block-number tools see it. Byte offsets into the line.
struct LineInfo {
    LineKind kind = LineKind::Empty;
    std::optional<long long> number;  // the block number the line carries
    std::size_t numberBegin = 0;      // the 'N' / ':' (Heidenhain: first digit); == numberEnd without a number
    std::size_t numberEnd = 0;        // after the digits
    std::size_t removeEnd = 0;        // after the digits and the blanks that follow them
    std::size_t insertAt = 0;         // where a new number goes (after indentation and a skip level '/n')
};

// `continuation`: the previous line ended in '~' (Heidenhain: this line continues that block).
LineInfo analyzeLine(std::string_view line, Dialect dialect, bool continuation = false);

// The 1-based line of the first block whose number is `number`; nullopt when there is none.
std::optional<int> findBlock(std::string_view text, Dialect dialect, long long number);

struct RenumberOptions {
    Dialect dialect = Dialect::Sinumerik;
    long long start = 10;
    long long step = 10;
    bool numberCommentLines = false;  // lines with only a comment get a number too
    bool numberEmptyLines = false;    // blank lines get a number too
    bool replaceExisting = true;      // false: numbered blocks keep their numbers, the others are added
    bool onlyNumbered = false;        // true: lines without a number stay without one
};

struct RenumberNote {
    int line = 0;  // 1-based
    std::string message;
};

struct RenumberReport {
    int linesNumbered = 0;  // lines whose number was added or changed
    int numbersRemoved = 0;
    int targetsRemapped = 0;          // GOTO N<n> targets rewritten to the new number
    std::vector<RenumberNote> notes;  // targets not found, options a dialect ignores, ...
};

struct RenumberResult {
    std::string text;
    RenumberReport report;
};

// Sinumerik / ISO: N words (Sinumerik ':' main blocks too) at the block start after a skip level.
// Heidenhain: every line's leading number, always from 0 in steps of 1 (the control insists),
// start/step/line options ignored with a note. Comments, strings, labels untouched; targets of
// GOTO/GOTOF/GOTOB/GOTOC N<n> (Sinumerik) and GOTO <n> (ISO macro) follow their block.
RenumberResult renumberBlocks(std::string_view text, const RenumberOptions& options);

// Removes the block numbers of Sinumerik / ISO programs; blocks a GOTO jumps to keep theirs
// (with a note). Heidenhain needs its numbers: the text comes back unchanged with a note.
RenumberResult removeBlockNumbers(std::string_view text, Dialect dialect);

// Splits at '\n'; each view excludes the '\n' and a '\r' before it. A final line end gives no
// extra empty line. Shared by the tools in this folder.
std::vector<std::string_view> splitLines(std::string_view text);

}  // namespace camwb::nc
