#include "nc/tools/BlockNumbers.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>

namespace camwb::nc {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isBlank(char c) { return c == ' ' || c == '\t'; }
bool isIdentChar(char c) { return isDigit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
char upper(char c) { return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c; }

std::size_t skipBlanks(std::string_view s, std::size_t i)
{
    while (i < s.size() && isBlank(s[i]))
        ++i;
    return i;
}

std::size_t skipDigits(std::string_view s, std::size_t i)
{
    while (i < s.size() && isDigit(s[i]))
        ++i;
    return i;
}

std::optional<long long> parseNumber(std::string_view digits)
{
    long long value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size())
        return std::nullopt;
    return value;
}

// Whether the rest of an ISO / Sinumerik line from `i` is only comments and blanks.
bool onlyComments(std::string_view s, std::size_t i, Dialect dialect)
{
    i = skipBlanks(s, i);
    if (i >= s.size())
        return false;
    while (i < s.size()) {
        if (s[i] == ';')
            return true;
        if (dialect == Dialect::Iso && s[i] == '(') {
            const std::size_t close = s.find(')', i);
            if (close == std::string_view::npos)
                return true;  // unclosed comment: still a comment line
            i = skipBlanks(s, close + 1);
            continue;
        }
        return false;
    }
    return true;
}

bool endsWithTilde(std::string_view line)
{
    std::size_t end = line.size();
    while (end > 0 && isBlank(line[end - 1]))
        --end;
    return end > 0 && line[end - 1] == '~';
}

// A line with its end of line kept apart, so the text comes back byte for byte.
struct RawLine {
    std::string_view content;
    std::string_view ending;
};

std::vector<RawLine> splitRaw(std::string_view text)
{
    std::vector<RawLine> lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t nl = text.find('\n', begin);
        std::size_t contentEnd = nl == std::string_view::npos ? text.size() : nl;
        std::size_t endingEnd = nl == std::string_view::npos ? text.size() : nl + 1;
        if (contentEnd > begin && text[contentEnd - 1] == '\r')
            --contentEnd;
        lines.push_back({text.substr(begin, contentEnd - begin), text.substr(contentEnd, endingEnd - contentEnd)});
        begin = endingEnd;
    }
    return lines;
}

std::vector<LineInfo> analyzeAll(const std::vector<RawLine>& lines, Dialect dialect)
{
    std::vector<LineInfo> infos;
    infos.reserve(lines.size());
    bool continuation = false;
    for (const RawLine& line : lines) {
        infos.push_back(analyzeLine(line.content, dialect, continuation));
        continuation = dialect == Dialect::Heidenhain && endsWithTilde(line.content);
    }
    return infos;
}

enum class JumpDirection { Forward, Backward, ForwardThenBackward };

// A GOTO whose target is a block number: where the number's digits are in the line.
struct JumpRef {
    std::size_t line = 0;
    std::size_t digitsBegin = 0;
    std::size_t digitsEnd = 0;
    long long number = 0;
    JumpDirection direction = JumpDirection::ForwardThenBackward;
    std::optional<std::size_t> target;  // line index
};

// GOTO words outside comments and strings. Sinumerik: GOTO/GOTOF/GOTOB/GOTOC N<n> (targets given
// as labels are left alone); ISO macro B: GOTO <n> or GOTO<n>.
void findJumps(std::string_view s, std::size_t lineIndex, const LineInfo& info, Dialect dialect,
               std::vector<JumpRef>& out, std::vector<RenumberNote>& notes)
{
    std::size_t i = info.removeEnd;
    while (i < s.size()) {
        const char c = s[i];
        if (c == ';')
            return;
        if (c == '"') {
            const std::size_t close = s.find('"', i + 1);
            if (close == std::string_view::npos)
                return;
            i = close + 1;
            continue;
        }
        if (dialect == Dialect::Iso && c == '(') {
            const std::size_t close = s.find(')', i + 1);
            if (close == std::string_view::npos)
                return;
            i = close + 1;
            continue;
        }
        if (!isIdentChar(c)) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < s.size() && isIdentChar(s[j]))
            ++j;
        // Only words starting with GOTO matter; look before copying (most words are G1, X10, ...).
        const bool gotoWord = j - i >= 4 && upper(s[i]) == 'G' && upper(s[i + 1]) == 'O' && upper(s[i + 2]) == 'T' &&
                              upper(s[i + 3]) == 'O';
        std::string word;
        if (gotoWord)
            for (std::size_t k = i; k < j; ++k)
                word.push_back(upper(s[k]));
        if (gotoWord) {
            JumpRef ref;
            ref.line = lineIndex;
            std::string_view suffix = std::string_view(word).substr(4);
            if (dialect == Dialect::Iso && !suffix.empty() &&
                std::all_of(suffix.begin(), suffix.end(), [](char ch) { return isDigit(ch); })) {
                ref.digitsBegin = i + 4;
                ref.digitsEnd = j;
            } else if (suffix.empty() || (dialect == Dialect::Sinumerik && suffix.size() == 1 &&
                                          (suffix[0] == 'F' || suffix[0] == 'B' || suffix[0] == 'C'))) {
                if (suffix == "F")
                    ref.direction = JumpDirection::Forward;
                else if (suffix == "B")
                    ref.direction = JumpDirection::Backward;
                std::size_t t = skipBlanks(s, j);
                if (dialect == Dialect::Sinumerik && t + 1 < s.size() && upper(s[t]) == 'N' && isDigit(s[t + 1]) &&
                    (skipDigits(s, t + 1) >= s.size() || !isIdentChar(s[skipDigits(s, t + 1)]))) {
                    ref.digitsBegin = t + 1;
                    ref.digitsEnd = skipDigits(s, t + 1);
                } else if (dialect == Dialect::Iso && t < s.size() && isDigit(s[t])) {
                    ref.digitsBegin = t;
                    ref.digitsEnd = skipDigits(s, t);
                } else if (dialect == Dialect::Iso && t < s.size() && (s[t] == '#' || s[t] == '[')) {
                    notes.push_back({int(lineIndex + 1), "GOTO with a computed target is not remapped"});
                }
            }
            if (ref.digitsEnd > ref.digitsBegin) {
                if (auto n = parseNumber(s.substr(ref.digitsBegin, ref.digitsEnd - ref.digitsBegin))) {
                    ref.number = *n;
                    out.push_back(ref);
                }
                i = ref.digitsEnd;
                continue;
            }
        }
        i = j;
    }
}

void resolveJumps(std::vector<JumpRef>& jumps, const std::vector<LineInfo>& infos, std::vector<RenumberNote>& notes)
{
    std::map<long long, std::vector<std::size_t>> linesByNumber;
    for (std::size_t k = 0; k < infos.size(); ++k)
        if (infos[k].number && infos[k].kind != LineKind::Header)
            linesByNumber[*infos[k].number].push_back(k);
    for (JumpRef& ref : jumps) {
        const auto it = linesByNumber.find(ref.number);
        if (it != linesByNumber.end()) {
            const std::vector<std::size_t>& candidates = it->second;
            const auto after = std::upper_bound(candidates.begin(), candidates.end(), ref.line);
            const bool wantForward = ref.direction != JumpDirection::Backward;
            if (wantForward && after != candidates.end())
                ref.target = *after;
            else if (ref.direction != JumpDirection::Forward) {
                // Backward: the nearest one before; GOTO/GOTOC search on from the program start.
                const auto before = std::lower_bound(candidates.begin(), candidates.end(), ref.line);
                if (ref.direction == JumpDirection::Backward && before != candidates.begin())
                    ref.target = *std::prev(before);
                else if (ref.direction == JumpDirection::ForwardThenBackward && !candidates.empty())
                    ref.target = candidates.front();
            }
        }
        if (!ref.target)
            notes.push_back(
                {int(ref.line + 1), "jump target N" + std::to_string(ref.number) + " not found: left as it is"});
    }
}

struct Edit {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::string replacement;
};

void appendEdited(std::string& out, std::string_view line, std::vector<Edit>& edits)
{
    std::sort(edits.begin(), edits.end(), [](const Edit& x, const Edit& y) { return x.begin < y.begin; });
    std::size_t pos = 0;
    for (const Edit& e : edits) {
        out.append(line.substr(pos, e.begin - pos));
        out.append(e.replacement);
        pos = e.end;
    }
    out.append(line.substr(pos));
}

std::string numberPrefix(const LineInfo& info, std::string_view line, Dialect dialect)
{
    // A Sinumerik main block keeps its ':'; an N keeps its case.
    if (dialect == Dialect::Heidenhain)
        return {};
    if (info.number)
        return std::string(1, line[info.numberBegin]);
    return "N";
}

// Shared by renumber and remove: per line, the number it gets (nullopt: none), then the text.
RenumberResult rewrite(const std::vector<RawLine>& lines, const std::vector<LineInfo>& infos,
                       const std::vector<std::optional<long long>>& newNumbers, std::vector<JumpRef>& jumps,
                       Dialect dialect, RenumberReport report)
{
    // Line by line with one reused edit list: no allocation per line on a million-line program.
    // Jumps come in line order (collectJumps scans the lines in order).
    RenumberResult result;
    std::size_t size = 0;
    for (const RawLine& l : lines)
        size += l.content.size() + l.ending.size() + 8;
    result.text.reserve(size);
    std::vector<Edit> edits;
    std::size_t nextJump = 0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
        edits.clear();
        const LineInfo& info = infos[k];
        const std::string_view line = lines[k].content;
        const std::optional<long long>& wanted = newNumbers[k];
        if (wanted != info.number) {
            if (!wanted) {
                edits.push_back({info.numberBegin, info.removeEnd, {}});
                ++report.numbersRemoved;
            } else if (info.number) {
                const std::size_t digitsBegin =
                    dialect == Dialect::Heidenhain ? info.numberBegin : info.numberBegin + 1;
                edits.push_back({digitsBegin, info.numberEnd, std::to_string(*wanted)});
                ++report.linesNumbered;
            } else {
                std::string text = numberPrefix(info, line, dialect) + std::to_string(*wanted);
                if (info.insertAt < line.size())
                    text.push_back(' ');
                edits.push_back({info.insertAt, info.insertAt, std::move(text)});
                ++report.linesNumbered;
            }
        }
        for (; nextJump < jumps.size() && jumps[nextJump].line == k; ++nextJump) {
            const JumpRef& ref = jumps[nextJump];
            if (!ref.target || !newNumbers[*ref.target] || *newNumbers[*ref.target] == ref.number)
                continue;
            edits.push_back({ref.digitsBegin, ref.digitsEnd, std::to_string(*newNumbers[*ref.target])});
            ++report.targetsRemapped;
        }
        if (edits.empty())
            result.text.append(line);
        else
            appendEdited(result.text, line, edits);
        result.text.append(lines[k].ending);
    }
    std::stable_sort(report.notes.begin(), report.notes.end(),
                     [](const RenumberNote& a, const RenumberNote& b) { return a.line < b.line; });
    result.report = std::move(report);
    return result;
}

std::vector<JumpRef> collectJumps(const std::vector<RawLine>& lines, const std::vector<LineInfo>& infos,
                                  Dialect dialect, std::vector<RenumberNote>& notes)
{
    std::vector<JumpRef> jumps;
    if (dialect == Dialect::Heidenhain)
        return jumps;  // CALL LBL names labels, not block numbers
    for (std::size_t k = 0; k < lines.size(); ++k)
        if (infos[k].kind == LineKind::Block)
            findJumps(lines[k].content, k, infos[k], dialect, jumps, notes);
    resolveJumps(jumps, infos, notes);
    return jumps;
}

}  // namespace

std::vector<std::string_view> splitLines(std::string_view text)
{
    std::vector<std::string_view> out;
    for (const RawLine& l : splitRaw(text))
        out.push_back(l.content);
    return out;
}

LineInfo analyzeLine(std::string_view s, Dialect dialect, bool continuation)
{
    LineInfo info;
    std::size_t i = skipBlanks(s, 0);
    if (dialect == Dialect::Heidenhain) {
        if (i >= s.size()) {
            info.kind = LineKind::Empty;
            return info;
        }
        if (continuation || s[i] == '~') {
            info.kind = LineKind::Header;
            info.numberBegin = info.numberEnd = info.removeEnd = info.insertAt = i;
            return info;
        }
        info.insertAt = info.numberBegin = info.numberEnd = info.removeEnd = i;
        const std::size_t d = skipDigits(s, i);
        if (d > i && (d == s.size() || isBlank(s[d]))) {
            info.number = parseNumber(s.substr(i, d - i));
            info.numberEnd = d;
            info.removeEnd = skipBlanks(s, d);
        }
        const std::size_t rest = info.removeEnd;
        info.kind = (rest < s.size() && (s[rest] == ';' || s[rest] == '*')) ? LineKind::CommentOnly : LineKind::Block;
        return info;
    }

    if (i < s.size() && s[i] == '%') {
        info.kind = LineKind::Header;
        info.numberBegin = info.numberEnd = info.removeEnd = info.insertAt = i;
        return info;
    }
    bool skipLevel = false;
    if (i < s.size() && s[i] == '/') {
        skipLevel = true;
        ++i;
        if (i < s.size() && isDigit(s[i]))
            ++i;
        i = skipBlanks(s, i);
    }
    info.insertAt = info.numberBegin = info.numberEnd = info.removeEnd = i;
    const bool nWord = i + 1 < s.size() && upper(s[i]) == 'N' && isDigit(s[i + 1]);
    const bool mainBlock = dialect == Dialect::Sinumerik && i + 1 < s.size() && s[i] == ':' && isDigit(s[i + 1]);
    if (nWord || mainBlock) {
        const std::size_t d = skipDigits(s, i + 1);
        info.number = parseNumber(s.substr(i + 1, d - i - 1));
        info.numberEnd = d;
        info.removeEnd = skipBlanks(s, d);
    }
    const std::size_t rest = info.removeEnd;
    if (rest >= s.size())
        info.kind = (info.number || skipLevel) ? LineKind::Block : LineKind::Empty;
    else if (onlyComments(s, rest, dialect))
        info.kind = LineKind::CommentOnly;
    else if (dialect == Dialect::Iso && !info.number && upper(s[rest]) == 'O' && rest + 1 < s.size() &&
             (isDigit(s[rest + 1]) || s[rest + 1] == '<'))
        info.kind = LineKind::Header;  // O1234 program number, LinuxCNC o<name> / o100 sub
    else
        info.kind = LineKind::Block;
    return info;
}

std::optional<int> findBlock(std::string_view text, Dialect dialect, long long number)
{
    // Streams over the text: fast on a million lines, no copies.
    std::size_t begin = 0;
    int line = 1;
    bool continuation = false;
    while (begin < text.size()) {
        std::size_t nl = text.find('\n', begin);
        std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        std::string_view content = text.substr(begin, end - begin);
        if (!content.empty() && content.back() == '\r')
            content.remove_suffix(1);
        const LineInfo info = analyzeLine(content, dialect, continuation);
        if (info.number && *info.number == number && info.kind != LineKind::Header)
            return line;
        continuation = dialect == Dialect::Heidenhain && endsWithTilde(content);
        if (nl == std::string_view::npos)
            break;
        begin = nl + 1;
        ++line;
    }
    return std::nullopt;
}

RenumberResult renumberBlocks(std::string_view text, const RenumberOptions& options)
{
    const Dialect dialect = options.dialect;
    const std::vector<RawLine> lines = splitRaw(text);
    const std::vector<LineInfo> infos = analyzeAll(lines, dialect);
    RenumberReport report;
    std::vector<JumpRef> jumps = collectJumps(lines, infos, dialect, report.notes);

    std::vector<std::optional<long long>> newNumbers(lines.size());
    if (dialect == Dialect::Heidenhain) {
        if (options.start != 0 || options.step != 1 || !options.replaceExisting || options.onlyNumbered)
            report.notes.push_back(
                {0, "Heidenhain blocks are always numbered from 0 in steps of 1, every line; other options ignored"});
        long long next = 0;
        for (std::size_t k = 0; k < lines.size(); ++k)
            if (infos[k].kind == LineKind::Block || infos[k].kind == LineKind::CommentOnly)
                newNumbers[k] = next++;
            else
                newNumbers[k] = infos[k].number;
    } else {
        const long long step = options.step > 0 ? options.step : 1;
        long long next = options.start;
        for (std::size_t k = 0; k < lines.size(); ++k) {
            const LineInfo& info = infos[k];
            newNumbers[k] = info.number;
            bool eligible = info.kind == LineKind::Block ||
                            (info.kind == LineKind::CommentOnly && (options.numberCommentLines || info.number)) ||
                            (info.kind == LineKind::Empty && options.numberEmptyLines);
            if (options.onlyNumbered && !info.number)
                eligible = false;
            if (!eligible || (info.number && !options.replaceExisting))
                continue;
            newNumbers[k] = next;
            next += step;
        }
    }
    return rewrite(lines, infos, newNumbers, jumps, dialect, std::move(report));
}

RenumberResult removeBlockNumbers(std::string_view text, Dialect dialect)
{
    const std::vector<RawLine> lines = splitRaw(text);
    RenumberReport report;
    if (dialect == Dialect::Heidenhain) {
        report.notes.push_back({0, "Heidenhain programs need their block numbers: nothing removed"});
        return {std::string(text), std::move(report)};
    }
    const std::vector<LineInfo> infos = analyzeAll(lines, dialect);
    std::vector<JumpRef> jumps = collectJumps(lines, infos, dialect, report.notes);
    std::set<std::size_t> targets;
    for (const JumpRef& ref : jumps)
        if (ref.target)
            targets.insert(*ref.target);
    std::vector<std::optional<long long>> newNumbers(lines.size());
    for (std::size_t k = 0; k < lines.size(); ++k) {
        if (targets.count(k) != 0) {
            newNumbers[k] = infos[k].number;
            report.notes.push_back({int(k + 1), "kept N" + std::to_string(*infos[k].number) + ": a GOTO jumps here"});
        } else if (infos[k].kind == LineKind::Header) {
            newNumbers[k] = infos[k].number;
        }
    }
    return rewrite(lines, infos, newNumbers, jumps, dialect, std::move(report));
}

}  // namespace camwb::nc
