// What the camwb-cli commands share: usage, messages, the posting options and atomic output.
#include "Cli.h"

#include "base/Result.h"
#include "document/JobFile.h"
#include "document/OperationParameters.h"
#include "document/StockBlank.h"
#include "post/PostInfo.h"
#include "toolpath/ClText.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string_view>

namespace camwb::cli {

namespace fs = std::filesystem;

void printSynopsis(std::ostream& out)
{
    out << "usage: camwb-cli --version\n"
           "       camwb-cli run <job.camwb> -o <output file> [--post-path DIR]... [--set "
           "<op>.<parameter>=<value>]...\n"
           "       camwb-cli posts [<post id>] [--post-path DIR]...\n"
           "       camwb-cli post <input> [--post <id>] [--machine <id>] [--property name=value]...\n"
           "                      [-o <output file>] [--input-format job|apt|freecad-dump|trace] [--post-path DIR]...\n"
           "                      [--project NAME] [--stock x0,y0,z0,x1,y1,z1]\n"
           "                      [--set <op>.<parameter>=<value>]...\n"
           "       camwb-cli cl <job.camwb> [-o <output file>] [--set <op>.<parameter>=<value>]...\n"
           "       camwb-cli nc trace <NC file> [--dialect sinumerik|heidenhain|iso] [--machine <id>]\n"
           "                      [--format text|jsonl] [-o <output file>] [--max-blocks N] [--tool-table FILE]\n"
           "       camwb-cli sim <job.camwb | NC file | CL file> [--machine <id>] [--resolution mm] [--tolerance mm]\n"
           "                      [--report <file.json>|-] [--stl <cut.stl>] [--trace-csv <out.csv>] [--sample-ms ms]\n"
           "                      [--model <part>] [--stock x0,y0,z0,x1,y1,z1|<blank file>] [--tool-table FILE]\n"
           "                      [--stock-profile x0,z0,x1,z1|<X,Z file> --insert-width mm [--design-profile ...]]\n"
           "                      [--measured <trace.csv> [--measured-z-offset mm]] [--analysis]\n"
           "                      [--set <op>.<parameter>=<value>]...\n"
           "       camwb-cli setup-sheet <job.camwb> -o <sheet.html> [--pdf <sheet.pdf>] [--machine <id>]\n"
           "                      [--no-sim] [--margin mm]\n";
}

void printUsage(std::ostream& out)
{
    printSynopsis(out);
    out << "\n"
           "run:   loads the job and its model, recomputes every operation, posts the program with\n"
           "       the job's post, machine and post properties and writes the NC file.\n"
           "       --set <op>.<parameter>=<value> (run, post, cl and sim of a job; repeatable) sets an\n"
           "       operation's parameter for this run only (the job file is not changed): <op> is the\n"
           "       operation's name or its number (1 = the first), <parameter> its name in the job file;\n"
           "       a groove also takes the thesis' R names (R0..R8, R10, R11, R30; R9 sets the insert\n"
           "       width, i.e. the diameter of the operation's tool). The operation checks the value\n"
           "       when it is computed. Example: run groove-kod1.camwb -o out.mpf --set Groove.R3=160\n"
           "posts: lists the posts (id, vendor, description, extension, origin); with an id, shows\n"
           "       that post's capabilities and properties.\n"
           "post:  posts a job (.camwb), an APT CL file (.apt .aptsource .cl .cls), a FreeCAD path dump\n"
           "       (.dump) or a CL trace (.trace); the format comes from the extension unless\n"
           "       --input-format names it.\n"
           "       A job brings its own post, machine and properties; the options override them.\n"
           "       Without -o the NC goes beside the input, named after it with the post's extension.\n"
           "       --project and --stock give what a CL file lacks (the job name and stock box some posts\n"
           "       write in their header, e.g. Klartext's BLK FORM); for a job they override its own.\n"
           "cl:    recomputes the job's operations and writes their CL records as a trace (one line per\n"
           "       record, the format in docs/architecture.md) instead of NC; each operation's counts of\n"
           "       lines, arcs, helices and cycles and its warnings go to stderr.\n"
           "nc trace: interprets an NC program in its dialect (guessed from the name and content unless\n"
           "       --dialect says) and writes one line per motion: source line, kind, end point, arc\n"
           "       centre, feed, spindle, tool. Diagnostics go to stderr with file, line and column;\n"
           "       the exit code is 1 when there are errors. Subprograms are looked up beside the file.\n"
           "       Cutter compensation moves the contour by the tool radius: from the program's own tool\n"
           "       data, else from --tool-table (LinuxCNC format: T<n> P<pocket> D<diameter> Z<length>).\n"
           "sim:   simulates a job (its model, stock, tools and machine) or an NC program (--model is the\n"
           "       part to compare with, --stock the blank: a box or a mesh/STEP file; --machine its\n"
           "       limits): the cycle time with the machine's accelerations, the stock cut at --resolution\n"
           "       (a height field, or tri-dexels when the tool tilts), and every check with file and\n"
           "       line: rapids through stock, gouges deeper than --tolerance (default 0.02 mm), shank or\n"
           "       holder in the stock, plunges of tools that do not cut at their centre, cutting with the\n"
           "       spindle off, machine limits. Exit code 1 when any of them is an error. --report writes\n"
           "       them all as JSON, --stl the cut stock, --trace-csv the motion sampled every --sample-ms\n"
           "       (default 3 ms). An NC program's tools are sized from --tool-table (as for nc trace).\n"
           "       A CL file (.apt .aptsource .cl .cls .dump .trace) is read as post reads it.\n"
           "       Turning: --stock-profile gives the revolved stock in XZ (X a radius), a rectangle or a file of\n"
           "       X,Z points, --design-profile the contour it must not cut into, --insert-width the grooving\n"
           "       insert (reference: its left corner); rapids through the stock and gouges are errors.\n"
           "       A job with groove operations is checked so without these options: its stock is the\n"
           "       grooves' shaft, the contour their offset contour, the insert the groove's tool.\n"
           "       --measured reads a trace the control recorded (TNCscope CSV: time, then nominal and actual\n"
           "       X Y Z and the two rotaries) through the machine's chain onto the workpiece: how far the\n"
           "       actual tip followed the nominal one and strayed from the program, and each axis' reversals.\n"
           "       --analysis adds the same analysis of the planned motion (reversals, the tip's top feed\n"
           "       and, on a five-axis machine, the top of the part of it each rotary axis makes: v_A, v_C).\n"
           "setup-sheet: writes the operator's setup sheet: the tools with the stick-out each needs (its\n"
           "       deepest tip below the stock or model top plus --margin, default 2 mm), stock and work\n"
           "       zero, machine and post, each operation's tool, feeds, heights, time and picture, and\n"
           "       what the simulator found (unless --no-sim); pictures in <sheet>-images/ beside it,\n"
           "       optionally a PDF. Nothing is replaced unless everything was written.\n"
           "\n"
           "Posts are looked up in --post-path folders, $CAMWB_POST_PATH, ~/.local/share/camwb/posts\n"
           "and the built-in folders, in that order: a user's post overrides a built-in one.\n"
           "NC files are written atomically: on any error the output file is left untouched.\n"
           "Output is deterministic; SOURCE_DATE_EPOCH and CAMWB_USER set the header's date and user.\n"
           "Exit codes: 0 success, 1 error, 2 usage error.\n";
}

int fail(const std::string& message)
{
    std::cerr << "camwb-cli: error: " << message << "\n";
    return kExitError;
}

int usageError(const std::string& message)
{
    // The reason, then the commands' synopsis and where the rest is: the whole help (90 lines)
    // would scroll the reason off the screen.
    std::cerr << "camwb-cli: " << message << "\n";
    printSynopsis(std::cerr);
    std::cerr << "camwb-cli --help says what each command does.\n";
    return kExitUsage;
}

void printDiagnostic(const base::Diagnostic& diagnostic)
{
    std::cerr << (diagnostic.file.empty() ? "camwb-cli: " : "") << base::formatDiagnostic(diagnostic) << "\n";
}

int printDiagnostics(const std::vector<base::Diagnostic>& diagnostics)
{
    for (const base::Diagnostic& diagnostic : diagnostics)
        printDiagnostic(diagnostic);
    return static_cast<int>(base::countOf(diagnostics, base::Severity::Warning));
}

base::Result<std::optional<kinematics::Machine>> machineOption(const std::string& id)
{
    if (id.empty())
        return std::optional<kinematics::Machine>();
    auto found = kinematics::findMachine(id, kinematics::defaultMachineDirs());
    if (!found)
        return found.error();
    return std::optional<kinematics::Machine>(std::move(found).value());
}

std::optional<base::Box3> parseStockBox(const std::string& text, std::string& error)
{
    double v[6];
    std::string_view rest = text;
    for (int i = 0; i < 6; ++i) {
        const std::size_t comma = i < 5 ? rest.find(',') : rest.size();
        const std::optional<double> number =
            comma == std::string_view::npos ? std::nullopt : toolpath::parseNumber(rest.substr(0, comma));
        if (!number) {
            error = "--stock needs six numbers x0,y0,z0,x1,y1,z1, got '" + text + "'";
            return std::nullopt;
        }
        v[i] = *number;
        rest.remove_prefix(std::min(comma + 1, rest.size()));
    }
    if (!(v[0] < v[3] && v[1] < v[4] && v[2] < v[5])) {
        error = "--stock " + text + ": each minimum must be below its maximum";
        return std::nullopt;
    }
    return base::Box3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, false};
}

bool takeSetOption(const std::vector<std::string>& args, std::size_t& i, std::vector<std::string>& sets,
                   std::string& error)
{
    if (args[i] != "--set")
        return false;
    if (i + 1 >= args.size()) {
        error = "--set needs <operation>.<parameter>=<value>";
        return true;
    }
    const std::string& value = args[++i];
    const std::size_t equals = value.find('=');
    const std::size_t dot = value.rfind('.', equals);
    if (equals == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == equals ||
        equals + 1 == value.size())
        error = "--set needs <operation>.<parameter>=<value>, got '" + value + "'";
    else
        sets.push_back(value);
    return true;
}

// One --set (already of the form <operation>.<parameter>=<value>) applied to the job.
base::Status applySet(document::Job& job, const std::string& set)
{
    const std::size_t equals = set.find('=');
    const std::size_t dot = set.rfind('.', equals);
    const auto index = document::findOperation(job, set.substr(0, dot));
    if (!index)
        return base::makeError("--set " + set + ": " + index.error().message);
    const base::Status status = document::setOperationParameter(
        job, index.value(), set.substr(dot + 1, equals - dot - 1), set.substr(equals + 1));
    if (!status)
        return base::makeError("--set " + set + ": " + status.error().message);
    return {};
}

bool takePostOption(const std::vector<std::string>& args, std::size_t& i, PostOptions& options, std::string& error)
{
    if (takeSetOption(args, i, options.sets, error))
        return true;
    const std::string& arg = args[i];
    const bool known = arg == "--post" || arg == "--machine" || arg == "--property" || arg == "--post-path" ||
                       arg == "-o" || arg == "--output" || arg == "--project" || arg == "--stock";
    if (!known)
        return false;
    if (i + 1 >= args.size()) {
        error = arg + " needs a value";
        return true;
    }
    const std::string& value = args[++i];
    if (arg == "--post") {
        options.postId = value;
    } else if (arg == "--machine") {
        options.machineId = value;
    } else if (arg == "--post-path") {
        options.postPaths.push_back(value);
    } else if (arg == "--property") {
        auto assignment = post::splitPropertyAssignment(value);
        if (!assignment)
            error = assignment.error().message;
        else
            options.properties[assignment->first] = assignment->second;
    } else if (arg == "--project") {
        options.project = value;
    } else if (arg == "--stock") {
        options.stock = parseStockBox(value, error);
    } else {
        options.output = value;
    }
    return true;
}

int postToFile(const post::PostProcessor& post, const toolpath::Toolpath& toolpath, const post::RunOptions& options,
               const std::string& outputPath)
{
    auto summary = post.runToFile(toolpath, options, outputPath);
    if (!summary)
        return fail(summary.error().toString());
    const int warnings = printDiagnostics(summary->messages);
    std::cout << "camwb-cli: wrote " << outputPath << " (" << summary->lines << " lines, " << warnings
              << (warnings == 1 ? " warning)" : " warnings)");
    // The files the post wrote beside the program (a main program's subprograms), by name.
    for (std::size_t i = 0; i < summary->companionPaths.size(); ++i)
        std::cout << (i == 0 ? " and beside it " : ", ") << fs::path(summary->companionPaths[i]).filename().string();
    std::cout << "\n";
    return kExitOk;
}

std::optional<ComputedJob> computeJobFile(const std::string& path, const std::vector<std::string>& sets)
{
    auto job = document::loadJob(path);
    if (!job) {
        fail(job.error().toString());
        return std::nullopt;
    }
    for (const std::string& set : sets) {
        if (const base::Status applied = applySet(job.value(), set); !applied) {
            fail(applied.error().message);
            return std::nullopt;
        }
    }
    auto model = document::loadJobModel(job.value());
    if (!model) {
        fail(model.error().toString());
        return std::nullopt;
    }
    document::resolveJobStock(job.value(), model.value());  // as the Workbench does after a load
    ComputedJob computed;
    auto blank = document::loadStockBlank(job.value(), path);
    if (!blank) {
        fail(blank.error().toString());
        return std::nullopt;
    }
    document::resolveStockBlank(job->stock, blank.value());
    auto program = document::computeProgram(job.value(), model.value(), {}, &computed.report);
    if (!program) {
        fail(path + ": " + program.error().message);
        return std::nullopt;
    }
    for (base::Diagnostic& warning : computed.report.warnings)
        warning.file = path;
    computed.job = std::move(job).value();
    computed.program = std::move(program).value();
    computed.model = std::move(model).value();
    computed.stockBlank = std::move(blank).value();
    return computed;
}

}  // namespace camwb::cli
