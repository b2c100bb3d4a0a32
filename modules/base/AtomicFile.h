// Writes files so that readers see either the old content or the complete new one, never a
// half-written file: write a temp file beside the target, fsync, rename over the target.
#pragma once

#include "base/Result.h"

#include <cstdio>
#include <string>
#include <string_view>

namespace camwb::base {

// Streams into "<target>.tmp-XXXXXX"; commit() makes it the target, destruction without commit
// removes the temp file and leaves the target untouched.
class AtomicFileWriter {
public:
    explicit AtomicFileWriter(std::string targetPath);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    Status open();
    void write(std::string_view data);
    // Flushes the temporary file to disk: a write error shows here, before any rename (a caller
    // that replaces several files finishes them all first). commit() does it when not yet done.
    Status finishWriting();
    Status commit();
    void abort();

private:
    std::string m_target;
    std::string m_tempPath;
    std::FILE* m_file = nullptr;
    bool m_writeFailed = false;
};

Status writeFileAtomically(const std::string& path, std::string_view content);
Result<std::string> readTextFile(const std::string& path);
// The same for a file that must be text (an NC program, a tool table, a CSV): one holding a NUL
// byte is binary data (a model or an archive picked by mistake), an error naming its line, rather
// than a screenful of its bytes read as words.
Result<std::string> readPlainTextFile(const std::string& path);

}  // namespace camwb::base
