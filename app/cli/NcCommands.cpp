// camwb-cli nc trace: reads an NC program in its dialect and writes what the control would do,
// one motion per line (nc/MotionTrace.h), with the program's diagnostics on stderr.
#include "Cli.h"

#include "base/AtomicFile.h"
#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "toolpath/ToolpathRecorder.h"

#include <charconv>
#include <iostream>
#include <optional>

namespace camwb::cli {

namespace {

struct TraceOptions {
    std::string input;
    std::optional<nc::Dialect> dialect;
    std::string machineId;
    nc::TraceFormat format = nc::TraceFormat::Text;
    std::string output;
    std::int64_t maxBlocks = 0;  // 0: the interpreter's default
};

// Parses the options of `nc trace`; returns an error message, empty when they are fine.
std::string parseTraceOptions(const std::vector<std::string>& args, TraceOptions& options)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        const bool takesValue = arg == "--dialect" || arg == "--machine" || arg == "--format" || arg == "-o" ||
                                arg == "--output" || arg == "--max-blocks";
        if (!takesValue) {
            if (!arg.empty() && arg[0] == '-' && arg != "-")
                return "unknown option '" + arg + "'";
            if (!options.input.empty())
                return "nc trace takes one NC file";
            options.input = arg;
            continue;
        }
        if (i + 1 >= args.size())
            return arg + " needs a value";
        const std::string& value = args[++i];
        if (arg == "--dialect") {
            options.dialect = nc::dialectFromName(value);
            if (!options.dialect)
                return "unknown dialect '" + value + "' (sinumerik, heidenhain or iso)";
        } else if (arg == "--machine") {
            options.machineId = value;
        } else if (arg == "--format") {
            if (value == "text")
                options.format = nc::TraceFormat::Text;
            else if (value == "jsonl")
                options.format = nc::TraceFormat::Jsonl;
            else
                return "unknown trace format '" + value + "' (text or jsonl)";
        } else if (arg == "--max-blocks") {
            const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), options.maxBlocks);
            if (ec != std::errc() || end != value.data() + value.size() || options.maxBlocks <= 0)
                return "--max-blocks needs a positive whole number, not '" + value + "'";
        } else {
            options.output = value;
        }
    }
    if (options.input.empty())
        return "nc trace needs an NC file";
    return {};
}

}  // namespace

int ncCommand(const std::vector<std::string>& args)
{
    if (args.empty() || args[0] != "trace")
        return usageError(args.empty() ? "nc needs a subcommand (trace)" : "unknown nc subcommand '" + args[0] + "'");
    TraceOptions options;
    if (const std::string error = parseTraceOptions({args.begin() + 1, args.end()}, options); !error.empty())
        return usageError(error);

    nc::InterpretOptions interpretOptions;
    std::optional<kinematics::Machine> machine;
    if (!options.machineId.empty()) {
        auto found = kinematics::findMachine(options.machineId, kinematics::defaultMachineDirs());
        if (!found)
            return fail(found.error().toString());
        machine = std::move(found).value();
        interpretOptions.machine = &*machine;
    }
    if (options.maxBlocks > 0)
        interpretOptions.maxBlocks = options.maxBlocks;

    toolpath::ToolpathRecorder recorder;
    const nc::InterpretResult result = nc::interpretFile(options.input, options.dialect, interpretOptions, recorder);
    printDiagnostics(result.diagnostics);
    if (result.diagnosticsDropped > 0)
        std::cerr << "camwb-cli: note: " << result.diagnosticsDropped << " more diagnostics not shown\n";

    const std::string trace = nc::motionTrace(recorder.toolpath(), result.files, options.format);
    if (options.output.empty()) {
        std::cout << trace;
        std::cout.flush();
    } else if (const base::Status written = base::writeFileAtomically(options.output, trace); !written) {
        return fail(written.error().toString());
    }
    return result.hasErrors() ? kExitError : kExitOk;
}

}  // namespace camwb::cli
