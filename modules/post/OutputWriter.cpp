#include "post/OutputWriter.h"

namespace camwb::post {

void OutputWriter::setBlockNumbering(long long start, long long step, bool enabled)
{
    m_next = start;
    m_step = step;
    m_numbering = enabled;
}

std::string OutputWriter::blockPrefix()
{
    if (!m_numbering)
        return {};
    std::string prefix = "N" + std::to_string(m_next) + " ";
    m_next += m_step;
    return prefix;
}

bool OutputWriter::writeBlock(const std::vector<std::string>& words)
{
    std::string line;
    for (const std::string& word : words) {
        if (word.empty())
            continue;
        if (!line.empty())
            line += ' ';
        line += word;
    }
    if (line.empty())
        return false;
    append(blockPrefix() + line);
    return true;
}

void OutputWriter::writeComment(const std::string& text) { append(blockPrefix() + ";" + text); }

void OutputWriter::writeLine(const std::string& text)
{
    std::size_t start = 0;
    while (true) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string::npos) {
            append(text.substr(start));
            return;
        }
        append(text.substr(start, newline - start));
        start = newline + 1;
    }
}

void OutputWriter::append(const std::string& line)
{
    // A line never carries its own line break or a trailing '\r'; the writer adds exactly one "\n".
    std::string clean = line;
    while (!clean.empty() && (clean.back() == '\r' || clean.back() == '\n'))
        clean.pop_back();
    m_text += clean;
    m_text += '\n';
    m_lineOperation.push_back(m_operation);
}

}  // namespace camwb::post
