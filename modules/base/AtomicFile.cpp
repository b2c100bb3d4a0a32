#include "base/AtomicFile.h"

#include "base/LineReader.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace camwb::base {

namespace {
std::string systemError() { return std::strerror(errno); }
}  // namespace

AtomicFileWriter::AtomicFileWriter(std::string targetPath) : m_target(std::move(targetPath)) {}

AtomicFileWriter::~AtomicFileWriter() { abort(); }

Status AtomicFileWriter::open()
{
    std::string pattern = m_target + ".tmp-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if (fd < 0)
        return makeError("cannot create a temporary file beside it: " + systemError(), m_target);
    ::fchmod(fd, 0644);
    m_tempPath = buffer.data();
    m_file = ::fdopen(fd, "wb");
    if (!m_file) {
        ::close(fd);
        ::unlink(m_tempPath.c_str());
        return makeError("cannot open the temporary file: " + systemError(), m_target);
    }
    return {};
}

void AtomicFileWriter::write(std::string_view data)
{
    if (!m_file || m_writeFailed)
        return;
    if (std::fwrite(data.data(), 1, data.size(), m_file) != data.size())
        m_writeFailed = true;
}

Status AtomicFileWriter::finishWriting()
{
    if (!m_file)
        return m_tempPath.empty() ? makeError("internal error: commit without open", m_target) : Status{};
    const bool flushed = std::fflush(m_file) == 0 && ::fsync(::fileno(m_file)) == 0;
    const int savedErrno = errno;
    std::fclose(m_file);
    m_file = nullptr;
    if (m_writeFailed || !flushed) {
        ::unlink(m_tempPath.c_str());
        m_tempPath.clear();
        errno = savedErrno;
        return makeError("write failed: " + systemError(), m_target);
    }
    return {};
}

Status AtomicFileWriter::commit()
{
    if (Status written = finishWriting(); !written)
        return written;
    if (::rename(m_tempPath.c_str(), m_target.c_str()) != 0) {
        const std::string reason = systemError();
        ::unlink(m_tempPath.c_str());
        m_tempPath.clear();
        return makeError("cannot replace the file: " + reason, m_target);
    }
    m_tempPath.clear();
    return {};
}

void AtomicFileWriter::abort()
{
    if (m_file) {
        std::fclose(m_file);
        m_file = nullptr;
    }
    if (!m_tempPath.empty()) {
        ::unlink(m_tempPath.c_str());
        m_tempPath.clear();
    }
}

Status writeFileAtomically(const std::string& path, std::string_view content)
{
    AtomicFileWriter writer(path);
    if (Status opened = writer.open(); !opened)
        return opened;
    writer.write(content);
    return writer.commit();
}

Result<std::string> readTextFile(const std::string& path)
{
    // One allocation of the file's size and one read into it: a stream copied into a string
    // touched three times the file's size in memory (a 1M-line program is 24 MB).
    auto opened = openForReading(path);
    if (!opened)
        return opened.error();
    const int fd = opened.value();
    struct stat info {};
    ::fstat(fd, &info);
    // The size it has now; a file that grows meanwhile (or a pipe, size 0) is read on in chunks.
    std::string text(info.st_size > 0 ? static_cast<std::size_t>(info.st_size) : 0, '\0');
    std::size_t length = 0;
    char chunk[65536];
    for (;;) {
        const bool intoText = length < text.size();
        const ssize_t n =
            intoText ? ::read(fd, text.data() + length, text.size() - length) : ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            ::close(fd);
            return makeError("read failed", path);
        }
        if (n == 0)
            break;
        if (!intoText)
            text.append(chunk, static_cast<std::size_t>(n));
        length += static_cast<std::size_t>(n);
    }
    ::close(fd);
    text.resize(length);
    return text;
}

Result<std::string> readPlainTextFile(const std::string& path)
{
    Result<std::string> text = readTextFile(path);
    if (!text)
        return text;
    const std::string& t = text.value();
    const std::size_t nul = t.find('\0');
    if (nul == std::string::npos)
        return text;
    const int line = 1 + static_cast<int>(std::count(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
    return makeError("not a text file (binary data: a NUL byte on this line)", path, line);
}

}  // namespace camwb::base
