// View ▸ Go to …: keys that put the keyboard into the job tree, the task panel, the NC editor,
// the report and the 3D view (showing and raising their dock), so the window's parts are
// reachable without a mouse; inside each, Tab and the arrows do the rest.
#pragma once

#include <QString>

class QMainWindow;
class QWidget;

namespace camwb::gui {

class ActionRegistry;

// Registers Cam.View.GoTo{JobTree,Task,Nc,Report,View} (Alt+1 … Alt+4, Alt+0) in `menu`.
void registerFocusActions(ActionRegistry& actions, QMainWindow& window, const QString& menu);

// The widget the keyboard goes to in `root`: itself or its first visible, enabled child that takes
// Tab focus; nullptr when none does.
QWidget* firstFocusable(QWidget* root);

}  // namespace camwb::gui
