// camwb-cli posts [<id>] and camwb-cli post <input> ...: list the posts, show one, and post a job
// or a CL file (APT, FreeCAD dump) through any post.
#include "Cli.h"

#include "base/NumberFormat.h"
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "post/PostRegistry.h"
#include "toolpath/ClImport.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>

namespace camwb::cli {

namespace {

namespace fs = std::filesystem;

std::string number(double value) { return base::NumberFormat{6, true}.format(value); }

std::string joined(const std::vector<std::string>& items, const char* separator = " ")
{
    std::string text;
    for (const std::string& item : items)
        text += (text.empty() ? "" : separator) + item;
    return text;
}

std::string origin(const post::PostEntry& entry)
{
    // A built-in post hiding another built-in one (installed and source tree) is not news to a user.
    if (entry.builtIn)
        return "built-in";
    return entry.shadows.empty() ? "user" : "user (overrides " + entry.shadows.front() + ")";
}

void printTable(const std::vector<std::vector<std::string>>& rows)
{
    std::vector<std::size_t> widths;
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c) {
            widths.resize(std::max(widths.size(), row.size()));
            widths[c] = std::max(widths[c], row[c].size());
        }
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c)
            line += c + 1 < row.size() ? row[c] + std::string(widths[c] - row[c].size() + 2, ' ') : row[c];
        std::cout << line << "\n";
    }
}

int showPost(const post::PostEntry& entry, const post::PostInfo& info)
{
    const post::PostCapabilities& caps = info.capabilities;
    std::cout << info.id << ": " << info.description << "\n";
    std::cout << "  file:       " << info.filePath << " (" << origin(entry) << ")\n";
    std::cout << "  vendor:     " << info.vendor << "\n";
    std::cout << "  extension:  " << info.extension << "\n";
    std::cout << "  machines:   " << (info.machines.empty() ? "any" : joined(info.machines))
              << (info.defaultMachine.empty() ? "" : " (default " + info.defaultMachine + ")") << "\n";
    std::cout << "  controls:   " << (info.controls.empty() ? "any" : joined(info.controls)) << "\n";
    std::cout << "  arcs:       planes " << joined(caps.arcPlanes) << ", helical "
              << (caps.helicalPlanes.empty() ? "none" : joined(caps.helicalPlanes)) << ", at most "
              << number(caps.maxArcSweepDeg) << " deg per block, " << (caps.arcRadiusWords ? "radius" : "centre")
              << " words, radius " << number(caps.minArcRadiusMm) << ".." << number(caps.maxArcRadiusMm)
              << " mm; other arcs become lines within " << number(caps.toleranceMm) << " mm\n";
    std::cout << "  cycles:     "
              << (caps.cyclesDeclared ? (caps.cycles.empty() ? "none" : joined(caps.cycles)) + " native, others"
                                      : std::string("native when the post has onCycle, else all"))
              << " expanded into moves\n";
    std::cout << "  axes:       " << caps.maxAxes << "\n";
    if (info.properties.empty()) {
        std::cout << "  properties: none\n";
        return kExitOk;
    }
    std::cout << "  properties:\n";
    std::vector<std::vector<std::string>> rows{{"    name", "type", "default", "accepts", "title"}};
    for (const post::PropertyDef& def : info.properties) {
        std::string accepts;
        if (def.type == post::PropertyType::Enum)
            accepts = joined(def.values, "|");
        else if (def.min || def.max)
            accepts = (def.min ? number(*def.min) : "") + ".." + (def.max ? number(*def.max) : "");
        rows.push_back({"    " + def.name, post::propertyTypeName(def.type), def.defaultValue, accepts, def.title});
    }
    printTable(rows);
    return kExitOk;
}

// What `post` reads: a job, or a CL file in one of the importers' formats.
struct InputKind {
    bool job = false;
    toolpath::ClFormat cl = toolpath::ClFormat::Apt;
};

std::optional<InputKind> inputKind(const std::string& name)
{
    if (name == "job")
        return InputKind{true};
    if (auto cl = toolpath::clFormatFromName(name))
        return InputKind{false, *cl};
    return std::nullopt;
}

std::optional<InputKind> inputKindOfFile(const std::string& path)
{
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    if (extension == ".camwb")
        return InputKind{true};
    if (auto cl = toolpath::clFormatFromExtension(path))
        return InputKind{false, *cl};
    return std::nullopt;
}

}  // namespace

int postsCommand(const std::vector<std::string>& args)
{
    PostOptions options;
    std::string id;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--post-path" && i + 1 < args.size())
            options.postPaths.push_back(args[++i]);
        else if (id.empty() && !args[i].empty() && args[i][0] != '-')
            id = args[i];
        else
            return usageError("unexpected argument '" + args[i] + "'");
    }
    const std::vector<post::PostEntry> entries = post::listPosts(post::defaultPostDirs(options.postPaths));
    if (!id.empty()) {
        const auto entry = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.id == id; });
        if (entry == entries.end())
            return fail(post::findPost(id, post::defaultPostDirs(options.postPaths)).error().message);
        auto loaded = post::PostProcessor::load(entry->path);
        if (!loaded)
            return fail(loaded.error().toString());
        return showPost(*entry, loaded->info());
    }
    std::vector<std::vector<std::string>> rows{{"id", "vendor", "description", "extension", "origin"}};
    for (const post::PostEntry& entry : entries) {
        auto loaded = post::PostProcessor::load(entry.path);
        if (!loaded) {
            std::cerr << "camwb-cli: warning: cannot load post " << entry.id << ": " << loaded.error().toString()
                      << "\n";
            rows.push_back({entry.id, "", "(cannot be loaded, see above)", "", origin(entry)});
            continue;
        }
        const post::PostInfo& info = loaded->info();
        rows.push_back({info.id, info.vendor, info.description, info.extension, origin(entry)});
    }
    printTable(rows);
    return kExitOk;
}

int postCommand(const std::vector<std::string>& args)
{
    std::string input, formatName;
    PostOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string error;
        if (takePostOption(args, i, options, error)) {
            if (!error.empty())
                return usageError(error);
        } else if (args[i] == "--input-format" && i + 1 < args.size()) {
            formatName = args[++i];
        } else if (input.empty() && !args[i].empty() && args[i][0] != '-') {
            input = args[i];
        } else {
            return usageError("unexpected argument '" + args[i] + "'");
        }
    }
    if (input.empty())
        return usageError("post needs an input file");
    const std::optional<InputKind> format = formatName.empty() ? inputKindOfFile(input) : inputKind(formatName);
    if (!format)
        return usageError(formatName.empty()
                              ? "cannot tell the format of " + input +
                                    " from its extension; give --input-format job|apt|freecad-dump|trace"
                              : "unknown input format '" + formatName + "' (job, apt, freecad-dump, trace)");

    if (!format->job && !options.sets.empty())
        return usageError("--set changes a job's operation; " + input + " is not a job");

    toolpath::Toolpath program;
    std::string postId = options.postId, machineId = options.machineId;
    std::map<std::string, std::string> properties;
    post::JobFacts jobFacts;
    document::Job jobOutput;  // the job's default output (name, folder), when posting a job
    if (format->job) {
        std::optional<ComputedJob> computed = computeJobFile(input, options.sets);
        if (!computed)
            return kExitError;
        printDiagnostics(computed->report.warnings);
        program = std::move(computed->program);
        const document::Job& job = computed->job;
        postId = postId.empty() ? job.postId : postId;
        machineId = machineId.empty() ? job.machineId : machineId;
        properties = job.postProperties;
        jobFacts = document::jobFacts(job);
        jobOutput.outputName = job.outputName;
        jobOutput.outputFolder = job.outputFolder;
    } else {
        auto imported = toolpath::readClFile(input, format->cl);
        if (!imported)
            return fail(imported.error().toString());
        printDiagnostics(imported->warnings);
        program = std::move(imported->toolpath);
        if (postId.empty())
            return usageError("posting a CL file needs --post <id> (see camwb-cli posts)");
    }
    for (const auto& [name, value] : options.properties)
        properties[name] = value;

    auto path = post::findPost(postId, post::defaultPostDirs(options.postPaths));
    if (!path)
        return fail(path.error().message);
    auto post = post::PostProcessor::load(path.value());
    if (!post)
        return fail(post.error().toString());
    auto machine = post::machineForPost(post->info(), machineId, kinematics::defaultMachineDirs());
    if (!machine)
        return fail(machine.error().toString());

    std::string output = options.output;
    if (output.empty())
        output = document::jobOutputPath(jobOutput, input, post->info().extension);
    if (output.empty())
        output = fs::path(input).replace_extension(post->info().extension).string();
    std::error_code ec;
    if (fs::equivalent(output, input, ec))
        return fail("the output " + output + " would overwrite the input; give -o <output file>");

    post::RunOptions runOptions;
    runOptions.context = post::PostContext::fromEnvironment(fs::path(input).stem().string());
    runOptions.context.outputName = fs::path(output).stem().string();
    if (!options.project.empty())
        jobFacts.name = options.project;
    if (options.stock)
        jobFacts.stock = options.stock;
    runOptions.job = jobFacts;
    runOptions.properties = properties;
    runOptions.machine = std::move(machine).value();
    return postToFile(post.value(), program, runOptions, output);
}

}  // namespace camwb::cli
