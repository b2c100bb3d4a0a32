// The post kernel: loads a post script (JavaScript, Fusion/HSM-like handlers) and turns a Toolpath
// into NC text. Everything that would make output non-deterministic (clock, user, version) comes in
// through PostContext; each run uses a fresh script engine, so runs are independent and thread-safe.
#pragma once

#include "base/Result.h"
#include "toolpath/Toolpath.h"

#include <cstdint>
#include <string>
#include <vector>

namespace camwb::post {

struct PostInfo {
    std::string id;  // from `post.id`, else the file's base name
    std::string description;
    std::string vendor;
    std::string extension;  // without the dot, e.g. "mpf"; "nc" when the post names none
    std::string filePath;
};

struct PostContext {
    std::string programName;
    std::int64_t dateEpochSeconds = 0;  // shown as UTC
    std::string user;
    std::string version;  // CAMWB_VERSION

    // SOURCE_DATE_EPOCH if set (else now), CAMWB_USER else USER else "unknown", CAMWB_VERSION.
    static PostContext fromEnvironment(std::string programName);
};

struct PostMessage {
    enum class Severity { Warning, Error };
    Severity severity = Severity::Warning;
    std::string text;
    std::string file;
    int line = 0;
};

struct PostOutput {
    std::string text;                   // every line ends with "\n"
    std::vector<PostMessage> messages;  // warnings from the kernel and the post
    std::vector<int> lineOperation;     // per output line: operation index of its CL record, -1 = none
};

class PostProcessor {
public:
    // Reads the script and evaluates it once to read the `post` metadata object.
    // Syntax errors and a missing `post` object give an Error with the file and line.
    static base::Result<PostProcessor> load(const std::string& scriptPath);

    const PostInfo& info() const { return m_info; }

    // Fresh script engine per run. Any script error gives an Error naming the post file and line.
    // Needs a QCoreApplication instance (QJSEngine does); without one it returns an Error.
    base::Result<PostOutput> run(const toolpath::Toolpath& toolpath, const PostContext& context) const;

private:
    PostInfo m_info;
    std::string m_source;
};

// "DD.MM.YYYY HH:MM:SS" in UTC, as the header date of posts.
std::string formatDateUtc(std::int64_t epochSeconds);

}  // namespace camwb::post
