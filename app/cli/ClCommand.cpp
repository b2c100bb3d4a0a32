// camwb-cli cl <job.camwb> [-o <file>] [--set op.param=value]...: recompute a job's operations and write the CL trace
// (toolpath/TraceWriter.h) instead of NC, with each operation's motion counts on stderr, so
// that what an operation produced can be read, diffed and kept as a golden before any post.
#include "Cli.h"

#include "base/AtomicFile.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "toolpath/TraceWriter.h"

#include <iostream>

namespace camwb::cli {

int clCommand(const std::vector<std::string>& args)
{
    std::string jobPath, output;
    std::vector<std::string> sets;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string error;
        if (takeSetOption(args, i, sets, error)) {
            if (!error.empty())
                return usageError(error);
        } else if (args[i] == "-o" || args[i] == "--output") {
            if (i + 1 >= args.size())
                return usageError(args[i] + " needs a file name");
            output = args[++i];
        } else if (jobPath.empty() && !args[i].empty() && args[i][0] != '-') {
            jobPath = args[i];
        } else {
            return usageError("unexpected argument '" + args[i] + "'");
        }
    }
    if (jobPath.empty())
        return usageError("cl needs a job file");

    const std::optional<ComputedJob> computed = computeJobFile(jobPath, sets);
    if (!computed)
        return kExitError;
    const document::ProgramReport& report = computed->report;

    for (std::size_t i = 0; i < report.counts.size(); ++i) {
        const document::Operation& op = computed->job.operations[i];
        const ops::MotionCounts& c = report.counts[i];
        if (!op.enabled) {
            std::cerr << "camwb-cli: " << document::kindLabel(op.kind()) << " \"" << op.name() << "\": disabled\n";
            continue;
        }
        std::cerr << "camwb-cli: " << document::kindLabel(op.kind()) << " \"" << op.name() << "\": " << c.lines
                  << " lines, " << c.arcs << " arcs, " << c.helices << " helices, " << c.cycles << " cycles, "
                  << c.rapids << " rapids\n";
    }
    printDiagnostics(report.warnings);

    const std::string trace = toolpath::traceOf(computed->program);
    if (output.empty()) {
        std::cout << trace;
        return kExitOk;
    }
    if (base::Status written = base::writeFileAtomically(output, trace); !written)
        return fail(written.error().toString());
    return kExitOk;
}

}  // namespace camwb::cli
