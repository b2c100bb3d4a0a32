// Highlighting of the CL files the editor opens besides NC (APT CL source, FreeCAD path dumps, our
// own trace): each is a statement per line with its own words, numbers and comments, so one small
// scanner serves the three with a rule per format for what a word is.
#include "gui/editor/detail/DialectLexers.h"

#include <array>
#include <cstring>
#include <string_view>

namespace camwb::gui {

namespace {

using lexchar::isDigit;
using lexchar::isLetter;
using lexchar::upper;

// APT statements whose text after the major word is free text, not parameters.
constexpr std::array<std::string_view, 5> kAptTextWords{"INSERT", "PARTNO", "PPRINT", "TPRINT", "TITLE"};

bool equalsUpper(const char* s, int length, std::string_view word)
{
    if (length != static_cast<int>(word.size()))
        return false;
    for (int k = 0; k < length; ++k)
        if (upper(s[k]) != word[static_cast<std::size_t>(k)])
            return false;
    return true;
}

// Walks one range line by line and token by token; the format decides each token's style.
class ClScanner {
public:
    ClScanner(const char* s, int n, char* styles) : m_s(s), m_n(n), m_styles(styles) {}

    int lineEnd(int from) const
    {
        while (from < m_n && m_s[from] != '\n' && m_s[from] != '\r')
            ++from;
        return from;
    }
    // Past `close` on this line, or the line's end when it is not closed ("(comment", "\"text").
    int closedEnd(int from, char close) const
    {
        const int end = lineEnd(from);
        while (from < end && m_s[from] != close)
            ++from;
        return from < end ? from + 1 : end;
    }
    int wordEnd(int from) const
    {
        while (from < m_n && (isLetter(m_s[from]) || isDigit(m_s[from])))
            ++from;
        return from;
    }
    // [sign] digits [. digits] [E [sign] digits], or -1 when no number starts here.
    int numberEnd(int from) const
    {
        int j = from;
        if (j < m_n && (m_s[j] == '-' || m_s[j] == '+'))
            ++j;
        const int digits = j;
        while (j < m_n && (isDigit(m_s[j]) || m_s[j] == '.'))
            ++j;
        if (j == digits || (j == digits + 1 && m_s[digits] == '.'))
            return -1;
        if (j + 1 < m_n && upper(m_s[j]) == 'E' &&
            (isDigit(m_s[j + 1]) || ((m_s[j + 1] == '-' || m_s[j + 1] == '+') && j + 2 < m_n && isDigit(m_s[j + 2])))) {
            j += 2;
            while (j < m_n && isDigit(m_s[j]))
                ++j;
        }
        return j;
    }
    // The first non-blank character at or after `from` on this line ('\0' at the line's end).
    char nextOnLine(int from) const
    {
        while (from < m_n && (m_s[from] == ' ' || m_s[from] == '\t'))
            ++from;
        return from < m_n ? m_s[from] : '\0';
    }
    void style(int from, int to, NcStyle style) const
    {
        std::memset(m_styles + from, static_cast<int>(style), static_cast<std::size_t>(to - from));
    }

private:
    const char* m_s;
    int m_n;
    char* m_styles;
};

}  // namespace

void lexApt(const char* text, int length, bool continuation, char* styles)
{
    const ClScanner scan(text, length, styles);
    scan.style(0, length, NcStyle::Default);
    // A statement's first word is its major word; so is any word a '/' follows (GOTO/, a nested
    // (CIRCLE/ ...)). The others are minor words (ON, MMPM, CLW). A line ending in '$' continues.
    bool statementStart = !continuation;
    bool lineContinues = false;
    for (int i = 0; i < length;) {
        const char c = text[i];
        int j = i + 1;
        if (c == '\n' || c == '\r') {
            if (c == '\r' && j < length && text[j] == '\n')
                ++j;  // CR LF: one line end
            statementStart = statementStart || !lineContinues;
            lineContinues = false;
        } else if (c == '$' && j < length && text[j] == '$') {
            j = scan.lineEnd(i);
            scan.style(i, j, NcStyle::Comment);
        } else if (c == '$') {
            const char next = scan.nextOnLine(j);
            lineContinues = next == '\0' || next == '\n' || next == '\r';
        } else if (isLetter(c)) {
            j = scan.wordEnd(i);
            const bool major = statementStart || scan.nextOnLine(j) == '/';
            scan.style(i, j, major ? NcStyle::Keyword : NcStyle::Parameter);
            statementStart = false;
            bool freeText = false;
            for (std::string_view word : kAptTextWords)
                freeText = freeText || (major && equalsUpper(text + i, j - i, word));
            if (freeText) {
                const int end = scan.lineEnd(j);
                scan.style(j, end, NcStyle::String);
                j = end;
            }
        } else if (const int end = scan.numberEnd(i); end > i) {
            scan.style(i, end, NcStyle::Number);
            j = end;
            statementStart = false;
        } else if (c != ' ' && c != '\t') {
            statementStart = false;
        }
        i = j;
    }
}

void lexFreeCadDump(const char* text, int length, char* styles)
{
    const ClScanner scan(text, length, styles);
    scan.style(0, length, NcStyle::Default);
    // "(Path: Profile)" comments; "Command G1 [ X:10 Y:5 F:300 ]": the command word, its G or M code
    // and the parameters, each letter with its value.
    for (int i = 0; i < length;) {
        const char c = text[i];
        int j = i + 1;
        if (c == '(') {
            j = scan.closedEnd(j, ')');
            scan.style(i, j, NcStyle::Comment);
        } else if (isLetter(c)) {
            j = scan.wordEnd(i);
            const char letter = upper(c);
            if (j < length && text[j] == ':') {
                const int end = scan.numberEnd(j + 1);
                j = end > j + 1 ? end : j + 1;
                const bool axis = std::strchr("XYZABCIJK", letter) != nullptr;
                const bool feed = std::strchr("FST", letter) != nullptr;
                scan.style(i, j, axis ? NcStyle::AxisWord : feed ? NcStyle::FeedSpeedTool : NcStyle::Parameter);
            } else if ((letter == 'G' || letter == 'M') && j > i + 1 && isDigit(text[i + 1])) {
                scan.style(i, j, letter == 'G' ? NcStyle::GWord : NcStyle::MWord);
            } else {
                scan.style(i, j, NcStyle::Keyword);
            }
        } else if (const int end = scan.numberEnd(i); end > i) {
            scan.style(i, end, NcStyle::Number);
            j = end;
        }
        i = j;
    }
}

void lexClTrace(const char* text, int length, char* styles)
{
    const ClScanner scan(text, length, styles);
    scan.style(0, length, NcStyle::Default);
    // One record a line: its kind first ("rapid", "section", "tool"), then numbers, "strings" and
    // key words (d, flute, holder); '#' starts a comment line.
    bool lineStart = true;
    for (int i = 0; i < length;) {
        const char c = text[i];
        int j = i + 1;
        if (c == '\n' || c == '\r') {
            lineStart = true;
        } else if (c == '#' && lineStart) {
            j = scan.lineEnd(i);
            scan.style(i, j, NcStyle::Comment);
        } else if (c == '"') {
            j = scan.closedEnd(j, '"');
            scan.style(i, j, NcStyle::String);
            lineStart = false;
        } else if (isLetter(c)) {
            j = scan.wordEnd(i);
            scan.style(i, j, lineStart ? NcStyle::Keyword : NcStyle::Parameter);
            lineStart = false;
        } else if (const int end = scan.numberEnd(i); end > i) {
            scan.style(i, end, NcStyle::Number);
            j = end;
            lineStart = false;
        } else if (c != ' ' && c != '\t') {
            lineStart = false;
        }
        i = j;
    }
}

void lexClFormat(toolpath::ClFormat format, const char* text, int length, bool continuation, char* styles)
{
    switch (format) {
    case toolpath::ClFormat::Apt:
        lexApt(text, length, continuation, styles);
        return;
    case toolpath::ClFormat::FreeCadDump:
        lexFreeCadDump(text, length, styles);
        return;
    case toolpath::ClFormat::Trace:
        lexClTrace(text, length, styles);
        return;
    }
}

}  // namespace camwb::gui
