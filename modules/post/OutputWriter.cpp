#include "post/OutputWriter.h"

#include <charconv>

namespace camwb::post {

void OutputWriter::streamTo(Sink sink, std::size_t chunkBytes)
{
    m_sink = std::move(sink);
    m_chunkBytes = chunkBytes;
    m_text.reserve(chunkBytes + 4096);
}

void OutputWriter::setBlockNumbering(long long start, long long step, bool enabled, std::string prefix)
{
    m_start = start;
    m_next = start;
    m_step = step;
    m_numbering = enabled;
    m_prefix = std::move(prefix);
}

OutputWriter OutputWriter::restartedNumbering() const
{
    OutputWriter fresh;
    fresh.setBlockNumbering(m_start, m_step, m_numbering, m_prefix);
    return fresh;
}

void OutputWriter::appendBlockNumber()
{
    if (!m_numbering)
        return;
    char digits[24];
    const auto result = std::to_chars(digits, digits + sizeof digits, m_next);
    m_text += m_prefix;
    m_text.append(digits, result.ptr);
    m_text += ' ';
    m_next += m_step;
}

void OutputWriter::appendClean(std::string_view text)
{
    // A block is one line whatever a post passes in: a line break inside it would shift every
    // later block number and line-to-operation link.
    const std::size_t start = m_text.size();
    m_text += text;
    for (std::size_t i = start; i < m_text.size(); ++i)
        if (m_text[i] == '\n' || m_text[i] == '\r')
            m_text[i] = ' ';
}

void OutputWriter::endLine()
{
    m_text += '\n';
    if (m_runs.empty() || m_runs.back().operation != m_operation)
        m_runs.push_back({m_lines, m_operation});
    ++m_lines;
    if (m_sink && m_text.size() >= m_chunkBytes) {
        if (!m_sinkFailed && !m_sink(m_text))
            m_sinkFailed = true;
        m_bytes += m_text.size();
        m_text.clear();
    }
}

bool OutputWriter::writeBlock(const std::vector<std::string>& words)
{
    beginBlock();
    for (const std::string& word : words)
        addWord({}, word);
    return endBlock();
}

void OutputWriter::addWord(std::string_view prefix, std::string_view text)
{
    while (!text.empty() && (text.back() == '\r' || text.back() == '\n'))
        text.remove_suffix(1);  // a word that ends a line would leave a blank at the end of the block
    if (prefix.empty() && text.empty())
        return;
    if (m_blockWords++ == 0)
        appendBlockNumber();
    else
        m_text += ' ';
    appendClean(prefix);
    appendClean(text);
}

bool OutputWriter::endBlock()
{
    if (m_blockWords == 0)
        return false;
    m_blockWords = 0;
    endLine();
    return true;
}

void OutputWriter::writeCleanBlock(std::string_view words)
{
    appendBlockNumber();
    m_text += words;
    endLine();
}

void OutputWriter::writeComment(std::string_view text)
{
    appendBlockNumber();
    m_text += ';';
    appendClean(text);
    endLine();
}

void OutputWriter::writeLine(std::string_view text)
{
    std::size_t start = 0;
    while (true) {
        const std::size_t newline = text.find('\n', start);
        std::string_view line = text.substr(start, newline == std::string_view::npos ? text.npos : newline - start);
        // The writer adds exactly one "\n" per line; a trailing '\r' would make a CRLF line.
        while (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        appendClean(line);
        endLine();
        if (newline == std::string_view::npos)
            return;
        start = newline + 1;
    }
}

bool OutputWriter::finish()
{
    if (m_sink && !m_text.empty()) {
        if (!m_sinkFailed && !m_sink(m_text))
            m_sinkFailed = true;
        m_bytes += m_text.size();
        m_text.clear();
    }
    return !m_sinkFailed;
}

std::vector<int> OutputWriter::lineOperations() const
{
    std::vector<int> operations(m_lines, -1);
    for (std::size_t i = 0; i < m_runs.size(); ++i) {
        const std::size_t end = i + 1 < m_runs.size() ? m_runs[i + 1].firstLine : m_lines;
        for (std::size_t line = m_runs[i].firstLine; line < end; ++line)
            operations[line] = m_runs[i].operation;
    }
    return operations;
}

}  // namespace camwb::post
