// Job > Setup Sheet…: writes the current job's setup sheet (HTML with its pictures, and a PDF
// beside it) through the sheet module, with the 3D view's picture of the part when the view can
// draw one (else the sheet's own renderer). Registered as Cam.Job.SetupSheet.
// The sheet is made on a worker thread from a copy of the job, model and program taken when it
// starts (the simulation of a long five-axis job takes a minute), with progress and Cancel in a
// non-modal dialog. It is written only when it finishes uncancelled and the job has not changed
// meanwhile; an edit while it runs discards it, and the report says so.
#pragma once

#include <QImage>
#include <QString>

#include <functional>

class QWidget;

namespace camwb::gui {

class ActionRegistry;
class Prompter;
class Workbench;

// Into `menu` (the window's Job menu). `grab`: the 3D view's picture (a null image without
// OpenGL); `prompter`: asks for the file and shows a failure; `window`: the progress dialog's
// parent (object name "setupSheetProgress").
void registerSetupSheetActions(ActionRegistry& registry, const QString& menu, Workbench* workbench, QWidget* window,
                               std::function<Prompter&()> prompter, std::function<QImage()> grab);

}  // namespace camwb::gui
