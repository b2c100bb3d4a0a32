#include "nc/tools/LineDiff.h"

#include "nc/tools/BlockNumbers.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace camwb::nc {

namespace {

std::string normalise(std::string_view line, const LineInfo& info, const DiffOptions& options)
{
    std::string out;
    out.reserve(line.size());
    std::size_t from = 0;
    if (options.ignoreBlockNumbers && info.number) {
        out.append(line.substr(0, info.numberBegin));
        from = info.removeEnd;
    }
    for (std::size_t i = from; i < line.size(); ++i) {
        const char c = line[i];
        if (options.ignoreWhitespace && (c == ' ' || c == '\t'))
            continue;
        out.push_back(c);
    }
    return out;
}

// Each line as an id: equal (normalised) lines, equal ids, across both programs.
std::vector<int> hashLines(std::string_view text, const DiffOptions& options, std::unordered_map<std::string, int>& ids)
{
    std::vector<int> out;
    bool continuation = false;
    for (std::string_view line : splitLines(text)) {
        const bool needInfo = options.ignoreBlockNumbers;
        LineInfo info;
        if (needInfo) {
            info = analyzeLine(line, options.dialect, continuation);
            if (options.dialect == Dialect::Heidenhain) {
                std::size_t end = line.size();
                while (end > 0 && (line[end - 1] == ' ' || line[end - 1] == '\t'))
                    --end;
                continuation = end > 0 && line[end - 1] == '~';
            }
        }
        std::string key = (needInfo || options.ignoreWhitespace) ? normalise(line, info, options) : std::string(line);
        const auto [it, inserted] = ids.try_emplace(std::move(key), static_cast<int>(ids.size()));
        out.push_back(it->second);
    }
    return out;
}

// Myers' linear-space bisection (as in diff-match-patch): finds the middle snake of the edit
// graph and recurses on both halves. Marks removed lines of A and added lines of B.
class Myers {
public:
    Myers(const std::vector<int>& a, const std::vector<int>& b) :
        m_a(a),
        m_b(b),
        m_removed(a.size(), 0),
        m_added(b.size(), 0)
    {
    }

    void run() { diff(0, static_cast<int>(m_a.size()), 0, static_cast<int>(m_b.size())); }
    const std::vector<char>& removed() const { return m_removed; }
    const std::vector<char>& added() const { return m_added; }

private:
    void diff(int a0, int a1, int b0, int b1)
    {
        while (a0 < a1 && b0 < b1 && m_a[a0] == m_b[b0]) {
            ++a0;
            ++b0;
        }
        while (a0 < a1 && b0 < b1 && m_a[a1 - 1] == m_b[b1 - 1]) {
            --a1;
            --b1;
        }
        if (a0 == a1) {
            std::fill(m_added.begin() + b0, m_added.begin() + b1, 1);
            return;
        }
        if (b0 == b1) {
            std::fill(m_removed.begin() + a0, m_removed.begin() + a1, 1);
            return;
        }
        int x = 0;
        int y = 0;
        if (!bisect(a0, a1, b0, b1, x, y)) {
            std::fill(m_removed.begin() + a0, m_removed.begin() + a1, 1);
            std::fill(m_added.begin() + b0, m_added.begin() + b1, 1);
            return;
        }
        diff(a0, a0 + x, b0, b0 + y);
        diff(a0 + x, a1, b0 + y, b1);
    }

    // Split point (x, y) relative to (a0, b0); false when the ranges share nothing.
    bool bisect(int a0, int a1, int b0, int b1, int& splitX, int& splitY)
    {
        const int n = a1 - a0;
        const int m = b1 - b0;
        const int maxD = (n + m + 1) / 2;
        const int offset = maxD;
        const int length = 2 * maxD + 2;
        m_v1.assign(static_cast<std::size_t>(length), -1);
        m_v2.assign(static_cast<std::size_t>(length), -1);
        m_v1[offset + 1] = 0;
        m_v2[offset + 1] = 0;
        const int delta = n - m;
        const bool front = (delta % 2) != 0;
        int k1start = 0, k1end = 0, k2start = 0, k2end = 0;
        const int* A = m_a.data() + a0;
        const int* B = m_b.data() + b0;
        for (int d = 0; d < maxD; ++d) {
            for (int k1 = -d + k1start; k1 <= d - k1end; k1 += 2) {
                const int k1o = offset + k1;
                int x1 = (k1 == -d || (k1 != d && m_v1[k1o - 1] < m_v1[k1o + 1])) ? m_v1[k1o + 1] : m_v1[k1o - 1] + 1;
                int y1 = x1 - k1;
                while (x1 < n && y1 < m && A[x1] == B[y1]) {
                    ++x1;
                    ++y1;
                }
                m_v1[k1o] = x1;
                if (x1 > n) {
                    k1end += 2;
                } else if (y1 > m) {
                    k1start += 2;
                } else if (front) {
                    const int k2o = offset + delta - k1;
                    if (k2o >= 0 && k2o < length && m_v2[k2o] != -1 && x1 >= n - m_v2[k2o]) {
                        splitX = x1;
                        splitY = y1;
                        return true;
                    }
                }
            }
            for (int k2 = -d + k2start; k2 <= d - k2end; k2 += 2) {
                const int k2o = offset + k2;
                int x2 = (k2 == -d || (k2 != d && m_v2[k2o - 1] < m_v2[k2o + 1])) ? m_v2[k2o + 1] : m_v2[k2o - 1] + 1;
                int y2 = x2 - k2;
                while (x2 < n && y2 < m && A[n - x2 - 1] == B[m - y2 - 1]) {
                    ++x2;
                    ++y2;
                }
                m_v2[k2o] = x2;
                if (x2 > n) {
                    k2end += 2;
                } else if (y2 > m) {
                    k2start += 2;
                } else if (!front) {
                    const int k1o = offset + delta - k2;
                    if (k1o >= 0 && k1o < length && m_v1[k1o] != -1) {
                        const int x1 = m_v1[k1o];
                        const int y1 = offset + x1 - k1o;
                        if (x1 >= n - x2) {
                            splitX = x1;
                            splitY = y1;
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    const std::vector<int>& m_a;
    const std::vector<int>& m_b;
    std::vector<char> m_removed;
    std::vector<char> m_added;
    std::vector<int> m_v1;
    std::vector<int> m_v2;
};

}  // namespace

LineDiff diffLines(std::string_view left, std::string_view right, const DiffOptions& options)
{
    std::unordered_map<std::string, int> ids;
    const std::vector<int> a = hashLines(left, options, ids);
    const std::vector<int> b = hashLines(right, options, ids);
    Myers myers(a, b);
    myers.run();
    const std::vector<char>& removed = myers.removed();
    const std::vector<char>& added = myers.added();

    LineDiff result;
    const int n = static_cast<int>(a.size());
    const int m = static_cast<int>(b.size());
    int i = 0;
    int j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && !removed[i] && !added[j]) {
            result.rows.push_back({DiffKind::Equal, i + 1, j + 1});
            ++i;
            ++j;
            continue;
        }
        // A run of removals and additions between two equal lines: pair them up as changes.
        int i1 = i;
        while (i1 < n && removed[i1])
            ++i1;
        int j1 = j;
        while (j1 < m && added[j1])
            ++j1;
        DiffHunk hunk;
        hunk.firstRow = static_cast<int>(result.rows.size());
        hunk.leftStart = i1 > i ? i + 1 : i;
        hunk.leftCount = i1 - i;
        hunk.rightStart = j1 > j ? j + 1 : j;
        hunk.rightCount = j1 - j;
        const int paired = std::min(i1 - i, j1 - j);
        for (int k = 0; k < paired; ++k)
            result.rows.push_back({DiffKind::Changed, i + k + 1, j + k + 1});
        for (int k = i + paired; k < i1; ++k)
            result.rows.push_back({DiffKind::Removed, k + 1, 0});
        for (int k = j + paired; k < j1; ++k)
            result.rows.push_back({DiffKind::Added, 0, k + 1});
        hunk.rowCount = static_cast<int>(result.rows.size()) - hunk.firstRow;
        if (hunk.rowCount == 0)
            break;  // cannot happen with a consistent edit script; never loop forever
        result.hunks.push_back(hunk);
        i = i1;
        j = j1;
    }
    return result;
}

}  // namespace camwb::nc
