// camwb-cli run <job.camwb> -o <file>: recompute a job's operations and post them with the job's
// own post, machine and properties. The same as `camwb-cli post <job> -o <file>` without overrides.
// Without -o, the job's own output name and folder (Job::outputName/outputFolder) are used.
#include "Cli.h"
#include "document/JobFile.h"

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
    if (jobPath.empty())
        return usageError("run needs a job file and -o <output file>");
    if (options.output.empty()) {
        // Without -o the job's own output (Job::outputName) is used; a job without one needs -o.
        auto job = document::loadJob(jobPath);
        if (!job)
            return fail(job.error().toString());
        if (job->outputName.empty())
            return usageError("run needs -o <output file> (the job names no output file)");
    }
    if (!options.postId.empty() || !options.machineId.empty() || !options.properties.empty() ||
        !options.project.empty() || options.stock)
        return usageError("run posts with the job's own settings; use `camwb-cli post` to override them");
    std::vector<std::string> postArgs = args;
    postArgs.insert(postArgs.end(), {"--input-format", "job"});  // a job whatever its extension
    return postCommand(postArgs);
}

}  // namespace camwb::cli
