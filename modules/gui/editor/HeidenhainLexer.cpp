// Heidenhain Klartext highlighting: words are letter groups (L, CC, IPA, FMAX) followed by a
// signed value or nothing, so the scanner reads the letters first and decides by the group.
#include "gui/editor/detail/DialectLexers.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <string_view>

namespace camwb::gui {

namespace {

// Path functions, program structure, cycles, tilted planes, FN and the functions of Q formulas.
// Sorted (binary search).
constexpr std::array<std::string_view, 79> kKeywords{
    "ABS",     "ADD",  "APPR",   "AUTO",    "AXIAL", "AXIS",     "BEGIN",  "BLK",     "C",         "CALL",
    "CC",      "CHF",  "COORD",  "COS",     "CP",    "CR",       "CT",     "CTP",     "CYCL",      "DATUM",
    "DECLARE", "DEF",  "DEP",    "DIV",     "END",   "EQ",       "EULER",  "FC",      "FCT",       "FEED",
    "FL",      "FLT",  "FN",     "FORM",    "FRAC",  "FUNCTION", "GOTO",   "GT",      "IF",        "INCH",
    "INT",     "L",    "LBL",    "LCT",     "LN",    "LOG",      "LP",     "LT",      "MAX",       "MM",
    "MOVE",    "MULT", "NE",     "PATTERN", "PGM",   "PLANE",    "POINTS", "POS",     "PROJECTED", "REL",
    "RELATIV", "REP",  "RESET",  "RND",     "SEL",   "SET",      "SIN",    "SPATIAL", "SQ",        "SQRT",
    "STAY",    "STOP", "STRING", "SUB",     "TAN",   "TCPM",     "TOOL",   "TURN",    "VECTOR"};
static_assert(std::is_sorted(kKeywords.begin(), kKeywords.end()), "keep sorted");

// Letter groups that take a coordinate: absolute, incremental (I...), polar (PA/PR) and
// circle-centre words.
constexpr std::array<std::string_view, 28> kAxisWords{"A",  "B",  "C",  "I",  "IA", "IB", "IC", "IPA", "IPR", "IU",
                                                      "IV", "IW", "IX", "IY", "IZ", "J",  "K",  "PA",  "PR",  "R",
                                                      "U",  "V",  "W",  "X",  "Y",  "Z",  "H",  "CCA"};

using lexchar::isDigit;
using lexchar::isLetter;
using lexchar::upper;

}  // namespace

void lexHeidenhain(const char* s, int n, bool continuation, char* styles)
{
    int i = 0;
    auto emitRun = [&](int length, NcStyle style) {
        std::memset(styles + i, static_cast<int>(style), std::size_t(length));
    };
    bool lineStart = true;
    bool afterNumber = false;   // only the block number seen on this line so far
    bool cycleContext = false;  // after CYCL DEF: the cycle's name reads as part of the cycle
    bool thisLineContinues = continuation;
    bool valueAllowed = true;  // a sign here starts a number (after blanks, '=', '(')
    bool programName = false;  // the next word names a program
    auto lineEnd = [&](int from) {
        while (from < n && s[from] != '\n' && s[from] != '\r')
            ++from;
        return from;
    };
    auto numberEnd = [&](int from) {
        while (from < n && (isDigit(s[from]) || s[from] == '.'))
            ++from;
        return from;
    };
    auto signedValueEnd = [&](int from) {
        if (from < n && (s[from] == '+' || s[from] == '-'))
            ++from;
        return numberEnd(from);
    };

    while (i < n) {
        const char c = s[i];
        int j = i + 1;
        NcStyle style = NcStyle::Default;
        if (c == '\n' || c == '\r') {
            // The line that just ended continues into the next one when it ended in '~'.
            if (c == '\n' || (j < n && s[j] != '\n')) {
                int k = i - 1;
                while (k >= 0 && (s[k] == ' ' || s[k] == '\t' || s[k] == '\r'))
                    --k;
                thisLineContinues = k >= 0 && s[k] == '~';
            }
            if (c == '\r' && j < n && s[j] == '\n')
                ++j;
            lineStart = true;
            afterNumber = false;
            cycleContext = false;
            programName = false;
            valueAllowed = true;
            emitRun(j - i, style);
            i = j;
            continue;
        }
        if (c == ' ' || c == '\t') {
            while (j < n && (s[j] == ' ' || s[j] == '\t'))
                ++j;
            valueAllowed = true;
            emitRun(j - i, style);
            i = j;
            continue;
        }
        const bool atLineStart = lineStart;
        lineStart = false;
        if (atLineStart && !thisLineContinues && isDigit(c)) {
            j = numberEnd(i);
            style = NcStyle::BlockNumber;
            afterNumber = true;
            emitRun(j - i, style);
            i = j;
            continue;
        }
        const bool commentStar = c == '*' && (afterNumber || atLineStart);
        afterNumber = false;
        if (programName) {
            // The name after PGM (BEGIN/END/CALL PGM F3D_CONTOUR16): no words inside it.
            while (j < n && s[j] != ' ' && s[j] != '\t' && s[j] != '\n' && s[j] != '\r')
                ++j;
            programName = false;
            emitRun(j - i, NcStyle::Default);
            i = j;
            continue;
        }
        if (c == ';' || commentStar) {
            j = lineEnd(i);
            style = NcStyle::Comment;
        } else if (c == '"') {
            while (j < n && s[j] != '"' && s[j] != '\n' && s[j] != '\r')
                ++j;
            if (j < n && s[j] == '"')
                ++j;
            style = NcStyle::String;
        } else if (isLetter(c)) {
            while (j < n && isLetter(s[j]))
                ++j;
            std::string word(static_cast<std::size_t>(j - i), ' ');
            std::transform(s + i, s + j, word.begin(), upper);
            const char next = j < n ? s[j] : '\0';
            const bool valueNext = isDigit(next) || next == '.' || next == '+' || next == '-';
            const bool digitNext = isDigit(next);
            if ((word == "Q" || word == "QL" || word == "QR" || word == "QS") && digitNext) {
                j = numberEnd(j);
                style = NcStyle::Parameter;
            } else if (word == "M" && digitNext) {
                j = numberEnd(j);
                style = NcStyle::MWord;
            } else if ((word == "F" || word == "S" || word == "FU" || word == "FZ") && digitNext) {
                j = numberEnd(j);
                style = NcStyle::FeedSpeedTool;
            } else if (word == "F" &&
                       (next == 'Q' || next == 'q' ||
                        ((next == '+' || next == '-') && j + 1 < n && (s[j + 1] == 'Q' || s[j + 1] == 'q')))) {
                style = NcStyle::FeedSpeedTool;  // F+Q603: the feed from a parameter (the Q styles next)
                if (next == '+' || next == '-')
                    ++j;
            } else if (word == "FMAX" || word == "FAUTO") {
                style = NcStyle::FeedSpeedTool;
            } else if ((word == "DL" || word == "DR") && valueNext && j + 1 < n && isDigit(s[j + 1])) {
                j = signedValueEnd(j);  // tool oversizes in TOOL CALL
                style = NcStyle::FeedSpeedTool;
            } else if (word == "DR" && (next == '+' || next == '-')) {
                ++j;  // arc direction
                style = NcStyle::Keyword;
            } else if (word == "R" && next == '0' && !(j + 1 < n && (isDigit(s[j + 1]) || s[j + 1] == '.'))) {
                ++j;  // R0: no radius compensation
                style = NcStyle::Keyword;
            } else if (word == "RL" || word == "RR") {
                style = NcStyle::Keyword;
            } else if (std::find(kAxisWords.begin(), kAxisWords.end(), word) != kAxisWords.end() &&
                       (valueNext || !std::binary_search(kKeywords.begin(), kKeywords.end(), word))) {
                j = signedValueEnd(j);
                style = NcStyle::AxisWord;
            } else if (std::binary_search(kKeywords.begin(), kKeywords.end(), word)) {
                style = NcStyle::Keyword;
                if (word == "CYCL")
                    cycleContext = true;
                programName = word == "PGM";
            } else if (cycleContext) {
                style = NcStyle::Keyword;  // the cycle's name: BOHREN, DRILLING, DATUM SHIFT
            }
        } else if (isDigit(c) || (c == '.' && j < n && isDigit(s[j])) ||
                   (valueAllowed && (c == '+' || c == '-') && j < n && (isDigit(s[j]) || s[j] == '.'))) {
            j = signedValueEnd(i);
            style = NcStyle::Number;
        }
        valueAllowed = c == '=' || c == '(' || c == ',';
        emitRun(j - i, style);
        i = j;
    }
}

}  // namespace camwb::gui
