// The job setup's action in the registry: Cam.Job.Setup ("Job Setup…", menu Job) opens the job
// setup task panel. One entry point, so the main window adds it with one line and tests trigger
// it by id. And what the 3D view shows of the setup: a milling job's stock, or a turning job's
// half-section in the XZ view.
#pragma once

#include "document/Job.h"
#include "gui/view3d/View3D.h"

#include <functional>
#include <optional>

namespace camwb::gui {

class ActionRegistry;
class Workbench;

void registerJobSetupActions(ActionRegistry& registry, std::function<void()> openPanel);
// Keeps the view's stock and work axes (View3D::setJobSetup) those of the workbench's job; a
// turning job's half-section instead of a stock (View3D::setLatheSection), and the view turns to
// the lathe's XZ preset when the job becomes a turning job (opened, or its first groove added),
// back to the isometric one when it stops being one.
void showJobSetupInView(Workbench& workbench, View3D& view);

// A turning job (operations, all of them grooves): the stock before cutting and each groove's
// contour (C1, bottom corners, P) and offset contour (R, S, T, U) as sim::grooveGeometry gives
// them. nullopt for any other job.
std::optional<LatheSection> latheSectionOf(const document::Job& job);

}  // namespace camwb::gui
