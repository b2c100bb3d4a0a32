// Physical lines of a text, one at a time: from memory, or from a file read in chunks so that a
// reader holds one line (and the one after it when it looks ahead) however long the file is.
// Lines end at LF, a CR before it is dropped, and a UTF-8 byte order mark at the very start is
// dropped so that columns on line 1 match what an editor shows.
#pragma once

#include "base/Result.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::base {

class LineReader {
public:
    // Reads `text`, which must outlive the reader.
    explicit LineReader(std::string_view text);
    // Reads the file at `path` in chunks; an Error names it when it cannot be opened.
    static Result<LineReader> open(const std::string& path);

    // The next line, valid until the next call of next(); nullopt at the end of the text (or
    // when reading failed: see readError()).
    std::optional<std::string_view> next();
    // The line after the one next() gave last, without taking it; the view of that one stays
    // valid. Valid itself until the next call of next().
    std::optional<std::string_view> peek();
    // 1-based number of the line next() gave last (0 before the first, the count at the end).
    int lineNumber() const { return m_lineNumber; }
    // Bytes in the whole text (a file's size when it was opened): readers size what they build.
    std::size_t sizeBytes() const { return m_sizeBytes; }
    // Set when the file could not be read to its end (the lines read so far are good).
    const std::optional<Error>& readError() const { return m_readError; }

private:
    struct Closer {
        void operator()(int* fd) const;
    };
    struct Span {
        std::size_t begin = 0, end = 0, next = 0;  // content [begin, end); the following line at next
    };

    LineReader(std::unique_ptr<int, Closer> file, std::string path, std::size_t sizeBytes);
    // The line starting at `from`; false at the end. `peeking`: keep the last line's view valid.
    bool find(std::size_t from, Span& span, bool peeking);
    bool fill(bool peeking);  // reads more; false when nothing more came
    void skipByteOrderMark();
    std::string_view view(const Span& span) const { return {m_data + span.begin, span.end - span.begin}; }

    const char* m_data = nullptr;  // the text, or the buffer's valid part [0, m_size)
    std::size_t m_size = 0;
    std::unique_ptr<int, Closer> m_file;  // the file descriptor while there is more to read
    std::string m_path;
    std::vector<char> m_buffer;
    std::vector<char> m_retired;  // the buffer before a refill while peeking: the last line is in it
    bool m_atEnd = true;          // nothing more to read beyond m_size
    std::size_t m_current = 0;    // start of the line next() gave last (kept valid by fill())
    std::size_t m_position = 0;   // where the line after it starts
    std::optional<Span> m_peeked;
    std::size_t m_sizeBytes = 0;
    int m_lineNumber = 0;
    std::optional<Error> m_readError;
};

// Opens a file for reading (a descriptor the caller closes), with the messages every reader gives
// ("cannot open: ...", "it is a folder").
Result<int> openForReading(const std::string& path);

}  // namespace camwb::base
