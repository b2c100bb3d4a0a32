// Sinumerik and plain ISO share the word-address syntax (letter, value); they differ in comments,
// parameters, keywords and a few letters. One scanner, a syntax table per dialect.
#include "gui/editor/detail/DialectLexers.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <string_view>

namespace camwb::gui {

namespace {

// Sorted (binary search). Control flow, declarations, frames, contour and arc words, motion
// modifiers and the common functions a Sinumerik program uses.
constexpr std::array<std::string_view, 92> kSinumerikKeywords{
    "ABS",        "AC",      "ACN",     "ACOS",    "ACP",     "AMIRROR", "AND",    "AP",     "AR",      "AROT",
    "AROTS",      "ASCALE",  "ASIN",    "ATAN2",   "ATRANS",  "AXIS",    "BOOL",   "CALL",   "CASE",    "CFC",
    "CFIN",       "CFTCP",   "CHAR",    "CHF",     "CHR",     "CIP",     "COS",    "CR",     "CT",      "DC",
    "DEF",        "DEFAULT", "DISPLOF", "DISPLON", "DIV",     "ELSE",    "ENDFOR", "ENDIF",  "ENDLOOP", "ENDWHILE",
    "EXECSTRING", "EXTCALL", "FOR",     "FRAME",   "GOTO",    "GOTOB",   "GOTOC",  "GOTOF",  "IC",      "IF",
    "INT",        "LOOP",    "MCALL",   "MIRROR",  "MOD",     "MSG",     "NOT",    "OF",     "OR",      "ORIAXES",
    "ORIVECT",    "ORIWKS",  "PAROT",   "PAROTOF", "POT",     "PROC",    "REAL",   "REPEAT", "RET",     "RND",
    "RNDM",       "ROT",     "ROUND",   "RP",      "SAVE",    "SCALE",   "SIN",    "SQRT",   "STOPRE",  "STRING",
    "SUPA",       "TAN",     "TCARR",   "TO",      "TRAFOOF", "TRANS",   "TRAORI", "TRUNC",  "TURN",    "UNTIL",
    "WHILE",      "XOR"};
static_assert(std::is_sorted(kSinumerikKeywords.begin(), kSinumerikKeywords.end()), "keep sorted");

// Standard and ShopMill cycles all start with one of these.
constexpr std::array<std::string_view, 6> kCyclePrefixes{"CYCLE", "POCKET", "SLOT", "LONGHOLE", "HOLES", "E_"};

// LinuxCNC O-word control flow and expression functions, Fanuc macro B words (linear search:
// only words of two letters or more get here).
constexpr std::array<std::string_view, 43> kIsoKeywords{
    "ABS",    "ACOS",   "AND",   "ASIN",      "ATAN",   "BREAK",    "CALL", "CONTINUE", "COS",   "DO",  "ELSE",
    "ELSEIF", "END",    "ENDIF", "ENDREPEAT", "ENDSUB", "ENDWHILE", "EQ",   "EXISTS",   "EXP",   "FIX", "FUP",
    "GE",     "GOTO",   "GT",    "IF",        "LE",     "LN",       "LT",   "MOD",      "NE",    "OR",  "POP",
    "REPEAT", "RETURN", "ROUND", "SIN",       "SQRT",   "SUB",      "TAN",  "THEN",     "WHILE", "XOR"};

using lexchar::isDigit;
using lexchar::isLetter;
using lexchar::upper;
bool isIdent(char c) { return isLetter(c) || isDigit(c) || c == '$'; }

bool isSinumerikKeyword(std::string_view word)
{
    if (std::binary_search(kSinumerikKeywords.begin(), kSinumerikKeywords.end(), word))
        return true;
    return std::any_of(kCyclePrefixes.begin(), kCyclePrefixes.end(),
                       [word](std::string_view p) { return word.size() > p.size() && word.substr(0, p.size()) == p; });
}

bool isIsoKeyword(std::string_view word)
{
    if (std::find(kIsoKeywords.begin(), kIsoKeywords.end(), word) != kIsoKeywords.end())
        return true;
    // Fanuc DO1 / END1 loop pairs, GOTO10 without a blank.
    for (std::string_view prefix : {std::string_view("DO"), std::string_view("END"), std::string_view("GOTO")}) {
        if (word.size() > prefix.size() && word.substr(0, prefix.size()) == prefix &&
            std::all_of(word.begin() + long(prefix.size()), word.end(), isDigit))
            return true;
    }
    return false;
}

struct Syntax {
    bool iso = false;
    NcStyle (*letterStyle)(char upperLetter) = nullptr;
};

NcStyle sinumerikLetter(char c)
{
    switch (c) {
    case 'G':
        return NcStyle::GWord;
    case 'M':
        return NcStyle::MWord;
    case 'X':
    case 'Y':
    case 'Z':
    case 'A':
    case 'B':
    case 'C':
    case 'I':
    case 'J':
    case 'K':
        return NcStyle::AxisWord;
    case 'F':
    case 'S':
    case 'T':
    case 'D':
        return NcStyle::FeedSpeedTool;
    case 'R':
        return NcStyle::Parameter;
    case 'N':
        return NcStyle::BlockNumber;
    default:
        return NcStyle::Default;
    }
}

NcStyle isoLetter(char c)
{
    switch (c) {
    case 'G':
        return NcStyle::GWord;
    case 'M':
        return NcStyle::MWord;
    case 'X':
    case 'Y':
    case 'Z':
    case 'A':
    case 'B':
    case 'C':
    case 'U':
    case 'V':
    case 'W':
    case 'I':
    case 'J':
    case 'K':
    case 'R':
        return NcStyle::AxisWord;
    case 'F':
    case 'S':
    case 'T':
    case 'D':
    case 'H':
        return NcStyle::FeedSpeedTool;
    case 'O':
        return NcStyle::Keyword;  // O-word: program number, LinuxCNC o100 sub / if / while
    case 'N':
        return NcStyle::BlockNumber;
    default:
        return NcStyle::Default;  // P, Q, L, E: cycle and call arguments
    }
}

// ISO canned cycles G73-G89 (with G80 to cancel) read as cycles, not as motion modes.
bool isIsoCycle(const char* s, int from, int to)
{
    int value = 0;
    int digits = 0;
    for (int k = from; k < to && isDigit(s[k]); ++k, ++digits)
        value = value * 10 + (s[k] - '0');
    return digits > 0 && digits <= 2 && (value == 73 || value == 74 || value == 76 || (value >= 80 && value <= 89));
}

void lexWordAddress(const Syntax& syntax, const char* s, int n, char* styles)
{
    int i = 0;
    auto emitRun = [&](int length, NcStyle style) {
        std::memset(styles + i, static_cast<int>(style), std::size_t(length));
    };
    bool blockStart = true;  // only whitespace and skip levels seen on this line so far
    auto lineEnd = [&](int from) {
        while (from < n && s[from] != '\n' && s[from] != '\r')
            ++from;
        return from;
    };
    auto numberEnd = [&](int from) {
        while (from < n && (isDigit(s[from]) || s[from] == '.'))
            ++from;
        // Sinumerik exponent: 1.5EX-3
        if (!syntax.iso && from + 2 < n && upper(s[from]) == 'E' && upper(s[from + 1]) == 'X' &&
            (isDigit(s[from + 2]) || s[from + 2] == '-' || s[from + 2] == '+')) {
            from += 3;
            while (from < n && isDigit(s[from]))
                ++from;
        }
        return from;
    };

    while (i < n) {
        const char c = s[i];
        int j = i + 1;
        NcStyle style = NcStyle::Default;
        if (c == '\n' || c == '\r') {
            blockStart = true;
        } else if (c == ' ' || c == '\t') {
            while (j < n && (s[j] == ' ' || s[j] == '\t'))
                ++j;
        } else if (c == ';') {
            j = lineEnd(i);
            style = NcStyle::Comment;
        } else if (syntax.iso && c == '(') {
            while (j < n && s[j] != ')' && s[j] != '\n' && s[j] != '\r')
                ++j;
            if (j < n && s[j] == ')')
                ++j;
            style = NcStyle::Comment;
        } else if (syntax.iso && c == '%' && blockStart) {
            j = lineEnd(i);
            style = NcStyle::Keyword;
        } else if (syntax.iso && c == '#') {
            // #12, #<_name>, ##1
            while (j < n && s[j] == '#')
                ++j;
            if (j < n && s[j] == '<') {
                while (j < n && s[j] != '>' && s[j] != '\n' && s[j] != '\r')
                    ++j;
                if (j < n && s[j] == '>')
                    ++j;
            } else {
                while (j < n && isDigit(s[j]))
                    ++j;
            }
            style = NcStyle::Parameter;
            blockStart = false;
        } else if (!syntax.iso && c == '"') {
            while (j < n && s[j] != '"' && s[j] != '\n' && s[j] != '\r')
                ++j;
            if (j < n && s[j] == '"')
                ++j;
            style = NcStyle::String;
            blockStart = false;
        } else if (blockStart && c == '/') {
            if (j < n && isDigit(s[j]))
                ++j;  // skip level /0../9
        } else if (blockStart && (upper(c) == 'N' || (!syntax.iso && c == ':')) && j < n && isDigit(s[j])) {
            while (j < n && isDigit(s[j]))
                ++j;
            style = NcStyle::BlockNumber;
            blockStart = false;
        } else if (isLetter(c) || (!syntax.iso && c == '$')) {
            blockStart = false;
            const bool oName = syntax.iso && upper(c) == 'O' && j < n && s[j] == '<';
            // Sinumerik names may be one letter (FOR I = 1 TO 3): a letter is an address only with
            // a value after it. ISO (LinuxCNC, Fanuc) allows blanks inside words: any lone letter.
            const char next = j < n ? s[j] : '\0';
            const bool valueNext = isDigit(next) || next == '=' || next == '.' || next == '-' || next == '+';
            const bool addressWord =
                isLetter(c) && c != '_' && (isDigit(next) || (syntax.iso ? !isIdent(next) : valueNext));
            if (oName) {
                while (j < n && s[j] != '>' && s[j] != '\n' && s[j] != '\r')
                    ++j;
                if (j < n && s[j] == '>')
                    ++j;
                style = NcStyle::Keyword;
            } else if (addressWord) {
                // Letter [=] [sign] number: G1, X-10.5, Z=-2. "X=IC(5)" styles "X=" here and IC next.
                style = syntax.letterStyle(upper(c));
                if (j < n && s[j] == '=' && !syntax.iso)
                    ++j;
                if (j + 1 < n && (s[j] == '-' || s[j] == '+') && (isDigit(s[j + 1]) || s[j + 1] == '.'))
                    ++j;
                const int valueBegin = j;
                j = numberEnd(j);
                if (syntax.iso && style == NcStyle::GWord && isIsoCycle(s, valueBegin, j))
                    style = NcStyle::Keyword;
            } else {
                while (j < n && isIdent(s[j]))
                    ++j;
                std::string word(static_cast<std::size_t>(j - i), ' ');
                std::transform(s + i, s + j, word.begin(), upper);
                if (c == '$')
                    style = NcStyle::Parameter;
                else if (syntax.iso ? isIsoKeyword(word) : isSinumerikKeyword(word))
                    style = NcStyle::Keyword;
            }
        } else if (isDigit(c) || (c == '.' && j < n && isDigit(s[j]))) {
            j = numberEnd(i);
            style = NcStyle::Number;
            blockStart = false;
        } else {
            blockStart = false;  // operators, brackets, non-ASCII bytes
        }
        emitRun(j - i, style);
        i = j;
    }
}

}  // namespace

void lexSinumerik(const char* text, int length, char* styles)
{
    lexWordAddress({false, sinumerikLetter}, text, length, styles);
}

void lexIso(const char* text, int length, char* styles) { lexWordAddress({true, isoLetter}, text, length, styles); }

void lexDialect(nc::Dialect dialect, const char* text, int length, bool continuation, char* styles)
{
    switch (dialect) {
    case nc::Dialect::Sinumerik:
        lexSinumerik(text, length, styles);
        return;
    case nc::Dialect::Iso:
        lexIso(text, length, styles);
        return;
    case nc::Dialect::Heidenhain:
        lexHeidenhain(text, length, continuation, styles);
        return;
    }
}

}  // namespace camwb::gui
