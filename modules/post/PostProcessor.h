// The post kernel: loads a post script (JavaScript, Fusion/HSM-like handlers plus C++ block
// templates for the per-move hot path) and turns a Toolpath into NC text. Everything that would
// make output non-deterministic (clock, user, version) comes in through PostContext; each run uses
// a fresh script engine, so runs are independent and thread-safe.
#pragma once

#include "base/Diagnostic.h"
#include "base/Result.h"
#include "base/Vec.h"
#include "kinematics/Machine.h"
#include "post/PostInfo.h"
#include "toolpath/Toolpath.h"

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace camwb::post {

struct PostContext {
    std::string programName;
    std::int64_t dateEpochSeconds = 0;  // shown as UTC
    std::string user;
    std::string version;  // CAMWB_VERSION
    // The output file's name without folder and extension ("" when posting into memory): the
    // name some controls want inside the program (Klartext's BEGIN PGM <name>).
    std::string outputName;

    // SOURCE_DATE_EPOCH if set (else now), CAMWB_USER else USER else "unknown", CAMWB_VERSION.
    static PostContext fromEnvironment(std::string programName);
};

// What the job says beyond its CL: its name (the project in headers) and the stock box.
struct JobFacts {
    std::string name;
    std::optional<base::Box3> stock;
};

struct RunOptions {
    PostContext context;
    JobFacts job;                                   // empty when posting a CL file
    std::map<std::string, std::string> properties;  // user values as text, by property name
    std::optional<kinematics::Machine> machine;     // given to the script; its limits are checked
    // Longest time one call into the script (loading it, or one handler) may take before it is
    // interrupted: a runaway loop becomes an error instead of a hang.
    std::chrono::milliseconds scriptBudget{10000};
};

// A file the post wrote beside the main program (openFile/closeFile in the script), e.g. the SPF
// subprograms a SINUMERIK main program calls: a plain file name and its text.
struct CompanionFile {
    std::string name;
    std::string text;  // every line ends with "\n"
};

struct PostOutput {
    std::string text;                        // every line ends with "\n"
    std::vector<CompanionFile> files;        // companion files, in the order the post opened them
    std::vector<base::Diagnostic> messages;  // warnings from the kernel, the machine check and the post
    std::vector<int> lineOperation;          // per output line: operation index of its CL record, -1 = none
};

// What a run into a file reports (the text itself went to the file).
struct PostSummary {
    std::vector<base::Diagnostic> messages;
    std::size_t lines = 0;
    std::size_t bytes = 0;
    std::vector<std::string> companionPaths;  // the companion files written beside the output
};

struct ScriptEngine;  // detail/ScriptEngine.h: what load and the runs do

class PostProcessor {
public:
    // Reads the script and evaluates it once to read the `post` metadata object (no handler
    // runs). Syntax errors, a missing `post` object and malformed declarations give an Error
    // with the file and line.
    static base::Result<PostProcessor> load(const std::string& scriptPath,
                                            std::chrono::milliseconds scriptBudget = std::chrono::seconds(10));

    const PostInfo& info() const { return m_info; }

    // Fresh script engine per run. Any script error gives an Error naming the post file and line.
    // Needs a QCoreApplication instance (QJSEngine does); without one it returns an Error.
    base::Result<PostOutput> run(const toolpath::Toolpath& toolpath, const RunOptions& options) const;
    base::Result<PostOutput> run(const toolpath::Toolpath& toolpath, const PostContext& context) const;

    // Streams the NC into a temporary file beside `outputPath`, writes each companion file to a
    // temporary file in the same folder, and renames them all over their targets only when the
    // whole run succeeded: on any error no file is written or replaced. (The renames themselves
    // run one after the other: a rename failing half-way, e.g. a file locked by another program,
    // leaves the earlier ones done; the error says which.)
    base::Result<PostSummary> runToFile(const toolpath::Toolpath& toolpath, const RunOptions& options,
                                        const std::string& outputPath) const;

private:
    friend struct ScriptEngine;
    PostInfo m_info;
    std::string m_source;
};

// "DD.MM.YYYY HH:MM:SS" in UTC, as the header date of posts.
std::string formatDateUtc(std::int64_t epochSeconds);

}  // namespace camwb::post
