// The job setup's action in the registry: Cam.Job.Setup ("Job Setup…", menu Job) opens the job
// setup task panel. One entry point, so the main window adds it with one line and tests trigger
// it by id. And what the 3D view shows of the setup.
#pragma once

#include <functional>

namespace camwb::gui {

class ActionRegistry;
class View3D;
class Workbench;

void registerJobSetupActions(ActionRegistry& registry, std::function<void()> openPanel);
// Keeps the view's stock and work axes (View3D::setJobSetup) those of the workbench's job.
void showJobSetupInView(Workbench& workbench, View3D& view);

}  // namespace camwb::gui
