#include "gui/editor/detail/SinumerikLexer.h"

#include <Qsci/qsciscintilla.h>

#include <QByteArray>
#include <QFontDatabase>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace camwb::gui {

namespace {

// Sorted (binary search). Control flow, declarations, frames, contour and arc words, motion
// modifiers and the common functions a Sinumerik program uses.
constexpr std::array<std::string_view, 92> kKeywords{
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

// Standard and ShopMill cycles all start with one of these.
constexpr std::array<std::string_view, 6> kCyclePrefixes{"CYCLE", "POCKET", "SLOT", "LONGHOLE", "HOLES", "E_"};

static_assert(std::is_sorted(kKeywords.begin(), kKeywords.end()), "kKeywords must stay sorted and full");

bool isKeyword(std::string_view upper)
{
    if (std::binary_search(kKeywords.begin(), kKeywords.end(), upper))
        return true;
    return std::any_of(kCyclePrefixes.begin(), kCyclePrefixes.end(), [upper](std::string_view p) {
        return upper.size() > p.size() && upper.substr(0, p.size()) == p;
    });
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAlpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isIdent(char c) { return isAlpha(c) || isDigit(c) || c == '$'; }
char upper(char c) { return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c; }

NcStyle addressStyle(char letter)
{
    switch (upper(letter)) {
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

}  // namespace

SinumerikLexer::SinumerikLexer(QObject* parent) :
    QsciLexerCustom(parent),
    m_font(QFontDatabase::systemFont(QFontDatabase::FixedFont))
{
    setDefaultFont(m_font);
    setDefaultPaper(Qt::white);
    setDefaultColor(Qt::black);
}

const char* SinumerikLexer::language() const { return "Sinumerik"; }

QString SinumerikLexer::description(int style) const
{
    // QScintilla enumerates styles until the description is empty.
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Default:
        return tr("Default");
    case NcStyle::Comment:
        return tr("Comment");
    case NcStyle::BlockNumber:
        return tr("Block number");
    case NcStyle::GWord:
        return tr("G word");
    case NcStyle::MWord:
        return tr("M word");
    case NcStyle::AxisWord:
        return tr("Axis word");
    case NcStyle::FeedSpeedTool:
        return tr("Feed, speed, tool");
    case NcStyle::Keyword:
        return tr("Keyword or cycle");
    case NcStyle::Number:
        return tr("Number");
    case NcStyle::String:
        return tr("String");
    case NcStyle::Parameter:
        return tr("Parameter");
    case NcStyle::Count:
        break;
    }
    return {};
}

QColor SinumerikLexer::defaultColor(int style) const
{
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Comment:
        return QColor(96, 128, 96);
    case NcStyle::BlockNumber:
        return QColor(128, 128, 150);
    case NcStyle::GWord:
        return QColor(0, 70, 200);
    case NcStyle::MWord:
        return QColor(170, 0, 140);
    case NcStyle::AxisWord:
        return QColor(150, 40, 20);
    case NcStyle::FeedSpeedTool:
        return QColor(190, 100, 0);
    case NcStyle::Keyword:
        return QColor(110, 30, 170);
    case NcStyle::Number:
        return QColor(0, 120, 120);
    case NcStyle::String:
        return QColor(130, 90, 0);
    case NcStyle::Parameter:
        return QColor(0, 110, 170);
    default:
        return QColor(20, 20, 20);
    }
}

QFont SinumerikLexer::defaultFont(int style) const
{
    QFont font = m_font;
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Comment:
        font.setItalic(true);
        break;
    case NcStyle::GWord:
    case NcStyle::Keyword:
        font.setBold(true);
        break;
    default:
        break;
    }
    return font;
}

QColor SinumerikLexer::defaultPaper(int) const { return Qt::white; }

void SinumerikLexer::lex(const char* s, int n, const std::function<void(int, NcStyle)>& emitRun)
{
    int i = 0;
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
        if (from + 2 < n && upper(s[from]) == 'E' && upper(s[from + 1]) == 'X' &&
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
        } else if (c == '"') {
            while (j < n && s[j] != '"' && s[j] != '\n' && s[j] != '\r')
                ++j;
            if (j < n && s[j] == '"')
                ++j;
            style = NcStyle::String;
            blockStart = false;
        } else if (blockStart && c == '/') {
            if (j < n && isDigit(s[j]))
                ++j;  // skip level /0../9
        } else if (blockStart && (upper(c) == 'N' || c == ':') && j < n && isDigit(s[j])) {
            while (j < n && isDigit(s[j]))
                ++j;
            style = NcStyle::BlockNumber;
            blockStart = false;
        } else if (isAlpha(c) || c == '$') {
            blockStart = false;
            const bool addressWord = isAlpha(c) && c != '_' && (j >= n || !isIdent(s[j]) || isDigit(s[j]));
            if (addressWord) {
                // Letter [=] [sign] number: G1, X-10.5, Z=-2. "X=IC(5)" styles "X=" here and IC next.
                style = addressStyle(c);
                if (j < n && s[j] == '=')
                    ++j;
                if (j + 1 < n && (s[j] == '-' || s[j] == '+') && (isDigit(s[j + 1]) || s[j + 1] == '.'))
                    ++j;
                j = numberEnd(j);
            } else {
                while (j < n && isIdent(s[j]))
                    ++j;
                std::string word(static_cast<std::size_t>(j - i), ' ');
                std::transform(s + i, s + j, word.begin(), upper);
                if (c == '$')
                    style = NcStyle::Parameter;
                else if (isKeyword(word))
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

void SinumerikLexer::styleText(int start, int end)
{
    QsciScintilla* sci = editor();
    if (sci == nullptr || end <= start)
        return;
    // Always restart at a line start: block numbers are recognised only there.
    const long line = sci->SendScintilla(QsciScintillaBase::SCI_LINEFROMPOSITION, static_cast<unsigned long>(start));
    start =
        static_cast<int>(sci->SendScintilla(QsciScintillaBase::SCI_POSITIONFROMLINE, static_cast<unsigned long>(line)));
    QByteArray bytes(end - start + 1, '\0');
    sci->SendScintilla(QsciScintillaBase::SCI_GETTEXTRANGE, start, end, bytes.data());
    startStyling(start);
    lex(bytes.constData(), end - start,
        [this](int length, NcStyle style) { setStyling(length, static_cast<int>(style)); });
}

}  // namespace camwb::gui
