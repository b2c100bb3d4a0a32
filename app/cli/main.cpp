// camwb-cli: the headless shell over the same modules as the GUI.
#include "Cli.h"
#include "camwb_version.h"
#include "sheet/SheetPainter.h"

#include <iostream>
#include <optional>

int main(int argc, char** argv)
{
    using namespace camwb::cli;
    // No Qt here: the post engine makes the core application QJSEngine needs when it is loaded,
    // and setup-sheet's fonts and pictures need a GUI one, made first by the sheet's painter.
    std::optional<camwb::sheet::SheetApplication> app;
    if (argc > 1 && std::string(argv[1]) == "setup-sheet") {
        camwb::base::Result<camwb::sheet::SheetApplication> made = camwb::sheet::sheetApplication(argc, argv);
        if (!made)
            return fail(made.error().toString());
        app.emplace(std::move(made).value());
    }
    const std::vector<std::string> args(argv + 1, argv + argc);

    if (args.empty())
        return usageError("a command is needed");
    if (args[0] == "--help" || args[0] == "-h") {
        printUsage(std::cout);
        return kExitOk;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "--version") {
        std::cout << "camwb-cli " << CAMWB_VERSION << "\n";
        return kExitOk;
    }
    if (args[0] == "run")
        return runCommand(rest);
    if (args[0] == "posts")
        return postsCommand(rest);
    if (args[0] == "post")
        return postCommand(rest);
    if (args[0] == "cl")
        return clCommand(rest);
    if (args[0] == "nc")
        return ncCommand(rest);
    if (args[0] == "sim")
        return simCommand(rest);
    if (args[0] == "setup-sheet")
        return setupSheetCommand(rest);
    return usageError("unknown command '" + args[0] + "'");
}
