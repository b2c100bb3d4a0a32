#include "nc/iso/IsoScanner.h"

#include "nc/iso/IsoNumber.h"

#include <cmath>
#include <cstring>

namespace camwb::nc::iso {

namespace {

constexpr int kMaxAssignments = 50;   // RS274NGC's limit of parameter settings per line
constexpr double kValueLimit = 1e15;  // larger word values are typing errors, not coordinates

char upper(char c) { return static_cast<char>(c & ~0x20); }

struct KeywordName {
    const char* text;
    OKeyword keyword;
};
constexpr KeywordName kKeywords[] = {
    {"sub", OKeyword::Sub},
    {"endsub", OKeyword::EndSub},
    {"call", OKeyword::Call},
    {"return", OKeyword::Return},
    {"do", OKeyword::Do},
    {"while", OKeyword::While},
    {"endwhile", OKeyword::EndWhile},
    {"if", OKeyword::If},
    {"elseif", OKeyword::ElseIf},
    {"else", OKeyword::Else},
    {"endif", OKeyword::EndIf},
    {"repeat", OKeyword::Repeat},
    {"endrepeat", OKeyword::EndRepeat},
    {"break", OKeyword::Break},
    {"continue", OKeyword::Continue},
};

// The label and keyword of an O-word whose 'O' is at p; p moves past the keyword. False when
// there is none (the caller says why when it matters).
enum class OParse { Ok, BadLabel, BadKeyword, NoKeyword };
OParse parseOHead(const char*& p, const char* end, std::string& label, OKeyword& keyword)
{
    ++p;  // the O
    while (p < end && isBlank(*p))
        ++p;
    label.clear();
    if (p < end && *p == '<') {
        ++p;
        while (p < end && *p != '>') {
            if (!isBlank(*p))
                label += (*p >= 'A' && *p <= 'Z') ? static_cast<char>(*p + 32) : *p;
            ++p;
        }
        if (p >= end || label.empty())
            return OParse::BadLabel;
        ++p;
    } else {
        std::uint64_t number = 0;
        int digits = 0;
        while (p < end && (isDigit(*p) || isBlank(*p))) {
            if (isDigit(*p) && digits++ < 12)
                number = number * 10 + static_cast<unsigned>(*p - '0');
            ++p;
        }
        if (digits == 0 || digits > 12)
            return OParse::BadLabel;
        label = std::to_string(number);
    }
    char word[12];
    int n = 0;
    while (p < end && (isLetter(*p) || isBlank(*p))) {
        if (isLetter(*p)) {
            if (n == static_cast<int>(sizeof word) - 1)
                return OParse::BadKeyword;
            word[n++] = static_cast<char>(*p | 0x20);
        }
        ++p;
    }
    word[n] = 0;
    if (n == 0)
        return OParse::NoKeyword;
    for (const KeywordName& k : kKeywords) {
        if (std::strcmp(k.text, word) == 0) {
            keyword = k.keyword;
            return OParse::Ok;
        }
    }
    return OParse::BadKeyword;
}

// A function name (SIN, ATAN, EXISTS...) followed by '[' at p: a value, not another word.
bool isFunctionAhead(const char* p, const char* end)
{
    static constexpr const char* kFunctions[] = {"abs", "acos", "asin", "atan",  "cos", "exp",  "exists",
                                                 "fix", "fup",  "ln",   "round", "sin", "sqrt", "tan"};
    char word[8];
    int n = 0;
    while (p < end && (isLetter(*p) || isBlank(*p))) {
        if (!isBlank(*p)) {
            if (n == 7)
                return false;
            word[n++] = static_cast<char>(*p | 0x20);
        }
        ++p;
    }
    word[n] = 0;
    if (p >= end || *p != '[')
        return false;
    for (const char* f : kFunctions)
        if (std::strcmp(f, word) == 0)
            return true;
    return false;
}

}  // namespace

void LineScanner::fail(const char* at, std::string message)
{
    if (m_failed)
        return;
    m_failed = true;
    m_reporter.error(m_line, columnOf(at), std::move(message));
}

void LineScanner::scan(std::string_view line, int lineNumber, Block& block)
{
    block.clear();
    m_begin = line.data();
    m_p = m_begin;
    m_end = m_begin + line.size();
    m_line = lineNumber;
    m_failed = false;
    m_depth = 0;
    skipBlanks();
    if (m_p < m_end && *m_p == '/') {
        block.blockDelete = true;
        ++m_p;
    }
    while (!m_failed) {
        skipBlanks();
        if (m_p >= m_end)
            break;
        const char c = *m_p;
        if (isLetter(c)) {
            if (upper(c) == 'O') {
                readOWord(block);
                break;
            }
            ++m_p;
            readWord(upper(c), block);
        } else if (c == '(') {
            readComment(block);
        } else if (c == ';') {
            break;  // the rest of the line is a comment
        } else if (c == '#') {
            readAssignment(block);
        } else if (c == ')') {
            fail(m_p, "')' without '(' before it");
        } else if (c == '[' || c == ']') {
            fail(m_p, std::string("'") + c + "' outside a word: an expression belongs after a letter or '='");
        } else {
            const unsigned char u = static_cast<unsigned char>(c);
            fail(m_p, u >= 0x20 && u < 0x7f ? std::string("unexpected character '") + c + "'"
                                            : "unexpected character (byte " + std::to_string(u) + ")");
        }
    }
    if (m_failed)
        block.error = true;
}

bool LineScanner::readWord(char letter, Block& block)
{
    const char* at = m_p - 1;
    double v = 0;
    // The common case inline: a plain number right after the letter.
    skipBlanks();
    const char* start = m_p;
    bool negative = false;
    if (m_p < m_end && (*m_p == '-' || *m_p == '+')) {
        negative = *m_p == '-';
        ++m_p;
        skipBlanks();
    }
    if (m_p < m_end && (isDigit(*m_p) || *m_p == '.')) {
        const NumberStatus status = scanUnsigned(m_p, m_end, v);
        if (status != NumberStatus::Ok) {
            fail(start,
                 status == NumberStatus::TooLong ? "number too long" : "missing value after " + std::string(1, letter));
            return false;
        }
        if (m_p < m_end && *m_p == '.') {
            // X1.2.3: LinuxCNC refuses the number ("bad number format"), so does the trace.
            const char* stop = m_p;
            while (stop < m_end && (isDigit(*stop) || *stop == '.'))
                ++stop;
            fail(start, "malformed number " + std::string(start, stop) + " after " + std::string(1, letter));
            return false;
        }
        if (negative)
            v = -v;
    } else {
        m_p = start;
        if (m_p >= m_end) {
            fail(at, std::string("missing value after ") + letter);
            return false;
        }
        if (isLetter(*m_p) && !isFunctionAhead(m_p, m_end)) {
            std::string word(1, letter);
            for (const char* q = m_p; q < m_end && (isLetter(*q) || isBlank(*q)) && word.size() < 24; ++q)
                if (!isBlank(*q))
                    word += upper(*q);
            fail(at, "unknown word " + word + " (a letter and a number expected)");
            return false;
        }
        if (!readValue(v))
            return false;
    }
    if (!std::isfinite(v) || std::abs(v) >= kValueLimit) {
        fail(start, std::string("value of ") + letter + " is out of range");
        return false;
    }
    switch (letter) {
    case 'G':
    case 'M': {
        int& count = letter == 'G' ? block.gCount : block.mCount;
        Code* codes = letter == 'G' ? block.g : block.m;
        if (count >= kMaxCodesPerBlock) {
            fail(at, std::string("too many ") + letter + " words in one block");
            return false;
        }
        const double tenths = v * 10;
        const long long rounded = v < 0 ? -1 : static_cast<long long>(tenths + 0.5);  // |v| < 1e15: fits
        if (v < 0 || std::abs(tenths - static_cast<double>(rounded)) > 1e-3 || (letter == 'M' && rounded % 10 != 0)) {
            fail(at, std::string(1, letter) + " number must be " +
                         (letter == 'G' ? "positive with at most one decimal" : "a positive integer"));
            return false;
        }
        codes[count++] = Code{static_cast<int>(rounded), columnOf(at)};
        return true;
    }
    case 'N':
        return true;  // block numbers do nothing
    case 'E':
        fail(at, "unknown word E (LinuxCNC has no E word)");
        return false;
    default: {
        const std::uint32_t bit = 1u << (letter - 'A');
        if (block.present & bit) {
            fail(at, std::string("word ") + letter + " given twice in one block");
            return false;
        }
        block.present |= bit;
        block.value[letter - 'A'] = v;
        block.column[letter - 'A'] = columnOf(at);
        return true;
    }
    }
}

bool LineScanner::readComment(Block& block)
{
    const char* open = m_p++;
    const char* text = m_p;
    while (m_p < m_end && *m_p != ')') {
        if (*m_p == '(') {
            fail(m_p, "comments cannot nest: '(' inside a comment");
            return false;
        }
        ++m_p;
    }
    if (m_p >= m_end) {
        fail(open, "comment not closed: missing ')'");
        return false;
    }
    block.comments.emplace_back(text, static_cast<std::size_t>(m_p - text));
    ++m_p;
    return true;
}

bool LineScanner::readAssignment(Block& block)
{
    const char* at = m_p++;
    int index = -1;
    if (!readParameterIndex(index, m_name))
        return false;
    if (m_name.empty() && (index < 1 || index >= kParameterCount)) {
        fail(at, "parameter #" + std::to_string(index) + " cannot be set (1..5399)");
        return false;
    }
    skipBlanks();
    if (m_p >= m_end || *m_p != '=') {
        fail(m_p < m_end ? m_p : at, "expected '=' after the parameter");
        return false;
    }
    ++m_p;
    double v = 0;
    if (!readValue(v))
        return false;
    if (!std::isfinite(v)) {
        fail(at, "parameter value is not a finite number");
        return false;
    }
    if (block.assignmentCount >= kMaxAssignments) {
        fail(at, "more than 50 parameter assignments in one block");
        return false;
    }
    if (block.assignmentCount >= static_cast<int>(block.assignments.size()))
        block.assignments.emplace_back();
    Assignment& a = block.assignments[static_cast<std::size_t>(block.assignmentCount++)];
    a.index = m_name.empty() ? index : -1;
    a.name = m_name;
    a.value = v;
    a.column = columnOf(at);
    return true;
}

bool LineScanner::readOWord(Block& block)
{
    const char* at = m_p;
    if (block.present || block.gCount || block.mCount || block.assignmentCount) {
        fail(at, "an O-word must be the only statement on its line");
        return false;
    }
    OKeyword keyword = OKeyword::None;
    switch (parseOHead(m_p, m_end, block.oLabel, keyword)) {
    case OParse::BadLabel:
        fail(at, "O-word needs a number or a <name>");
        return false;
    case OParse::BadKeyword:
        fail(at, "unknown O-word keyword");
        return false;
    case OParse::NoKeyword:
        // Fanuc-style controls start a program with its number ("O1000"): nothing to run.
        m_reporter.warning(m_line, columnOf(at), "program number O" + block.oLabel + " ignored");
        while (m_p < m_end && !m_failed) {  // a comment may follow
            skipBlanks();
            if (m_p < m_end && *m_p == '(')
                readComment(block);
            else
                break;
        }
        if (!m_failed && m_p < m_end && *m_p != ';')
            fail(m_p, "unexpected text after the program number");
        return !m_failed;
    case OParse::Ok:
        break;
    }
    block.oKeyword = keyword;
    block.oColumn = columnOf(at);
    while (!m_failed) {
        skipBlanks();
        if (m_p >= m_end || *m_p == ';')
            break;
        if (*m_p == '(') {
            readComment(block);
        } else if (*m_p == '[') {
            double v = 0;
            if (!readBracketed(v))
                return false;
            if (block.oArguments.size() >= 64) {
                fail(m_p, "too many O-word arguments");
                return false;
            }
            block.oArguments.push_back(v);
        } else {
            fail(m_p, "expected [expression] after the O-word");
            return false;
        }
    }
    return !m_failed;
}

bool LineScanner::peekOWord(std::string_view line, std::string& label, OKeyword& keyword)
{
    const char* p = line.data();
    const char* end = p + line.size();
    while (p < end && (isBlank(*p) || *p == '/'))
        ++p;
    if (p < end && (*p == 'N' || *p == 'n')) {
        ++p;
        while (p < end && (isDigit(*p) || isBlank(*p)))
            ++p;
    }
    if (p >= end || (*p != 'O' && *p != 'o'))
        return false;
    return parseOHead(p, end, label, keyword) == OParse::Ok;
}

}  // namespace camwb::nc::iso
