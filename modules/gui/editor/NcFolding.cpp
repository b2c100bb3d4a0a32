// Fold levels of NC programs from the keywords of each line: PROC ... M17/RET, IF/ELSE/ENDIF,
// WHILE, FOR, REPEAT/UNTIL, LOOP (Sinumerik); O-word sub/if/while/do/repeat and Fanuc DOn/ENDn
// (ISO); LBL n ... LBL 0 (Heidenhain). The state fits Scintilla's per-line integer.
#include "gui/editor/detail/DialectLexers.h"

#include <algorithm>
#include <cctype>

namespace camwb::gui {

namespace {

constexpr int kMaxDepth = 255;
// Scintilla's SC_FOLDLEVELBASE and SC_FOLDLEVELHEADERFLAG (stable parts of its API), so this file
// stays free of QScintilla.
constexpr int kFoldLevelBase = 0x400;
constexpr int kFoldHeaderFlag = 0x2000;

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool isCodeToken(const FoldToken& t) { return t.style == NcStyle::Keyword || t.style == NcStyle::MWord; }

// How the line changes the depth: opens, closes, or both at once (ELSE, a second LBL).
struct FoldStep {
    int closes = 0;
    int opens = 0;
    bool middle = false;  // ELSE-like: the line heads the second part of the fold it is in
};

FoldStep sinumerikStep(const std::vector<FoldToken>& tokens, FoldState& state)
{
    FoldStep step;
    const bool hasGoto = std::any_of(tokens.begin(), tokens.end(), [](const FoldToken& t) {
        return t.style == NcStyle::Keyword && startsWith(t.text, "GOTO");
    });
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const FoldToken& t = tokens[k];
        if (!isCodeToken(t))
            continue;
        const std::string& w = t.text;
        const bool lastCode = std::none_of(tokens.begin() + long(k) + 1, tokens.end(), isCodeToken);
        if (w == "PROC") {
            ++step.opens;
            state.inProc = true;
        } else if ((w == "IF" && !hasGoto) || w == "WHILE" || w == "FOR" || w == "LOOP") {
            ++step.opens;
        } else if (w == "REPEAT" && lastCode && k + 1 == tokens.size()) {
            ++step.opens;  // REPEAT ... UNTIL; "REPEAT LABEL1 LABEL2 P=3" repeats a section in one line
        } else if (w == "ELSE") {
            step.middle = true;
        } else if (w == "ENDIF" || w == "ENDWHILE" || w == "ENDFOR" || w == "UNTIL" || w == "ENDLOOP") {
            if (step.opens > 0)
                --step.opens;
            else
                ++step.closes;
        } else if (state.inProc && (w == "M17" || w == "RET" || w == "M2" || w == "M02" || w == "M30") &&
                   state.depth - step.closes + step.opens == 1) {
            ++step.closes;  // the PROC's end, not a RET inside an IF
            state.inProc = false;
        }
    }
    return step;
}

FoldStep isoStep(const std::vector<FoldToken>& tokens, FoldState& state)
{
    FoldStep step;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string& w = tokens[k].text;
        if (tokens[k].style != NcStyle::Keyword)
            continue;
        // Fanuc macro B: WHILE [...] DO1 ... END1.
        if (w.size() > 2 && startsWith(w, "DO") && std::isdigit(static_cast<unsigned char>(w[2]))) {
            ++step.opens;
            continue;
        }
        if (w.size() > 3 && startsWith(w, "END") && std::isdigit(static_cast<unsigned char>(w[3]))) {
            ++step.closes;
            continue;
        }
        // LinuxCNC: o100 sub / endsub, if / elseif / else / endif, while / endwhile, do ... while,
        // repeat / endrepeat: the word right after the O-word decides.
        const bool oWord =
            w.size() > 1 && w[0] == 'O' && (std::isdigit(static_cast<unsigned char>(w[1])) || w[1] == '<');
        if (!oWord || k + 1 >= tokens.size())
            continue;
        const std::string& verb = tokens[k + 1].text;
        const int depthBefore = state.depth;
        if (verb == "SUB" || verb == "IF" || verb == "REPEAT") {
            ++step.opens;
        } else if (verb == "DO") {
            ++step.opens;
            if (depthBefore < 16)
                state.doMask = std::uint16_t(state.doMask | (1u << depthBefore));
        } else if (verb == "WHILE") {
            if (depthBefore > 0 && depthBefore <= 16 && (state.doMask & (1u << (depthBefore - 1))) != 0) {
                ++step.closes;  // the "while" that ends a do loop
                state.doMask = std::uint16_t(state.doMask & ~(1u << (depthBefore - 1)));
            } else {
                ++step.opens;
            }
        } else if (verb == "ELSE" || verb == "ELSEIF") {
            step.middle = true;
        } else if (verb == "ENDSUB" || verb == "ENDIF" || verb == "ENDWHILE" || verb == "ENDREPEAT") {
            ++step.closes;
        }
        ++k;
    }
    return step;
}

FoldStep heidenhainStep(const std::vector<FoldToken>& tokens, FoldState& state)
{
    FoldStep step;
    if (tokens.empty())
        return step;
    const std::string& first = tokens[0].text;
    if (first == "LBL" && tokens[0].style == NcStyle::Keyword) {
        // A label definition; CALL LBL and GOTO LBL have another word first.
        const bool zero = tokens.size() > 1 && tokens[1].style == NcStyle::Number && tokens[1].text == "0";
        if (zero) {
            if (state.inLabel)
                ++step.closes;
            state.inLabel = false;
        } else if (state.inLabel) {
            step.middle = true;  // labels do not nest: the next one ends the previous section
        } else {
            ++step.opens;
            state.inLabel = true;
        }
    } else if (first == "END" && tokens.size() > 1 && tokens[1].text == "PGM") {
        step.closes = state.depth;
        state.inLabel = false;
    }
    return step;
}

}  // namespace

int FoldState::pack() const
{
    return std::clamp(depth, 0, kMaxDepth) | (inProc ? 1 << 8 : 0) | (inLabel ? 1 << 9 : 0) |
           (continues ? 1 << 10 : 0) | (int(doMask) << 16);
}

FoldState FoldState::unpack(int state)
{
    FoldState s;
    s.depth = state & 0xff;
    s.inProc = (state & (1 << 8)) != 0;
    s.inLabel = (state & (1 << 9)) != 0;
    s.continues = (state & (1 << 10)) != 0;
    s.doMask = std::uint16_t((unsigned(state) >> 16) & 0xffffu);
    return s;
}

int foldLevel(nc::Dialect dialect, const std::vector<FoldToken>& tokens, bool lineEndsWithTilde, FoldState& state)
{
    FoldStep step;
    switch (dialect) {
    case nc::Dialect::Sinumerik:
        step = sinumerikStep(tokens, state);
        break;
    case nc::Dialect::Iso:
        step = isoStep(tokens, state);
        break;
    case nc::Dialect::Heidenhain:
        step = heidenhainStep(tokens, state);
        break;
    }
    state.continues = lineEndsWithTilde;
    const int before = state.depth;
    // A closing line belongs to the fold it closes: its level is the depth before it.
    int level = kFoldLevelBase + before;
    int after = std::clamp(before - step.closes, 0, kMaxDepth);
    if (step.middle && after > 0) {
        level = kFoldLevelBase + (after - 1);
        level |= kFoldHeaderFlag;
    } else if (step.opens > 0) {
        level = kFoldLevelBase + after;
        level |= kFoldHeaderFlag;
    }
    after = std::clamp(after + step.opens, 0, kMaxDepth);
    state.depth = after;
    return level;
}

}  // namespace camwb::gui
