// camwb-cli run <job.camwb> -o <file>: recompute a job's operations and post them with the job's
// own post, machine and properties. The same as `camwb-cli post <job> -o <file>` without overrides.
#include "Cli.h"

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
    if (!options.postId.empty() || !options.machineId.empty() || !options.properties.empty() ||
        !options.project.empty() || options.stock)
        return usageError("run posts with the job's own settings; use `camwb-cli post` to override them");
    std::vector<std::string> postArgs = args;
    postArgs.insert(postArgs.end(), {"--input-format", "job"});  // a job whatever its extension
    return postCommand(postArgs);
}

}  // namespace camwb::cli
