// The pure part of the NC editor's highlighting, one function per dialect: style bytes for text
// that starts at a line start (one NcStyle per byte, written straight into the buffer Scintilla
// takes), and fold levels from a line's keywords. No QScintilla here, so the lexers run on any
// byte range (Scintilla asks for the visible ones) and a benchmark can call them.
#pragma once

#include "gui/editor/NcStyles.h"
#include "nc/Dialect.h"
#include "toolpath/ClFormat.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::gui {

// The character classes every lexer here reads by (NC and CL text is ASCII; other bytes are none).
namespace lexchar {
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }
inline bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
inline char upper(char c) { return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c; }
}  // namespace lexchar

// Sinumerik 828D/840D: ';' comments, "strings", N/: block numbers, R parameters, $ variables,
// keywords and cycles (CYCLE81, POCKET3, MCALL), letter [=] value address words.
void lexSinumerik(const char* text, int length, char* styles);
// Plain ISO (LinuxCNC / Fanuc): '(' and ';' comments, '%', N numbers, #n / #<name> parameters,
// O-words and control flow, [expressions], canned cycles G73-G89 as keywords.
void lexIso(const char* text, int length, char* styles);
// Heidenhain Klartext: leading block numbers, ';' and '*' comments, L/C/CC/CR/CP/... path words,
// signed axis words (X+10, IX-5, PA+30), Q parameters, CYCL DEF/CALL, LBL, FN, M, F/FMAX/S, R0/RL/RR.
// `continuation`: the range starts on a line that continues the block above (it ended in '~').
void lexHeidenhain(const char* text, int length, bool continuation, char* styles);

void lexDialect(nc::Dialect dialect, const char* text, int length, bool continuation, char* styles);

// CL files (ClLexers.cpp). APT CL source: "$$" comments, major words (the statement's first, and any
// before a '/') as keywords, minor words (ON, MMPM) as parameters, numbers, PARTNO/PPRINT text as
// strings; `continuation`: the range starts on a line the one above continues (it ended in '$').
void lexApt(const char* text, int length, bool continuation, char* styles);
// FreeCAD path dump: "(...)" comments, "Command", G and M codes, "X:10" parameters by letter.
void lexFreeCadDump(const char* text, int length, char* styles);
// Our trace: the record's kind as a keyword, numbers, "strings", key words, '#' comment lines.
void lexClTrace(const char* text, int length, char* styles);
void lexClFormat(toolpath::ClFormat format, const char* text, int length, bool continuation, char* styles);

// What the fold computation needs to carry from one line to the next (Scintilla's line state).
struct FoldState {
    int depth = 0;
    bool inProc = false;       // Sinumerik: inside PROC (M17/RET at depth 1 closes it)
    bool inLabel = false;      // Heidenhain: inside LBL n (LBL 0 or the next LBL closes it)
    bool continues = false;    // Heidenhain: the line ended in '~'
    std::uint16_t doMask = 0;  // ISO: bit d set when the fold at depth d was opened by "do"

    int pack() const;
    static FoldState unpack(int state);
};

// A styled word of a line that folding looks at (keywords, M words, numbers, strings), upper case.
struct FoldToken {
    std::string text;
    NcStyle style = NcStyle::Default;
};

// The line's Scintilla fold level (SC_FOLDLEVELBASE + depth, header flag when it opens a fold)
// given the state after the previous line; updates the state for the next line.
int foldLevel(nc::Dialect dialect, const std::vector<FoldToken>& tokens, bool lineEndsWithTilde, FoldState& state);

}  // namespace camwb::gui
