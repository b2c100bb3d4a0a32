// camwb-cli run <job.camwb> -o <file>: recompute a job's operations and post them.
#include "Cli.h"

#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "post/PostRegistry.h"

#include <filesystem>

namespace camwb::cli {

int runCommand(const std::vector<std::string>& args)
{
    std::string jobPath;
    PostOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string error;
        if (takePostOption(args, i, options, error)) {
            if (!error.empty())
                return usageError(error);
            continue;
        }
        if (!jobPath.empty() || args[i].empty() || args[i][0] == '-')
            return usageError("unexpected argument '" + args[i] + "'");
        jobPath = args[i];
    }
    if (jobPath.empty() || options.output.empty())
        return usageError("run needs a job file and -o <output file>");
    if (!options.postId.empty() || !options.machineId.empty() || !options.properties.empty())
        return usageError("run posts with the job's own settings; use `camwb-cli post` to override them");

    auto job = document::loadJob(jobPath);
    if (!job)
        return fail(job.error().toString());
    auto model = document::loadJobModel(job.value());
    if (!model)
        return fail(model.error().toString());
    auto program = document::computeProgram(job.value(), model.value());
    if (!program)
        return fail(jobPath + ": " + program.error().message);
    auto post = document::loadJobPost(job.value(), post::defaultPostDirs(options.postPaths));
    if (!post)
        return fail(post.error().toString());
    const std::string programName = std::filesystem::path(jobPath).stem().string();
    auto runOptions = document::jobRunOptions(
        job.value(), post.value(), post::PostContext::fromEnvironment(programName), kinematics::defaultMachineDirs());
    if (!runOptions)
        return fail(jobPath + ": " + runOptions.error().toString());
    return postToFile(post.value(), program.value(), runOptions.value(), options.output);
}

}  // namespace camwb::cli
