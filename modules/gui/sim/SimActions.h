// The simulator's actions in the registry (menu "Simulate"): Cam.Sim.Start ("Simulate" what the
// NC editor holds: the job's posted program or an opened file), Cam.Sim.Play, Cam.Sim.Pause,
// Cam.Sim.StepForward, Cam.Sim.StepBack, Cam.Sim.JumpToLine, Cam.Sim.ImportMeasured (a trace the
// control recorded, overlaid on the program) and Cam.Sim.ClearMeasured. One entry point, so the main window
// adds them with one call and tests trigger them by id.
#pragma once

#include "gui/sim/SimRun.h"

#include <functional>
#include <optional>

namespace camwb::gui {

class ActionRegistry;
class SimPlayer;

// `request` answers what to simulate now (nullopt: nothing, the reason already shown); `line`
// the line Jump to Line goes to; `importMeasured` asks for a measured trace and imports it.
void registerSimulatorActions(ActionRegistry& registry, SimPlayer* player,
                              std::function<std::optional<SimRunRequest>()> request, std::function<int()> line,
                              std::function<void()> importMeasured);

}  // namespace camwb::gui
