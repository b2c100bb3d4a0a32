// camwb-cli setup-sheet: the operator's setup sheet of a job, headless: its facts
// (document/SetupSheet.h), pictures drawn without OpenGL and the HTML (and PDF) written by the
// sheet module. It needs a QGuiApplication (fonts, images); main() makes one on the offscreen
// platform for this command only.
#include "Cli.h"

#include "base/NumberFormat.h"
#include "document/JobFile.h"
#include "document/SetupSheet.h"
#include "occ/Model.h"
#include "post/PostRegistry.h"
#include "sheet/SheetFiles.h"
#include "sheet/SheetHtml.h"
#include "sheet/SheetPicture.h"
#include "toolpath/ClText.h"

#include <QGuiApplication>

#include <cstdlib>
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

QtMessageHandler g_previousHandler = nullptr;

// The offscreen platform's note that XDG_RUNTIME_DIR is not set (it falls back to a folder of
// its own) says nothing about the sheet; stderr stays for the command's own messages.
void dropRuntimeDirNote(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtWarningMsg && message.startsWith(QStringLiteral("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    if (g_previousHandler)
        g_previousHandler(type, context, message);
}

}  // namespace

std::unique_ptr<QCoreApplication> sheetApplication(int& argc, char** argv)
{
    // Fonts and images need a GUI application, a display does not: offscreen unless told otherwise.
    if (!std::getenv("QT_QPA_PLATFORM"))
        setenv("QT_QPA_PLATFORM", "offscreen", 1);
    g_previousHandler = qInstallMessageHandler(dropRuntimeDirNote);
    return std::make_unique<QGuiApplication>(argc, argv);
}

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

    const sheet::SheetPicture pictures(model.mesh(), computed->job.stock.box(), computed->program);
    sheet::SheetOutput output;
    output.htmlPath = options.html;
    output.pdfPath = options.pdf;
    if (const base::Status written = sheet::writeSetupSheet(sheet.value(), pictures, output); !written)
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
