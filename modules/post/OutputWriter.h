// The NC text being built by a post run: block numbering, word joining, the operation index of
// every line, and streaming to a file in chunks so memory stays flat however long the program is.
// Qt-free: the script bindings and the C++ block templates both write through it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::post {

class OutputWriter {
public:
    // Receives finished text in order; returns false when writing failed.
    using Sink = std::function<bool(std::string_view)>;

    // From now on, text goes to `sink` in chunks of about chunkBytes (default: kept in memory).
    void streamTo(Sink sink, std::size_t chunkBytes = std::size_t(1) << 20);

    // Next block gets `start`; each numbered block adds `step`. Default: N10, N20, ...
    void setBlockNumbering(long long start, long long step, bool enabled, std::string prefix = "N");

    // An empty writer (in memory) that numbers as this one was last set up to, from its first
    // number again: a companion file of the program restarts its block numbers.
    OutputWriter restartedNumbering() const;

    // Joins the non-empty words with single spaces, prefixed by "N<n> " when numbering is on.
    // All words empty: writes nothing and uses no block number. Returns whether a line was written.
    bool writeBlock(const std::vector<std::string>& words);
    // Block number, then ';' + text (';' is the first character after the N word).
    void writeComment(std::string_view text);
    // Raw text, no number; embedded newlines make several lines.
    void writeLine(std::string_view text);

    // A block built word by word, with writeBlock's rules: the block number is taken when the
    // first word arrives, and a block without words writes nothing.
    void beginBlock() { m_blockWords = 0; }
    void addWord(std::string_view prefix, std::string_view text);
    bool endBlock();
    // A whole block of words already joined by single blanks, none of which can hold a line break
    // (block templates assemble their words in a buffer of their own): "N<n> " + words, a line.
    void writeCleanBlock(std::string_view words);

    // Operation index recorded for the lines written from now on (-1 = none).
    void setOperation(int operationIndex) { m_operation = operationIndex; }

    // Hands the remaining text to the sink (streaming); false when the sink failed at any time.
    bool finish();
    // The text kept in memory (all of it without a sink).
    const std::string& text() const { return m_text; }
    std::string takeText() { return std::move(m_text); }
    // Per output line, the operation index that was current when it was written.
    std::vector<int> lineOperations() const;
    std::size_t lineCount() const { return m_lines; }
    std::size_t byteCount() const { return m_bytes + m_text.size(); }

private:
    void appendBlockNumber();
    void appendClean(std::string_view text);  // line breaks inside a block become spaces
    void endLine();

    struct OperationRun {
        std::size_t firstLine;
        int operation;
    };

    std::string m_text;
    Sink m_sink;
    std::size_t m_chunkBytes = 0;
    bool m_sinkFailed = false;
    std::vector<OperationRun> m_runs;
    std::size_t m_lines = 0;
    std::size_t m_bytes = 0;  // streamed so far
    int m_operation = -1;
    int m_blockWords = 0;
    long long m_start = 10;
    long long m_next = 10;
    long long m_step = 10;
    bool m_numbering = true;
    std::string m_prefix = "N";
};

}  // namespace camwb::post
