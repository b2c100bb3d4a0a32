#include "base/LineReader.h"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace camwb::base {

namespace {

constexpr std::size_t kChunkBytes = std::size_t(1) << 20;
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

}  // namespace

Result<int> openForReading(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return makeError(std::string("cannot open: ") + std::strerror(errno), path);
    struct stat info {};
    if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
        ::close(fd);
        return makeError("cannot read: it is a folder, not a file", path);  // it would read as empty
    }
    return fd;
}

void LineReader::Closer::operator()(int* fd) const
{
    ::close(*fd);
    delete fd;
}

LineReader::LineReader(std::string_view text) : m_data(text.data()), m_size(text.size()), m_sizeBytes(text.size())
{
    skipByteOrderMark();
}

LineReader::LineReader(std::unique_ptr<int, Closer> file, std::string path, std::size_t sizeBytes) :
    m_file(std::move(file)),
    m_path(std::move(path)),
    m_buffer(kChunkBytes),
    m_atEnd(false),
    m_sizeBytes(sizeBytes)
{
    m_data = m_buffer.data();
    while (m_size < kByteOrderMark.size() && fill(false)) {
    }
    skipByteOrderMark();
}

Result<LineReader> LineReader::open(const std::string& path)
{
    auto fd = openForReading(path);
    if (!fd)
        return fd.error();
    struct stat info {};
    const std::size_t size = ::fstat(fd.value(), &info) == 0 ? static_cast<std::size_t>(info.st_size) : 0;
    return LineReader(std::unique_ptr<int, Closer>(new int(fd.value())), path, size);
}

void LineReader::skipByteOrderMark()
{
    if (std::string_view(m_data, m_size).substr(0, kByteOrderMark.size()) == kByteOrderMark)
        m_current = m_position = kByteOrderMark.size();
}

bool LineReader::fill(bool peeking)
{
    if (m_atEnd)
        return false;
    if (m_size == m_buffer.size()) {
        // Full: start a buffer with what is still needed, from the line next() gave last on.
        // While peeking that line's view must stay valid, so the old buffer is kept until the
        // next next(); otherwise the text moves to the front of the same buffer.
        const std::size_t keep = m_current;
        const std::size_t rest = m_size - keep;
        const std::size_t capacity = rest * 2 > m_buffer.size() ? m_buffer.size() * 2 : m_buffer.size();
        if (peeking || capacity != m_buffer.size()) {
            std::vector<char> fresh(capacity);
            std::memcpy(fresh.data(), m_buffer.data() + keep, rest);
            m_retired = std::exchange(m_buffer, std::move(fresh));
        } else {
            std::memmove(m_buffer.data(), m_buffer.data() + keep, rest);
        }
        m_size = rest;
        m_current -= keep;
        m_position -= keep;
        m_data = m_buffer.data();
    }
    ssize_t read = 0;
    do
        read = ::read(*m_file, m_buffer.data() + m_size, m_buffer.size() - m_size);
    while (read < 0 && errno == EINTR);
    if (read > 0) {
        m_size += static_cast<std::size_t>(read);
    } else {
        if (read < 0)
            m_readError = makeError(std::string("read failed: ") + std::strerror(errno), m_path);
        m_atEnd = true;
        m_file.reset();
    }
    return read > 0;
}

bool LineReader::find(std::size_t from, Span& span, bool peeking)
{
    while (true) {
        if (const void* lf = from < m_size ? std::memchr(m_data + from, '\n', m_size - from) : nullptr) {
            const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(lf) - m_data);
            span = {from, end > from && m_data[end - 1] == '\r' ? end - 1 : end, end + 1};
            return true;
        }
        if (m_atEnd) {
            if (from >= m_size)
                return false;
            // The last line, without a line break.
            span = {from, m_size > from && m_data[m_size - 1] == '\r' ? m_size - 1 : m_size, m_size};
            return true;
        }
        // fill() may move the text: `from` moves with the line next() gave last.
        const std::size_t offset = from - m_current;
        fill(peeking);
        from = m_current + offset;
    }
}

std::optional<std::string_view> LineReader::next()
{
    Span span;
    m_retired.clear();  // the line given before this one is no longer needed
    m_retired.shrink_to_fit();
    if (m_peeked) {
        span = *m_peeked;
        m_peeked.reset();
    } else if (!find(m_position, span, false)) {
        m_current = m_position;
        return std::nullopt;
    }
    m_current = span.begin;
    m_position = span.next;
    ++m_lineNumber;
    return view(span);
}

std::optional<std::string_view> LineReader::peek()
{
    if (!m_peeked) {
        Span span;
        if (!find(m_position, span, true))
            return std::nullopt;
        m_peeked = span;
    }
    return view(*m_peeked);
}

}  // namespace camwb::base
