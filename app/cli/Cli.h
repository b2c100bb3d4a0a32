// camwb-cli internals: the commands (each in its own file) and what they share: exit codes,
// messages to stderr, and the options that choose a post, a machine and property values.
#pragma once

#include "base/Diagnostic.h"
#include "document/Job.h"
#include "document/JobPipeline.h"
#include "kinematics/Machine.h"
#include "post/PostProcessor.h"
#include "sim/TriangleMesh.h"

#include "base/Vec.h"

#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace camwb::cli {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

// "camwb-cli: error: <message>" on stderr; returns kExitError.
int fail(const std::string& message);
// "camwb-cli: <message>", the commands' synopsis and a pointer to --help on stderr; returns
// kExitUsage.
int usageError(const std::string& message);
// The synopsis, then what each command does (--help).
void printUsage(std::ostream& out);
void printSynopsis(std::ostream& out);

// A diagnostic on stderr as compilers write them, "file:line:column: severity: message", which
// editors and CI parsers understand; one that is about no file reads "camwb-cli: severity: message".
void printDiagnostic(const base::Diagnostic& diagnostic);
// Each of them; returns the number of warnings.
int printDiagnostics(const std::vector<base::Diagnostic>& diagnostics);

// Options shared by the commands that post.
struct PostOptions {
    std::string postId;                             // --post
    std::string machineId;                          // --machine
    std::map<std::string, std::string> properties;  // --property name=value (repeatable)
    std::vector<std::string> postPaths;             // --post-path DIR (repeatable)
    std::string output;                             // -o / --output
    std::string project;                            // --project NAME: the job name a post's header shows
    std::optional<base::Box3> stock;                // --stock x0,y0,z0,x1,y1,z1 (a CL file has none)
    std::vector<std::string> sets;                  // --set <operation>.<parameter>=<value> (a job's)
};

// Consumes `--set <operation>.<parameter>=<value>` (repeatable) into `sets`; false when args[i]
// is not --set. A malformed one sets `error`.
bool takeSetOption(const std::vector<std::string>& args, std::size_t& i, std::vector<std::string>& sets,
                   std::string& error);

// Consumes args[i] (and its value) when it is one of the PostOptions; false when it is not one.
// A malformed option sets `error`.
bool takePostOption(const std::vector<std::string>& args, std::size_t& i, PostOptions& options, std::string& error);

// Posts `toolpath` into `outputPath` atomically and reports like every posting command does.
int postToFile(const post::PostProcessor& post, const toolpath::Toolpath& toolpath, const post::RunOptions& options,
               const std::string& outputPath);

// A job file with its operations recomputed on its model (what `post` and `cl` start from).
struct ComputedJob {
    document::Job job;
    toolpath::Toolpath program;
    document::ProgramReport report;   // warnings (their file: the job's) and motion counts, per operation
    std::optional<occ::Model> model;  // the model it was computed on
    sim::TriangleMesh stockBlank;     // a blank stock's solid (document::loadStockBlank); else empty
};
// Loads the job and its model (none for a lathe job), applies `sets` (--set, for this run only:
// the file is not changed) and computes the program; on an error, reports it (fail()) and
// returns nothing. The warnings are left to the caller to print.
std::optional<ComputedJob> computeJobFile(const std::string& path, const std::vector<std::string>& sets = {});

int runCommand(const std::vector<std::string>& args);         // camwb-cli run <job> -o <file>
int postsCommand(const std::vector<std::string>& args);       // camwb-cli posts [<id>]
int postCommand(const std::vector<std::string>& args);        // camwb-cli post <input> --post <id> ...
int ncCommand(const std::vector<std::string>& args);          // camwb-cli nc trace <file> ...
int clCommand(const std::vector<std::string>& args);          // camwb-cli cl <job> [-o <file>]
int simCommand(const std::vector<std::string>& args);         // camwb-cli sim <job|program> ...
int setupSheetCommand(const std::vector<std::string>& args);  // camwb-cli setup-sheet <job> -o <html> ...

// The machine `--machine <id>` names (an id or a machine file); none when `id` is empty.
base::Result<std::optional<kinematics::Machine>> machineOption(const std::string& id);

// "x0,y0,z0,x1,y1,z1": a stock box, each minimum below its maximum; nothing and `error` set when not.
std::optional<base::Box3> parseStockBox(const std::string& text, std::string& error);

}  // namespace camwb::cli
