// camwb-cli: the headless shell over the same modules as the GUI.
//   camwb-cli --version
//   camwb-cli run <job.camwb> -o <file>     recompute the operations, post, write the NC
#include "base/AtomicFile.h"
#include "camwb_version.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "post/PostRegistry.h"

#include <QCoreApplication>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace camwb;

constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

void printUsage(std::ostream& out)
{
    out << "usage: camwb-cli --version\n"
           "       camwb-cli run <job.camwb> -o <output file>\n"
           "\n"
           "run: loads the job and its model, recomputes every operation, posts the\n"
           "     program with the job's post and writes the NC file (atomically).\n"
           "     Output is deterministic; SOURCE_DATE_EPOCH and CAMWB_USER set the header.\n";
}

int fail(const std::string& message)
{
    std::cerr << "camwb-cli: error: " << message << "\n";
    return kExitError;
}

int runJob(const std::string& jobPath, const std::string& outputPath)
{
    auto job = document::loadJob(jobPath);
    if (!job)
        return fail(job.error().toString());
    auto model = document::loadJobModel(job.value());
    if (!model)
        return fail(model.error().toString());
    auto program = document::computeProgram(job.value(), model.value());
    if (!program)
        return fail(jobPath + ": " + program.error().message);
    auto post = document::loadJobPost(job.value(), post::defaultPostDirs());
    if (!post)
        return fail(post.error().toString());

    const std::string programName = std::filesystem::path(jobPath).stem().string();
    auto nc = post->run(program.value(), post::PostContext::fromEnvironment(programName));
    if (!nc)
        return fail(nc.error().toString());

    int warnings = 0;
    for (const post::PostMessage& message : nc->messages) {
        const bool isError = message.severity == post::PostMessage::Severity::Error;
        std::cerr << "camwb-cli: " << (isError ? "error: " : "warning: ")
                  << base::Error{message.text, message.file, message.line}.toString() << "\n";
        warnings += isError ? 0 : 1;
    }
    if (base::Status written = base::writeFileAtomically(outputPath, nc->text); !written)
        return fail(written.error().toString());

    const auto lines = std::count(nc->text.begin(), nc->text.end(), '\n');
    std::cout << "camwb-cli: wrote " << outputPath << " (" << lines << " lines, " << warnings << " warnings)\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    // QJSEngine (post scripts) needs a core application object; nothing here needs a display.
    QCoreApplication app(argc, argv);
    const std::vector<std::string> args(argv + 1, argv + argc);

    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        printUsage(args.empty() ? std::cerr : std::cout);
        return args.empty() ? kExitUsage : 0;
    }
    if (args[0] == "--version") {
        std::cout << "camwb-cli " << CAMWB_VERSION << "\n";
        return 0;
    }
    if (args[0] == "run") {
        std::string job, output;
        for (std::size_t i = 1; i < args.size(); ++i) {
            if ((args[i] == "-o" || args[i] == "--output") && i + 1 < args.size())
                output = args[++i];
            else if (job.empty() && !args[i].empty() && args[i][0] != '-')
                job = args[i];
            else {
                std::cerr << "camwb-cli: unexpected argument '" << args[i] << "'\n";
                printUsage(std::cerr);
                return kExitUsage;
            }
        }
        if (job.empty() || output.empty()) {
            std::cerr << "camwb-cli: run needs a job file and -o <output file>\n";
            return kExitUsage;
        }
        return runJob(job, output);
    }
    std::cerr << "camwb-cli: unknown command '" << args[0] << "'\n";
    printUsage(std::cerr);
    return kExitUsage;
}
