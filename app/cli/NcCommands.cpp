// camwb-cli nc trace: reads an NC program in its dialect and writes what the control would do,
// one motion per line (nc/MotionTrace.h), with the program's diagnostics on stderr.
#include "Cli.h"

#include "base/AtomicFile.h"
#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "nc/MotionTrace.h"
#include "nc/ToolTable.h"

#include <charconv>
#include <cstdio>
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
    std::string toolTable;
};

// Parses the options of `nc trace`; returns an error message, empty when they are fine.
std::string parseTraceOptions(const std::vector<std::string>& args, TraceOptions& options)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        const bool takesValue = arg == "--dialect" || arg == "--machine" || arg == "--format" || arg == "-o" ||
                                arg == "--output" || arg == "--max-blocks" || arg == "--tool-table";
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
        } else if (arg == "--tool-table") {
            options.toolTable = value;
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
    auto found = machineOption(options.machineId);
    if (!found)
        return fail(found.error().toString());
    const std::optional<kinematics::Machine> machine = std::move(found).value();
    if (machine)
        interpretOptions.machine = &*machine;
    if (options.maxBlocks > 0)
        interpretOptions.maxBlocks = options.maxBlocks;
    std::optional<nc::ToolTable> toolTable;
    if (!options.toolTable.empty()) {
        auto read = nc::readToolTable(options.toolTable);
        if (!read)
            return fail(read.error().toString());
        toolTable = std::move(read).value();
        interpretOptions.toolTable = &*toolTable;
    }

    // The trace is written while the interpreter runs, nothing recorded: to stdout, or to a
    // temporary file beside -o that replaces it only when complete.
    std::optional<base::AtomicFileWriter> file;
    if (!options.output.empty()) {
        file.emplace(options.output);
        if (const base::Status opened = file->open(); !opened)
            return fail(opened.error().toString());
    }
    nc::MotionTraceWriter trace(options.input, options.format, [&file](std::string_view text) {
        if (file) {
            file->write(text);  // a failure shows at commit()
            return true;
        }
        return std::fwrite(text.data(), 1, text.size(), stdout) == text.size();
    });
    const nc::InterpretResult result = nc::interpretFile(options.input, options.dialect, interpretOptions, trace);
    printDiagnostics(result.diagnostics);
    if (result.diagnosticsDropped > 0)
        std::cerr << "camwb-cli: note: " << result.diagnosticsDropped << " more diagnostics not shown\n";

    const bool traced = trace.finish(result.files);
    if (file) {
        if (const base::Status written = file->commit(); !written)
            return fail(written.error().toString());
    } else if (!traced || std::fflush(stdout) != 0) {
        return fail("cannot write the trace to standard output");
    }
    return result.hasErrors() ? kExitError : kExitOk;
}

}  // namespace camwb::cli
