// The NC text being built by a post run: block numbering, word joining and the operation index of
// every line. Qt-free so that the C++ block templates of the full engine can write through it too.
#pragma once

#include <string>
#include <vector>

namespace camwb::post {

class OutputWriter {
public:
    // Next block gets `start`; each numbered block adds `step`. Default: N10, N20, ...
    void setBlockNumbering(long long start, long long step, bool enabled);

    // Joins the non-empty words with single spaces, prefixed by "N<n> " when numbering is on.
    // All words empty: writes nothing and uses no block number. Returns whether a line was written.
    bool writeBlock(const std::vector<std::string>& words);
    // Block number, then ';' + text (';' is the first character after the N word).
    void writeComment(const std::string& text);
    // Raw text, no number; embedded newlines make several lines.
    void writeLine(const std::string& text);

    // Operation index recorded for the lines written from now on (-1 = none).
    void setOperation(int operationIndex) { m_operation = operationIndex; }

    const std::string& text() const { return m_text; }
    const std::vector<int>& lineOperation() const { return m_lineOperation; }

private:
    void append(const std::string& line);
    std::string blockPrefix();

    std::string m_text;
    std::vector<int> m_lineOperation;
    int m_operation = -1;
    long long m_next = 10;
    long long m_step = 10;
    bool m_numbering = true;
};

}  // namespace camwb::post
