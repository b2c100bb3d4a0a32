// camwb-cli setup-sheet: the operator's setup sheet of a job, headless: its facts
// (document/SetupSheet.h), pictures drawn without OpenGL and the HTML (and PDF) written by the
// sheet's painter library, loaded for this command only (sheet/SheetPainter.h); main() makes its
// GUI application on the offscreen platform.
#include "Cli.h"

#include "base/NumberFormat.h"
#include "document/JobFile.h"
#include "document/SetupSheet.h"
#include "occ/Model.h"
#include "post/PostRegistry.h"
#include "sheet/SheetHtml.h"
#include "sheet/SheetPainter.h"
#include "toolpath/ClText.h"

#include <iostream>
#include <set>

namespace camwb::cli {

namespace {

struct SheetCommandOptions {
    std::string job;
    std::string html;
    std::string pdf;
    std::string machineId;
    bool simulate = true;
    double marginMm = 2;
};

std::string parseSheetOptions(const std::vector<std::string>& args, SheetCommandOptions& options)
{
    static const std::set<std::string> kTakesValue{"-o", "--output", "--pdf", "--machine", "--margin"};
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--no-sim") {
            options.simulate = false;
            continue;
        }
        if (kTakesValue.count(arg) == 0) {
            if (!arg.empty() && arg[0] == '-')
                return "unknown option '" + arg + "'";
            if (!options.job.empty())
                return "setup-sheet takes one job, got '" + options.job + "' and '" + arg + "'";
            options.job = arg;
            continue;
        }
        if (i + 1 >= args.size())
            return arg + " needs a value";
        const std::string& value = args[++i];
        if (arg == "--margin") {
            const std::optional<double> margin = toolpath::parseNumber(value);  // no "inf" or "nan"
            if (!margin || *margin < 0)
                return "--margin needs a number of mm, 0 or more, not '" + value + "'";
            options.marginMm = *margin;
        } else if (arg == "--pdf") {
            options.pdf = value;
        } else if (arg == "--machine") {
            options.machineId = value;
        } else {
            options.html = value;
        }
    }
    if (options.job.empty())
        return "setup-sheet needs a job (.camwb)";
    if (options.html.empty())
        return "setup-sheet needs -o <sheet.html>";
    return {};
}

}  // namespace

int setupSheetCommand(const std::vector<std::string>& args)
{
    SheetCommandOptions options;
    if (const std::string error = parseSheetOptions(args, options); !error.empty())
        return usageError(error);
    auto machine = machineOption(options.machineId);
    if (!machine)
        return fail(machine.error().toString());
    std::optional<ComputedJob> computed = computeJobFile(options.job);
    if (!computed)
        return kExitError;
    printDiagnostics(computed->report.warnings);
    const occ::Model& model = *computed->model;

    document::SheetOptions sheetOptions;
    sheetOptions.stickOutMarginMm = options.marginMm;
    sheetOptions.simulate = options.simulate;
    sheetOptions.machine = std::move(machine).value();
    sheetOptions.postDirs = post::defaultPostDirs();
    auto sheet = document::collectSetupSheet(computed->job, options.job, model, computed->program, sheetOptions);
    if (!sheet)
        return fail(sheet.error().toString());

    const sheet::HeadlessSheet headless{sheet.value(),     model.mesh(), computed->job.stock.box(),
                                        computed->program, options.html, options.pdf};
    if (const base::Status written = sheet::writeHeadlessSheet(headless); !written)
        return fail(written.error().toString());

    std::cout << "setup sheet " << options.html << (options.pdf.empty() ? "" : " and " + options.pdf) << ": "
              << sheet.value().tools.size() << " tools, " << sheet.value().operations.size()
              << " operations, cycle time " << sheet::formatDuration(sheet.value().cycleSeconds) << "\n";
    const document::SheetVerification& verified = sheet.value().verification;
    const int errors = verified.gouges + verified.holderCollisions + verified.rapidsInStock + verified.machineLimits +
                       verified.otherErrors;
    if (verified.run && errors > 0)
        std::cerr << "camwb-cli: warning: the simulator found " << errors << " errors; the sheet lists them\n";
    return kExitOk;
}

}  // namespace camwb::cli
