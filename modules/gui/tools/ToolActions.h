// The tool library's actions in the registry (menu "Tools"): Cam.Tools.Library opens the library
// dialog on the user's library, Cam.Tools.ComputeFeeds sets the job's tools' speeds and feeds from
// their cutting data and the job's material (one undo step). One entry point for the main window.
#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace camwb::gui {

class ActionRegistry;
class Prompter;
class Workbench;

// The user's library: tools.camwb-tools.json in the user data dir (QStandardPaths).
QString userToolLibraryPath();
// The shipped default library (resources/tools/, installed share/camwb/tools); empty if not found.
QString defaultToolLibraryPath();

// `prompter` answers the window's prompter now (tests replace it).
void registerToolActions(ActionRegistry& registry, Workbench& workbench, std::function<Prompter&()> prompter,
                         QWidget* parent);

}  // namespace camwb::gui
