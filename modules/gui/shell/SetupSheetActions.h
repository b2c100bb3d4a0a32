// Job > Setup Sheet…: writes the current job's setup sheet (HTML with its pictures, and a PDF
// beside it) through the sheet module, with the 3D view's picture of the part when the view can
// draw one (else the sheet's own renderer). Registered as Cam.Job.SetupSheet.
#pragma once

#include <QImage>
#include <QString>

#include <functional>

namespace camwb::gui {

class ActionRegistry;
class Prompter;
class Workbench;

// Into `menu` (the window's Job menu). `grab`: the 3D view's picture (a null image without
// OpenGL); `prompter`: asks for the file and shows a failure.
void registerSetupSheetActions(ActionRegistry& registry, const QString& menu, Workbench* workbench,
                               std::function<Prompter&()> prompter, std::function<QImage()> grab);

}  // namespace camwb::gui
